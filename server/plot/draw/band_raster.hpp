#pragma once
/// Colour bands rasterized straight into an image, for meshes too large to fill as paths: each
/// triangle (device px, y down) is scan-converted once, and every pixel whose centre (i + 1/2,
/// j + 1/2) lies in it takes the colour of the band of the field's linear interpolant at that
/// centre, v(x, y) = a + b x + c y. A pixel centre belongs to a triangle when its row's centre is
/// in [y_top, y_bottom) and its column's centre in [x_left, x_right) of the triangle's span on that
/// row, with each edge's crossing computed from its endpoints in a fixed order: triangles that share
/// an edge colour every pixel along it exactly once (no seams, no double cover). Cost O(triangles +
/// pixels covered), memory the image (4 bytes a pixel); no antialiasing (band edges are stroked
/// over it by the contour plot, iso_segment).
///
/// Band k (0 .. n - 1 for levels l_0 < .. < l_n) is the largest k with v >= l_k, clamped to
/// 0 .. n - 1: the same band the path fill paints (level k's path is where v >= l_k, painted in
/// increasing k).

#include <cairo.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "plot/draw/canvas.hpp"
#include "plot/draw/color_map.hpp"
#include "plot/draw/contour_bands.hpp"

namespace saasgaps::plot {

/// The band of value v between increasing levels (see above).
int band_of(const std::vector<double>& levels, double v);

/// The part of the iso-line v = level inside a triangle: the two crossings of its edges by the
/// level (the points clip_at_least puts on the boundary), or none when the level does not cross it.
std::optional<std::array<Point, 2>> iso_segment(const ValueTriangle& triangle, double level);

class BandRaster {
 public:
  /// A transparent ARGB32 image of width x height px; colors[k] is band k's, one per band
  /// (levels.size() - 1 of them, at least one).
  BandRaster(int width, int height, std::vector<double> levels, const std::vector<Rgb>& colors);

  /// Paints the pixels whose centres lie in the triangle (corners in device px, in any order).
  void fill(const ValueTriangle& triangle);

  /// The image, for cairo_set_source_surface (owned by the raster; marked as written).
  cairo_surface_t* surface();

 private:
  struct SurfaceDeleter {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
  };
  int width_, height_, stride_;
  std::vector<double> levels_;
  std::vector<std::uint32_t> pixels_of_band_;  ///< opaque ARGB32 of each band
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface_;
  unsigned char* data_;
};

}  // namespace saasgaps::plot
