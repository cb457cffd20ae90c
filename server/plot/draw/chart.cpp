#include "plot/draw/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "plot/draw/nice_scale.hpp"
#include "plot/draw/number_format.hpp"

namespace saasgaps::plot {

namespace {

Axis axis_from_scale(const Scale& s, std::string title) {
  Axis a;
  a.min = s.lo;
  a.max = s.hi;
  a.ticks = s.values();
  const TickFormat format(s.step, std::max(std::abs(s.lo), std::abs(s.hi)));
  for (const double t : a.ticks) a.labels.push_back(format(t));
  a.title = std::move(title);
  return a;
}

}  // namespace

Axis numeric_axis(double lo, double hi, std::string title, int max_ticks) {
  return axis_from_scale(nice_scale(lo, hi, max_ticks, tick_mantissas), std::move(title));
}

Axis integer_axis(int lo, int hi, std::string title, int max_ticks, double padding) {
  if (hi <= lo) hi = lo + 1;
  Scale s = nice_scale(lo, hi, max_ticks, tick_mantissas);
  if (s.step < 1.0 || std::abs(s.step - std::round(s.step)) > 1e-9) {
    s.step = std::max(1.0, std::ceil(s.step));
    s.lo = std::floor(lo / s.step) * s.step;
    s.hi = std::ceil(hi / s.step) * s.step;
  }
  Axis a = axis_from_scale(s, std::move(title));
  a.min -= padding;
  a.max += padding;
  return a;
}

Axis log_axis(double lo, double hi, std::string title) {
  if (!(lo > 0.0)) lo = 1.0;
  if (!(hi > lo)) hi = lo * 10.0;
  Axis a;
  a.title = std::move(title);
  a.min = std::floor(std::log10(lo) + 1e-9);
  a.max = std::ceil(std::log10(hi) - 1e-9);
  if (a.max <= a.min) a.max = a.min + 1.0;
  const bool fine = a.max - a.min < 3.0;
  const int step = static_cast<int>(std::ceil((a.max - a.min) / 8.0));
  for (int d = static_cast<int>(a.min); d <= static_cast<int>(a.max); ++d) {
    for (const double m : {1.0, 2.0, 5.0}) {
      if ((m != 1.0 && (!fine || d == static_cast<int>(a.max))) || (m == 1.0 && (d - static_cast<int>(a.min)) % step != 0)) {
        continue;
      }
      const double value = m * std::pow(10.0, d);
      char label[32];
      std::snprintf(label, sizeof label, "%g", value);
      a.ticks.push_back(std::log10(value));
      a.labels.emplace_back(label);
    }
  }
  return a;
}

Gutters Chart::gutters_for(const Canvas& canvas, const Axis& y, const std::vector<Series>& legend) {
  const Typography t = typography(canvas);
  double label_width = 0.0;
  for (const std::string& l : y.labels) label_width = std::max(label_width, canvas.text_width(l, t.small));
  double legend_width = 0.0;
  for (const Series& s : legend) {
    if (!s.name.empty()) legend_width = std::max(legend_width, canvas.text_width(s.name, t.small));
  }
  // Legend entries: a 2.4-em line sample, a gap, the text.
  if (legend_width > 0.0) legend_width += 3.2 * t.small + t.margin;
  return {t.margin + 1.4 * t.base + label_width + 0.6 * t.small, t.margin + legend_width};
}

Chart::Chart(const Canvas& canvas, Rect area, Axis x, Axis y, const std::vector<Series>& legend, Gutters at_least)
    : canvas_(canvas), type_(typography(canvas)), x_(std::move(x)), y_(std::move(y)) {
  for (const Series& s : legend) {
    if (!s.name.empty()) legend_.push_back({s.name, {}, {}, s.color, s.width, s.dashed, s.markers});
  }
  const Gutters need = gutters_for(canvas, y_, legend);
  const double left = area.x + std::max(need.left, at_least.left);
  const double right = area.right() - std::max(need.right, at_least.right);
  const double bottom = area.bottom() - type_.margin - 1.4 * type_.base - 1.6 * type_.small;
  const double top = area.y + 0.8 * type_.small;
  plot_ = {left, top, std::max(10.0, right - left), std::max(10.0, bottom - top)};
  legend_area_ = {plot_.right() + type_.margin, plot_.y, std::max(0.0, area.right() - plot_.right() - type_.margin),
                  plot_.height};
}

Point Chart::to_device(double x, double y) const {
  return {plot_.x + (x - x_.min) / (x_.max - x_.min) * plot_.width,
          plot_.bottom() - (y - y_.min) / (y_.max - y_.min) * plot_.height};
}

void Chart::draw_axes() const {
  cairo_t* cr = canvas_.context();
  const double tick = 0.4 * type_.small;
  canvas_.set_line(1.0);
  for (std::size_t i = 0; i < x_.ticks.size(); ++i) {
    const Point p = to_device(x_.ticks[i], y_.min);
    canvas_.set_color(colors::grid);
    canvas_.line({p.x, plot_.y}, {p.x, plot_.bottom()});
    canvas_.set_color(colors::axis);
    canvas_.line({p.x, plot_.bottom()}, {p.x, plot_.bottom() + tick});
    canvas_.set_color(colors::text);
    canvas_.text({p.x, plot_.bottom() + tick + 0.2 * type_.small}, x_.labels[i], type_.small, HAlign::center,
                 VAlign::top);
  }
  for (std::size_t i = 0; i < y_.ticks.size(); ++i) {
    const Point p = to_device(x_.min, y_.ticks[i]);
    canvas_.set_color(colors::grid);
    canvas_.line({plot_.x, p.y}, {plot_.right(), p.y});
    canvas_.set_color(colors::axis);
    canvas_.line({plot_.x - tick, p.y}, {plot_.x, p.y});
    canvas_.set_color(colors::text);
    canvas_.text({plot_.x - tick - 0.3 * type_.small, p.y}, y_.labels[i], type_.small, HAlign::right, VAlign::middle);
  }
  canvas_.stroke_rect(plot_, colors::axis, 1.0);
  canvas_.set_color(colors::text);
  canvas_.text({plot_.x + plot_.width / 2.0, plot_.bottom() + tick + 1.5 * type_.small}, x_.title, type_.base,
               HAlign::center, VAlign::top);
  // The y title reads upwards along the axis.
  double label_width = 0.0;
  for (const std::string& l : y_.labels) label_width = std::max(label_width, canvas_.text_width(l, type_.small));
  cairo_save(cr);
  cairo_translate(cr, plot_.x - tick - 0.6 * type_.small - label_width - 0.4 * type_.base, plot_.y + plot_.height / 2.0);
  cairo_rotate(cr, -std::numbers::pi / 2.0);
  canvas_.text({0.0, 0.0}, canvas_.fit_text(y_.title, type_.base, plot_.height), type_.base, HAlign::center,
               VAlign::bottom);
  cairo_restore(cr);
}

void Chart::draw(const Series& s) const {
  if (s.x.empty()) return;
  cairo_t* cr = canvas_.context();
  cairo_save(cr);
  cairo_rectangle(cr, plot_.x, plot_.y, plot_.width, plot_.height);
  cairo_clip(cr);
  canvas_.set_color(s.color);
  canvas_.set_line(s.width, s.dashed);
  // A NaN value is a point without one: the line breaks there.
  bool pen_down = false;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (std::isnan(s.y[i])) {
      pen_down = false;
      continue;
    }
    const Point p = to_device(s.x[i], s.y[i]);
    if (pen_down) cairo_line_to(cr, p.x, p.y);
    else cairo_move_to(cr, p.x, p.y);
    pen_down = true;
  }
  cairo_stroke(cr);
  cairo_restore(cr);  // markers unclipped: a point on the frame shows whole
  if (s.markers) {
    canvas_.set_color(s.color);  // cairo_restore reset the source too
    const double radius = std::max(2.0, 1.3 * s.width);
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isnan(s.y[i])) continue;
      const Point p = to_device(s.x[i], s.y[i]);
      cairo_new_sub_path(cr);
      cairo_arc(cr, p.x, p.y, radius, 0.0, 2.0 * std::numbers::pi);
    }
    cairo_fill(cr);
  }
}

