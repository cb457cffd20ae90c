#include "plot/pictures/friction_plot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"
#include "plot/result/contact_points.hpp"
#include "plot/result/field.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

// The zones' tints, drawn translucent over the grid and under the curves.
constexpr Rgb stick_tint{0.55, 0.75, 0.95};
constexpr Rgb slip_tint{1.00, 0.68, 0.30};
constexpr double tint_alpha = 0.35;

bool has_friction(const ContactPairCurve& c) { return c.friction > 0.0 && !c.x.empty(); }

/// A run of consecutive points of one state (stick or slip) along a pair: [from, to] in x, each end
/// halfway to the neighbouring point (the end point itself at the ends of the pair).
struct Zone {
  std::string state;
  double from = 0.0, to = 0.0;
};

std::vector<Zone> zones_of(const ContactPairCurve& c) {
  std::vector<Zone> zones;
  const std::size_t n = c.x.size();
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && c.state[j + 1] == c.state[i]) ++j;
    if (c.state[i] == "stick" || c.state[i] == "slip") {
      zones.push_back({c.state[i], i == 0 ? c.x[i] : 0.5 * (c.x[i - 1] + c.x[i]),
                       j + 1 == n ? c.x[j] : 0.5 * (c.x[j] + c.x[j + 1])});
    }
    i = j + 1;
  }
  return zones;
}

/// A legend entry drawn as a thick stroke of a zone's tint.
Series zone_legend(std::string name, Rgb tint) {
  Series s;
  s.name = std::move(name);
  s.color = tint;
  s.width = 8.0;
  return s;
}

}  // namespace

bool has_friction_points(const json& result) {
  const std::vector<ContactPairCurve> curves = contact_pair_curves(result, RowAxis::position);
  return std::any_of(curves.begin(), curves.end(), has_friction);
}

