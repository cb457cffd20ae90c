#pragma once
/// A drawing surface for one image: cairo's image surface (PNG) or SVG surface, owned RAII, encoded
/// into memory through cairo's stream writers so that a server can answer with the bytes and the
/// command line can write them to a file. Device units are pixels, y downwards.

#include <cairo.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "plot/draw/color_map.hpp"

namespace saasgaps::plot {

enum class ImageFormat { png, svg };

/// The format an output path asks for by its extension (.png or .svg, any case); anything else is a
/// std::invalid_argument naming the path.
ImageFormat image_format_for_path(const std::string& path);

/// "image/png" or "image/svg+xml".
const char* media_type(ImageFormat format);

struct Point {
  double x = 0.0, y = 0.0;
};

struct Rect {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
};

enum class HAlign { left, center, right };
enum class VAlign { top, middle, baseline, bottom };

class Canvas {
 public:
  /// The one range of an image side, px, for every way of asking for a plot (saasgaps plot --width
  /// and --height, the HTTP width and height parameters): larger requests are refused, not
  /// attempted. 4000 x 4000 is 64 MB of pixels, what one request to a shared server may cost.
  static constexpr int min_side = 16;
  static constexpr int max_side = 4000;

  /// A white canvas of width x height px (each min_side .. max_side, else std::invalid_argument).
  Canvas(ImageFormat format, int width, int height);
  ~Canvas();
  // The SVG surface writes into buffer_ through a pointer: the canvas stays where it was made.
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  cairo_t* context() const { return cr_.get(); }
  ImageFormat format() const { return format_; }
  int width() const { return width_; }
  int height() const { return height_; }

  /// Ends drawing and returns the encoded image (PNG bytes or SVG text). Throws std::runtime_error
  /// when cairo reports an error. The canvas cannot be drawn on afterwards.
  std::string finish();

  // --- Drawing helpers over context() -----------------------------------------------------------
  void set_color(Rgb color, double alpha = 1.0) const;
  void set_line(double width_px, bool dashed = false) const;
  /// Text in the sans-serif face, size in px, anchored at p.
  void text(Point p, std::string_view utf8, double size, HAlign h = HAlign::left, VAlign v = VAlign::baseline,
            bool bold = false) const;
  /// Advance width of the text in px.
  double text_width(std::string_view utf8, double size, bool bold = false) const;
  /// The text, shortened with an ellipsis to fit max_width px.
  std::string fit_text(std::string_view utf8, double size, double max_width, bool bold = false) const;
  void fill_rect(const Rect& r, Rgb color) const;
  void stroke_rect(const Rect& r, Rgb color, double width_px) const;
  void line(Point a, Point b) const;  ///< strokes with the current colour and line
  /// Adds a closed polygon to the current path (fill or stroke it after).
  void polygon(const std::vector<Point>& corners) const;

 private:
  struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  };
  struct ContextDeleter {
    void operator()(cairo_t* c) const { cairo_destroy(c); }
  };

  void select_font(double size, bool bold) const;
  void check(const char* what) const;

  ImageFormat format_;
  int width_;
  int height_;
  std::string buffer_;  ///< encoded output, appended by the stream writer
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface_;
  std::unique_ptr<cairo_t, ContextDeleter> cr_;
  bool finished_ = false;
};

}  // namespace saasgaps::plot