Series reference_series(std::string name, Rgb color) {
  Series s;
  s.name = std::move(name);
  s.color = color;
  s.dashed = true;
  return s;
}

void Chart::draw_reference(double y, Rgb color) const {
  if (y < y_.min || y > y_.max) return;
  const Point p = to_device(x_.min, y);
  const Series style = reference_series("", color);
  canvas_.set_color(style.color);
  canvas_.set_line(style.width, style.dashed);
  canvas_.line({plot_.x, p.y}, {plot_.right(), p.y});
  canvas_.set_line(1.0);
}

void Chart::draw_legend() const {
  cairo_t* cr = canvas_.context();
  const double row = 1.5 * type_.small;
  double y = legend_area_.y + row / 2.0;
  for (const Series& s : legend_) {
    if (y > legend_area_.bottom()) break;
    const double x0 = legend_area_.x;
    const double x1 = x0 + 2.4 * type_.small;
    canvas_.set_color(s.color);
    canvas_.set_line(s.width, s.dashed);
    canvas_.line({x0, y}, {x1, y});
    if (s.markers) {
      cairo_arc(cr, (x0 + x1) / 2.0, y, std::max(2.0, 1.3 * s.width), 0.0, 2.0 * std::numbers::pi);
      cairo_fill(cr);
    }
    canvas_.set_color(colors::text);
    canvas_.text({x1 + 0.8 * type_.small, y}, s.name, type_.small, HAlign::left, VAlign::middle);
    y += row;
  }
  canvas_.set_line(1.0);
}

}  // namespace saasgaps::plot