DataTable draw_friction_plot(const Canvas& canvas, const json& result) {
  const std::vector<ContactPairCurve> curves = contact_pair_curves(result, RowAxis::position);
  if (!std::any_of(curves.begin(), curves.end(), has_friction)) {
    throw std::invalid_argument("the result has no contact pair with friction > 0: there is no friction to plot");
  }
  const UnitNames units = result_units(result);
  const auto [title, status, iterations] = run_facts(result);

  // The y axis holds the shear and both bounds, and always 0.
  double low_x = INFINITY, high_x = -INFINITY, low_y = 0.0, high_y = 0.0;
  int points = 0, sticking = 0, slipping = 0, pairs = 0;
  for (const ContactPairCurve& c : curves) {
    if (!has_friction(c)) continue;
    ++pairs;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      const double bound = c.friction * c.pressure[i];
      low_x = std::min(low_x, c.x[i]);
      high_x = std::max(high_x, c.x[i]);
      low_y = std::min({low_y, c.shear[i], -bound});
      high_y = std::max({high_y, c.shear[i], bound});
      ++points;
      sticking += c.state[i] == "stick" ? 1 : 0;
      slipping += c.state[i] == "slip" ? 1 : 0;
    }
  }
  if (!(high_x > low_x)) {
    low_x -= 0.5;
    high_x += 0.5;
  }
  if (!(high_y > low_y)) {
    low_y = -1.0;
    high_y = 1.0;
  }

  // Per pair: the shear (solid), +mu p (dashed, named) and -mu p (dashed, the same entry).
  const bool markers = points <= 200;
  std::vector<Series> drawn, legend;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ContactPairCurve& c = curves[k];
    if (!has_friction(c)) continue;
    Series shear, upper, lower;
    shear.name = c.name + " shear";
    upper.name = c.name + " \u00b1\u03bc\u00b7p (\u03bc = " + DataTable::number(c.friction) + ")";
    shear.color = upper.color = lower.color = pair_color(k);
    shear.x = upper.x = lower.x = c.x;
    shear.y = c.shear;
    for (const double p : c.pressure) {
      upper.y.push_back(c.friction * p);
      lower.y.push_back(-c.friction * p);
    }
    shear.width = 2.0;
    upper.width = lower.width = 1.5;
    upper.dashed = lower.dashed = true;
    legend.push_back(shear);
    legend.push_back(upper);
    drawn.push_back(std::move(shear));
    drawn.push_back(std::move(upper));
    drawn.push_back(std::move(lower));
  }
  legend.push_back(zone_legend("stick zone", stick_tint));
  legend.push_back(zone_legend("slip zone", slip_tint));

  const std::string subtitle =
      "Shear and \u00b1\u03bc \u00d7 contact pressure " + unit_phrase(Quantity::stress, units) + " along side A of " +
      std::to_string(pairs) + " contact pair" + (pairs == 1 ? "" : "s") + " with friction (" + std::to_string(points) +
      " points: " + std::to_string(sticking) + " stick, " + std::to_string(slipping) + " slip, " +
      std::to_string(points - sticking - slipping) + " open) \u2014 " + run_summary(status, iterations);
  const Rect area = draw_header(canvas, title.empty() ? "Friction along the contact surfaces" : title, subtitle);
  const Axis x_axis = contact_x_axis(low_x, high_x, RowAxis::position, units);
  const Axis y_axis = numeric_axis(low_y, high_y, with_unit("shear, \u00b1\u03bc\u00b7p", Quantity::stress, units));
  const Chart chart(canvas, area, x_axis, y_axis, legend);
  chart.draw_axes();

  // Zones behind the curves, clipped to the plotting area.
  cairo_t* cr = canvas.context();
  const Rect& plot = chart.plot_area();
  std::vector<std::vector<Zone>> zones(curves.size());
  cairo_save(cr);
  cairo_rectangle(cr, plot.x, plot.y, plot.width, plot.height);
  cairo_clip(cr);
  for (std::size_t k = 0; k < curves.size(); ++k) {
    if (!has_friction(curves[k])) continue;
    zones[k] = zones_of(curves[k]);
    for (const Zone& z : zones[k]) {
      const double left = chart.to_device(z.from, 0.0).x, right = chart.to_device(z.to, 0.0).x;
      // A zone of one point at a pair's end is a line: give it a few px to be seen.
      const double width = std::max(right - left, 3.0);
      canvas.set_color(z.state == "stick" ? stick_tint : slip_tint, tint_alpha);
      cairo_rectangle(cr, 0.5 * (left + right - width), plot.y, width, plot.height);
      cairo_fill(cr);
    }
  }
  cairo_restore(cr);
  chart.draw_reference(0.0, colors::axis);
  for (const Series& s : drawn) chart.draw(s);

  // Each point's state on the shear curve: a filled dot sticks, an open ring slips.
  const double radius = markers ? 4.0 : 2.5;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ContactPairCurve& c = curves[k];
    if (!has_friction(c)) continue;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      if (c.state[i] != "stick" && c.state[i] != "slip") continue;
      const Point p = chart.to_device(c.x[i], c.shear[i]);
      cairo_new_sub_path(cr);
      cairo_arc(cr, p.x, p.y, radius, 0.0, 2.0 * std::numbers::pi);
      if (c.state[i] == "stick") {
        canvas.set_color(pair_color(k));
        cairo_fill(cr);
      } else {
        canvas.set_color(colors::white);
        cairo_fill_preserve(cr);
        canvas.set_color(pair_color(k));
        canvas.set_line(1.5);
        cairo_stroke(cr);
      }
    }
  }
  chart.draw_legend();

  DataTable table({"pair", "point", "x", "r", "z", "pressure", "shear", "mu", "mu_pressure", "slip", "state", "px",
                   "py_shear", "py_bound"});
  table.note("SAASGAPS friction along the contact surfaces: " + title);
  table.note("x: " + x_axis.title + "; pair: 1, 2, .. the result's contact pairs (those with friction > 0 drawn, one "
             "curve set each); point: 1, 2, .. along side A; pressure, shear, mu_pressure = mu x pressure " +
             unit_phrase(Quantity::stress, units) + "; slip " + unit_phrase(Quantity::length, units));
  std::string names = "pairs (surfaces A / B, mu):";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    names += " " + std::to_string(k + 1) + " = " + curves[k].name + ", mu " + DataTable::number(curves[k].friction) + ";";
  }
  std::replace(names.begin(), names.end(), '\n', ' ');  // names are free text; a note is one line
  table.note(names);
  table.note("image " + std::to_string(canvas.width()) + "x" + std::to_string(canvas.height()) +
             " px; px, py_shear: where each point's state marker is drawn; py_bound: +mu x pressure");
  table.note(y_tick_note("shear", chart));
  for (std::size_t k = 0; k < curves.size(); ++k) {
    if (zones[k].empty()) continue;
    std::string note = "zones pair " + std::to_string(k + 1) + ":";
    for (const Zone& z : zones[k]) note += " " + z.state + " " + DataTable::number(z.from) + ".." + DataTable::number(z.to);
    table.note(note);
  }
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ContactPairCurve& c = curves[k];
    if (!has_friction(c)) continue;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      const double bound = c.friction * c.pressure[i];
      const Point p = chart.to_device(c.x[i], c.shear[i]);
      const Point b = chart.to_device(c.x[i], bound);
      table.add_row({std::to_string(k + 1), std::to_string(i + 1), DataTable::number(c.x[i]), DataTable::number(c.r[i]),
                     DataTable::number(c.z[i]), DataTable::number(c.pressure[i]), DataTable::number(c.shear[i]),
                     DataTable::number(c.friction), DataTable::number(bound), DataTable::number(c.slip[i]), c.state[i],
                     DataTable::number(p.x), DataTable::number(p.y), DataTable::number(b.y)});
    }
  }
  return table;
}

}  // namespace saasgaps::plot
