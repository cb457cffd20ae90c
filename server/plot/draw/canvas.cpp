#include "plot/draw/canvas.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace saasgaps::plot {

namespace {

/// cairo's stream writer: appends to the std::string passed as closure.
cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

std::string lower_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

ImageFormat image_format_for_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == "png") return ImageFormat::png;
  if (ext == "svg") return ImageFormat::svg;
  throw std::invalid_argument("cannot tell the image format of '" + path + "': the name must end in .png or .svg");
}

const char* media_type(ImageFormat format) { return format == ImageFormat::png ? "image/png" : "image/svg+xml"; }

Canvas::Canvas(ImageFormat format, int width, int height) : format_(format), width_(width), height_(height) {
  if (width < min_side || height < min_side || width > max_side || height > max_side) {
    throw std::invalid_argument("image size " + std::to_string(width) + " x " + std::to_string(height) +
                                " px is out of range (" + std::to_string(min_side) + " .. " + std::to_string(max_side) + " per side)");
  }
  if (format == ImageFormat::png) {
    // RGB24: an opaque image, a third smaller as PNG than ARGB32.
    surface_.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  } else {
    surface_.reset(cairo_svg_surface_create_for_stream(append_to_string, &buffer_, width, height));
    if (cairo_surface_status(surface_.get()) == CAIRO_STATUS_SUCCESS) {
      cairo_svg_surface_set_document_unit(surface_.get(), CAIRO_SVG_UNIT_PX);
    }
  }
  if (const cairo_status_t s = cairo_surface_status(surface_.get()); s != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cannot create the image surface: ") + cairo_status_to_string(s));
  }
  cr_.reset(cairo_create(surface_.get()));
  check("cannot create the drawing context");
  cairo_set_line_join(cr_.get(), CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_.get(), CAIRO_LINE_CAP_BUTT);
  fill_rect({0.0, 0.0, static_cast<double>(width), static_cast<double>(height)}, colors::white);
}

Canvas::~Canvas() = default;

void Canvas::check(const char* what) const {
  if (const cairo_status_t s = cairo_status(cr_.get()); s != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string(what) + ": " + cairo_status_to_string(s));
  }
}

std::string Canvas::finish() {
  if (finished_) throw std::logic_error("Canvas::finish called twice");
  finished_ = true;
  check("drawing failed");
  cr_.reset();
  if (format_ == ImageFormat::png) {
    cairo_surface_flush(surface_.get());
    if (const cairo_status_t s = cairo_surface_write_to_png_stream(surface_.get(), append_to_string, &buffer_);
        s != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error(std::string("cannot encode the PNG image: ") + cairo_status_to_string(s));
    }
  }
  // The SVG surface writes its document as it is finished.
  cairo_surface_finish(surface_.get());
  if (const cairo_status_t s = cairo_surface_status(surface_.get()); s != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cannot encode the image: ") + cairo_status_to_string(s));
  }
  surface_.reset();
  return std::move(buffer_);
}

void Canvas::set_color(Rgb color, double alpha) const {
  cairo_set_source_rgba(cr_.get(), color.r, color.g, color.b, alpha);
}

void Canvas::set_line(double width_px, bool dashed) const {
  cairo_set_line_width(cr_.get(), width_px);
  if (dashed) {
    const double dashes[] = {4.0 * std::max(1.0, width_px), 3.0 * std::max(1.0, width_px)};
    cairo_set_dash(cr_.get(), dashes, 2, 0.0);
  } else {
    cairo_set_dash(cr_.get(), nullptr, 0, 0.0);
  }
}

void Canvas::select_font(double size, bool bold) const {
  cairo_select_font_face(cr_.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_.get(), size);
}

double Canvas::text_width(std::string_view utf8, double size, bool bold) const {
  select_font(size, bold);
  const std::string s(utf8);
  cairo_text_extents_t e;
  cairo_text_extents(cr_.get(), s.c_str(), &e);
  return e.x_advance;
}

std::string Canvas::fit_text(std::string_view utf8, double size, double max_width, bool bold) const {
  std::string s(utf8);
  if (text_width(s, size, bold) <= max_width) return s;
  static constexpr std::string_view ellipsis = "\u2026";
  while (!s.empty()) {
    // Drop one UTF-8 character: the continuation bytes, then the lead byte.
    while (!s.empty() && (static_cast<unsigned char>(s.back()) & 0xC0U) == 0x80U) s.pop_back();
    if (!s.empty()) s.pop_back();
    if (text_width(s + std::string(ellipsis), size, bold) <= max_width) break;
  }
  return s + std::string(ellipsis);
}

void Canvas::text(Point p, std::string_view utf8, double size, HAlign h, VAlign v, bool bold) const {
  select_font(size, bold);
  const std::string s(utf8);
  cairo_text_extents_t e;
  cairo_text_extents(cr_.get(), s.c_str(), &e);
  cairo_font_extents_t f;
  cairo_font_extents(cr_.get(), &f);
  double x = p.x;
  if (h == HAlign::center) x -= e.x_advance / 2.0;
  if (h == HAlign::right) x -= e.x_advance;
  // Vertical placement from the font's ascent and descent, not the glyphs', so that labels in a
  // column line up whatever their digits.
  double y = p.y;
  if (v == VAlign::top) y += f.ascent;
  if (v == VAlign::middle) y += (f.ascent - f.descent) / 2.0;
  if (v == VAlign::bottom) y -= f.descent;
  cairo_move_to(cr_.get(), x, y);
  cairo_show_text(cr_.get(), s.c_str());
  cairo_new_path(cr_.get());
}

void Canvas::fill_rect(const Rect& r, Rgb color) const {
  set_color(color);
  cairo_rectangle(cr_.get(), r.x, r.y, r.width, r.height);
  cairo_fill(cr_.get());
}

void Canvas::stroke_rect(const Rect& r, Rgb color, double width_px) const {
  set_color(color);
  set_line(width_px);
  cairo_rectangle(cr_.get(), r.x, r.y, r.width, r.height);
  cairo_stroke(cr_.get());
}

void Canvas::line(Point a, Point b) const {
  cairo_move_to(cr_.get(), a.x, a.y);
  cairo_line_to(cr_.get(), b.x, b.y);
  cairo_stroke(cr_.get());
}

void Canvas::polygon(const std::vector<Point>& corners) const {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (i == 0) cairo_move_to(cr_.get(), corners[i].x, corners[i].y);
    else cairo_line_to(cr_.get(), corners[i].x, corners[i].y);
  }
  if (!corners.empty()) cairo_close_path(cr_.get());
}

}  // namespace saasgaps::plot
