#include "plot/pictures/contour_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>

#include "plot/draw/band_raster.hpp"
#include "plot/draw/color_map.hpp"
#include "plot/draw/contour_bands.hpp"
#include "plot/draw/figure.hpp"
#include "plot/draw/nice_scale.hpp"
#include "plot/draw/number_format.hpp"
#include "plot/pictures/gap_markers.hpp"
#include "plot/result/field.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

// ------------------------------------------------------------------------------------------ view
/// Model (r, z) to device px with equal scales on both axes, z upwards.
struct View {
  double pixels_per_length = 1.0;
  double x0 = 0.0, y0 = 0.0;  ///< device position of the model origin
  Point operator()(std::array<double, 2> rz) const {
    return {x0 + pixels_per_length * rz[0], y0 - pixels_per_length * rz[1]};
  }
};

/// The largest view of the given model points that fits `area`, centred in it.
View fit_view(const std::vector<std::array<double, 2>>& points, const Rect& area) {
  double r0 = std::numeric_limits<double>::max(), r1 = -r0, z0 = r0, z1 = -r0;
  for (const auto& p : points) {
    r0 = std::min(r0, p[0]);
    r1 = std::max(r1, p[0]);
    z0 = std::min(z0, p[1]);
    z1 = std::max(z1, p[1]);
  }
  const double width = std::max(r1 - r0, 1e-12), height = std::max(z1 - z0, 1e-12);
  View v;
  v.pixels_per_length = std::min(area.width / width, area.height / height);
  v.x0 = area.x + (area.width - v.pixels_per_length * width) / 2.0 - v.pixels_per_length * r0;
  v.y0 = area.y + (area.height + v.pixels_per_length * height) / 2.0 + v.pixels_per_length * z0;
  return v;
}

/// Node positions at magnification `scale`, in device px.
std::vector<Point> device_positions(const ResultMesh& mesh, const View& view, double scale) {
  std::vector<Point> p;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) p.push_back(view(mesh.position(static_cast<int>(n), scale)));
  return p;
}

// ----------------------------------------------------------------------------------------- edges
/// Edges of solid elements used by exactly one of them: the outline of the bodies, in increasing
/// order of (lower node, higher node). (Sorted in a flat vector: a map of the 10^6 edges of a large
/// mesh cost 100 MB.)
std::vector<std::array<int, 2>> boundary_edges(const ResultMesh& mesh) {
  std::vector<std::array<int, 2>> all;
  for (const SolidElement& e : mesh.solids) {
    for (std::size_t a = 0; a < e.nodes.size(); ++a) {
      const int p = e.nodes[a], q = e.nodes[(a + 1) % e.nodes.size()];
      all.push_back({std::min(p, q), std::max(p, q)});
    }
  }
  std::sort(all.begin(), all.end());
  std::vector<std::array<int, 2>> edges;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && all[j] == all[i]) ++j;
    if (j - i == 1) edges.push_back(all[i]);
    i = j;
  }
  return edges;
}

void stroke_edges(cairo_t* cr, const std::vector<std::array<int, 2>>& edges, const std::vector<Point>& at) {
  for (const auto& [p, q] : edges) {
    cairo_move_to(cr, at[p].x, at[p].y);
    cairo_line_to(cr, at[q].x, at[q].y);
  }
  cairo_stroke(cr);
}

// ----------------------------------------------------------------------------------------- bands
/// Fills the bands between levels over the solid elements. Level k's path is every triangle's part
/// where v >= levels[k]; painting the levels in increasing order leaves each point the colour of
/// its band, and since one path holds all triangles, antialiasing leaves no seams along the
/// element edges.
void fill_bands(const Canvas& canvas, const ResultMesh& mesh, const std::vector<Point>& at,
                const std::vector<double>& values, const std::vector<double>& levels, const std::vector<Rgb>& colors) {
  cairo_t* cr = canvas.context();
  std::vector<ValueTriangle> triangles;
  triangles.reserve(2 * mesh.solids.size());
  std::vector<ValuePoint> corners;
  for (const SolidElement& e : mesh.solids) {
    corners.clear();
    for (const int n : e.nodes) corners.push_back({at[n].x, at[n].y, values[n]});
    triangulate(corners, triangles);
  }
  const auto add = [cr](std::span<const ValuePoint> part) {
    for (std::size_t i = 0; i < part.size(); ++i) {
      if (i == 0) cairo_move_to(cr, part[i].x, part[i].y);
      else cairo_line_to(cr, part[i].x, part[i].y);
    }
    if (!part.empty()) cairo_close_path(cr);
  };
  const int bands = static_cast<int>(levels.size()) - 1;
  for (int k = 0; k < bands; ++k) {
    for (const ValueTriangle& tri : triangles) {
      if (k == 0) {
        add(tri);
      } else {
        const ClippedTriangle part = clip_at_least(tri, levels[k]);
        add(part.corners());
      }
    }
    canvas.set_color(colors[k]);
    cairo_fill(cr);
  }
}

/// The same bands rasterized (band_raster.hpp): each triangle scan-converted once into an image of
/// the canvas, painted in one go; then each interior level's iso-line stroked 1 px wide in the mean
/// of its two bands' colours, which stands in for the antialiasing of the band edges. No list of
/// triangles is kept: memory is the image and the iso-lines.
void raster_bands(const Canvas& canvas, const ResultMesh& mesh, const std::vector<Point>& at,
                  const std::vector<double>& values, const std::vector<double>& levels, const std::vector<Rgb>& colors) {
  BandRaster raster(canvas.width(), canvas.height(), levels, colors);
  const std::size_t bands = levels.size() - 1;
  std::vector<std::vector<std::array<Point, 2>>> iso_lines(bands);  // [k]: level k's segments, k >= 1
  std::vector<ValueTriangle> triangles;
  std::vector<ValuePoint> corners;
  for (const SolidElement& e : mesh.solids) {
    corners.clear();
    for (const int n : e.nodes) corners.push_back({at[n].x, at[n].y, values[n]});
    triangles.clear();
    triangulate(corners, triangles);
    for (const ValueTriangle& t : triangles) {
      raster.fill(t);
      const double lo = std::min({t[0].v, t[1].v, t[2].v}), hi = std::max({t[0].v, t[1].v, t[2].v});
      for (std::size_t k = 1; k < bands; ++k) {
        if (levels[k] < lo || levels[k] > hi) continue;
        if (const auto segment = iso_segment(t, levels[k])) iso_lines[k].push_back(*segment);
      }
    }
  }
  cairo_t* cr = canvas.context();
  cairo_set_source_surface(cr, raster.surface(), 0.0, 0.0);
  cairo_paint(cr);
  canvas.set_line(1.0);
  for (std::size_t k = 1; k < bands; ++k) {
    if (iso_lines[k].empty()) continue;
    for (const auto& [a, b] : iso_lines[k]) {
      cairo_move_to(cr, a.x, a.y);
      cairo_line_to(cr, b.x, b.y);
    }
    const Rgb below = colors[k - 1], above = colors[k];
    canvas.set_color({(below.r + above.r) / 2.0, (below.g + above.g) / 2.0, (below.b + above.b) / 2.0});
    cairo_stroke(cr);
  }
}

/// The colour bar in `box` (its width is the bar's), highest level on top, level labels to the
/// right; a uniform field gets one band labelled with its value. Returns the bar's bottom.
double draw_color_bar(const Canvas& canvas, const Rect& box, const BandLevels& bands_of, const std::vector<Rgb>& colors,
                      std::optional<double> uniform_value) {
  const Typography t = typography(canvas);
  const std::vector<double>& levels = bands_of.levels;
  const int bands = static_cast<int>(levels.size()) - 1;
  const double band_height = std::clamp(box.height / bands, 0.5 * t.small, 2.4 * t.small);
  for (int k = 0; k < bands; ++k) {
    canvas.fill_rect({box.x, box.y + (bands - 1 - k) * band_height, box.width, band_height}, colors[k]);
  }
  canvas.stroke_rect({box.x, box.y, box.width, bands * band_height}, colors::axis, 1.0);
  const double label_x = box.right() + 0.5 * t.small;
  canvas.set_color(colors::text);
  if (uniform_value) {
    canvas.text({label_x, box.y + band_height / 2.0}, format_value(*uniform_value) + " (uniform)", t.small,
                HAlign::left, VAlign::middle);
    return box.y + bands * band_height;
  }
  const TickFormat label(bands_of.label_step, std::max(std::abs(levels.front()), std::abs(levels.back())));
  // Every level while the labels fit, else every second, third, ..
  const int every = std::max(1, static_cast<int>(std::ceil(1.15 * t.small / band_height)));
  for (int k = 0; k <= bands; k += every) {
    const double y = box.y + (bands - k) * band_height;
    canvas.set_color(colors::axis);
    canvas.line({box.right(), y}, {box.right() + 0.3 * t.small, y});
    canvas.set_color(colors::text);
    canvas.text({label_x, y}, label(levels[k]), t.small, HAlign::left, VAlign::middle);
  }
  return box.y + bands * band_height;
}

// ------------------------------------------------------------------------------------------ axes
/// A round step of model length that puts ticks at least min_px apart.
double axis_step(double pixels_per_length, double min_px) {
  const double raw = min_px / pixels_per_length;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * decade >= raw * (1.0 - 1e-9)) return m * decade;
  }
  return 10.0 * decade;
}

/// Multiples of step within [lo, hi].
std::vector<double> ticks_within(double lo, double hi, double step) {
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) {
    ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
  }
  return ticks;
}

/// Space the axes need outside the frame: tick labels and titles to the left and below.
struct AxisGutters {
  double left, bottom;
};

AxisGutters axis_gutters(const Canvas& canvas) {
  const Typography t = typography(canvas);
  // The widest label a round tick gets in practice ("-12.5", "0.0025"): room for seven digits.
  const double label = canvas.text_width("-0.00025", t.small);
  return {0.4 * t.small + label + 0.5 * t.small + 1.4 * t.base, 0.4 * t.small + 1.4 * t.small + 1.4 * t.base};
}

/// The frame round `frame` with ticks on its left and bottom edges at round model coordinates, one
/// step for both axes (the drawing is to scale), labelled, and the axes' titles.
void draw_model_axes(const Canvas& canvas, const Rect& frame, const View& view, const std::string& r_title,
                     const std::string& z_title) {
  const Typography t = typography(canvas);
  const double step = axis_step(view.pixels_per_length, 6.0 * t.small);
  const double r_lo = (frame.x - view.x0) / view.pixels_per_length;
  const double r_hi = (frame.right() - view.x0) / view.pixels_per_length;
  const double z_lo = (view.y0 - frame.bottom()) / view.pixels_per_length;
  const double z_hi = (view.y0 - frame.y) / view.pixels_per_length;
  const double tick = 0.4 * t.small;
  canvas.stroke_rect(frame, colors::axis, 1.0);
  canvas.set_line(1.0);
  const std::vector<double> r_ticks = ticks_within(r_lo, r_hi, step), z_ticks = ticks_within(z_lo, z_hi, step);
  double magnitude = 0.0;
  for (const double v : {r_lo, r_hi, z_lo, z_hi}) magnitude = std::max(magnitude, std::abs(v));
  const TickFormat label(step, magnitude);
  for (const double r : r_ticks) {
    const double x = view({r, 0.0}).x;
    canvas.set_color(colors::axis);
    canvas.line({x, frame.bottom()}, {x, frame.bottom() + tick});
    canvas.set_color(colors::text);
    canvas.text({x, frame.bottom() + tick + 0.2 * t.small}, label(r), t.small, HAlign::center, VAlign::top);
  }
  double widest = 0.0;
  for (const double z : z_ticks) {
    const double y = view({0.0, z}).y;
    canvas.set_color(colors::axis);
    canvas.line({frame.x - tick, y}, {frame.x, y});
    canvas.set_color(colors::text);
    canvas.text({frame.x - tick - 0.3 * t.small, y}, label(z), t.small, HAlign::right, VAlign::middle);
    widest = std::max(widest, canvas.text_width(label(z), t.small));
  }
  canvas.text({frame.x + frame.width / 2.0, frame.bottom() + tick + 1.4 * t.small}, r_title, t.base, HAlign::center,
               VAlign::top);
  cairo_t* cr = canvas.context();
  cairo_save(cr);
  cairo_translate(cr, frame.x - tick - 0.6 * t.small - widest - 0.3 * t.base, frame.y + frame.height / 2.0);
  cairo_rotate(cr, -std::numbers::pi / 2.0);
  canvas.text({0.0, 0.0}, z_title, t.base, HAlign::center, VAlign::bottom);
  cairo_restore(cr);
}

/// Area each node stands for: an equal share of every solid element around it (weights of the
/// quantile levels).
std::vector<double> nodal_areas(const ResultMesh& mesh) {
  std::vector<double> area(mesh.nodes.size(), 0.0);
  for (const SolidElement& e : mesh.solids) {
    const double share = mesh.area(e) / static_cast<double>(e.nodes.size());
    for (const int n : e.nodes) area[n] += share;
  }
  return area;
}

// ------------------------------------------------------------------------------------ extremes
struct Extreme {
  double value;
  int id;
};

/// Smallest and largest of values[i] (NaN skipped), with ids[i].
std::pair<Extreme, Extreme> extremes(const std::vector<double>& values, const std::vector<int>& ids) {
  Extreme low{std::numeric_limits<double>::infinity(), 0}, high{-std::numeric_limits<double>::infinity(), 0};
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isnan(values[i])) continue;
    if (values[i] < low.value) low = {values[i], ids[i]};
    if (values[i] > high.value) high = {values[i], ids[i]};
  }
  return {low, high};
}

}  // namespace

double automatic_deformation_scale(const ResultMesh& mesh) {
  double largest = 0.0, r0 = std::numeric_limits<double>::max(), r1 = -r0, z0 = r0, z1 = -r0;
  for (const MeshNode& n : mesh.nodes) {
    largest = std::max(largest, std::hypot(n.u_r, n.u_z));
    r0 = std::min(r0, n.r);
    r1 = std::max(r1, n.r);
    z0 = std::min(z0, n.z);
    z1 = std::max(z1, n.z);
  }
  const double extent = std::max(r1 - r0, z1 - z0);
  if (largest <= 0.0 || extent <= 0.0) return 1.0;
  const double wanted = 0.08 * extent / largest;
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
  for (const double m : {5.0, 2.0, 1.0}) {
    if (m * decade <= wanted) return m * decade;
  }
  return decade;
}

void draw_contour_plot(const Canvas& canvas, const PlotResult& result, const ContourOptions& options) {
  const FieldInfo& field = find_field(options.field);
  if (field.location == FieldLocation::gap) {
    throw std::invalid_argument("'" + std::string(field.name) + "' is a gap field: plot it with the closure plot");
  }
  if (options.deformation_scale && !(*options.deformation_scale > 0.0 && std::isfinite(*options.deformation_scale))) {
    throw std::invalid_argument("the deformation scale must be a positive number, not " +
                                format_value(*options.deformation_scale));
  }
  ColorMap::require_name(options.color_map);  // before the work
  const ResultMesh& mesh = result.mesh();
  if (mesh.solids.empty()) throw std::invalid_argument("the result has no solid elements to contour");
  require_field_fits(field, mesh);
  const std::vector<double> values = nodal_values(result, mesh, field, options.centre);

  // Levels from the values at the nodes of solid elements (the contoured ones): a node no solid
  // element uses weighs nothing.
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const SolidElement& e : mesh.solids) {
    for (const int n : e.nodes) {
      low = std::min(low, values[n]);
      high = std::max(high, values[n]);
    }
  }
  if (!std::isfinite(low) || !std::isfinite(high)) throw std::invalid_argument("the field has no finite values");
  const BandLevels bands_of = band_levels(values, nodal_areas(mesh), options.max_bands, options.levels);
  const std::vector<double>& levels = bands_of.levels;
  const ColorMap colors_of = ColorMap::named(ColorMap::for_range(options.color_map, low, high));
  const std::vector<Rgb> band_colors = colors_of.band_colors(levels);
  const bool uniform = bands_of.uniform;

  // Extremes for the panel: element values as computed (averaging at nodes lowers peaks), or
  // nodal ones for node fields.
  std::vector<double> raw;
  std::vector<int> ids;
  if (field.location == FieldLocation::element) {
    raw = element_values(result, mesh, field, options.centre);
    for (const SolidElement& e : mesh.solids) ids.push_back(e.id);
  } else {
    // Over the nodes drawn: a wall node that only a gap element uses is not part of the picture.
    raw.assign(mesh.nodes.size(), std::numeric_limits<double>::quiet_NaN());
    for (const SolidElement& e : mesh.solids) {
      for (const int n : e.nodes) raw[n] = values[n];
    }
    for (const MeshNode& n : mesh.nodes) ids.push_back(n.id);
  }
  const auto [lowest, highest] = extremes(raw, ids);
  const char* where = field.location == FieldLocation::element ? "element" : "node";

  // ---- Header and layout: the mesh on the left, the colour bar and legends on the right.
  const bool deformed = options.automatic_deformation || options.deformation_scale.has_value();
  const double deformation = options.automatic_deformation ? automatic_deformation_scale(mesh)
                                                           : options.deformation_scale.value_or(0.0);
  std::string subtitle = field_label(field, mesh, options.centre) + " " + unit_phrase(field.quantity, mesh.units) +
                         (uniform ? "" : options.levels == LevelRule::quantile ? ", bands of equal area"
                                                                                 : ", bands of equal width") +
                         (colors_of.centred_on_zero() && !uniform ? ", white at zero" : "") + "\n";
  if (deformed) {
    subtitle += "Deformed shape, displacements \u00d7" + format_value(deformation, 3) + " (dashed: undeformed)";
  } else {
    subtitle += "Undeformed mesh";
  }
  subtitle += " \u2014 " + run_summary(mesh.status, mesh.iterations);
  const Rect area = draw_header(canvas, mesh.title.empty() ? "SAASGAPS result" : mesh.title, subtitle);
  const Typography t = typography(canvas);

  const TickFormat level_text(bands_of.label_step, std::max(std::abs(levels.front()), std::abs(levels.back())));
  const std::string bar_title = with_unit(field_title(field, mesh), field.quantity, mesh.units);
  const double bar_width = 1.6 * t.base;
  double panel_width = 0.0;
  for (const double l : levels) panel_width = std::max(panel_width, canvas.text_width(level_text(l), t.small));
  const std::optional<double> uniform_value = uniform ? std::optional<double>((low + high) / 2.0) : std::nullopt;
  if (uniform_value) panel_width = canvas.text_width(format_value(*uniform_value) + " (uniform)", t.small);
  panel_width += bar_width + 0.6 * t.small;
  const std::string max_text = "max " + format_value(highest.value) + " (" + where + " " + std::to_string(highest.id) + ")";
  const std::string min_text = "min " + format_value(lowest.value) + " (" + where + " " + std::to_string(lowest.id) + ")";
  for (const std::string& s : {max_text, min_text, bar_title}) {
    panel_width = std::max(panel_width, canvas.text_width(s, t.small, true));
  }
  if (!mesh.gaps.empty()) panel_width = std::max(panel_width, gap_legend_width(canvas));
  const Rect panel{area.right() - t.margin - panel_width, area.y + 0.5 * t.margin, panel_width,
                   area.height - 1.5 * t.margin};
  const AxisGutters gutters = axis_gutters(canvas);
  const Rect plot{area.x + t.margin + gutters.left, area.y + 0.5 * t.margin,
                  panel.x - 2.0 * t.margin - area.x - gutters.left, area.height - 1.5 * t.margin - gutters.bottom};

  // ---- The view: everything drawn must fit, deformed and undeformed.
  std::vector<std::array<double, 2>> extent;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    extent.push_back(mesh.position(static_cast<int>(n), 0.0));
    if (deformation != 0.0) extent.push_back(mesh.position(static_cast<int>(n), deformation));
  }
  const double strip = std::max(5.0, 0.5 * t.base);  // gap marker width, px
  const Rect inset{plot.x + strip, plot.y + strip, plot.width - 2.0 * strip, plot.height - 2.0 * strip};
  const View view = fit_view(extent, inset);
  const std::vector<Point> at = device_positions(mesh, view, deformation);
  const std::vector<Point> rest = device_positions(mesh, view, 0.0);
  const std::vector<std::array<int, 2>> outline = boundary_edges(mesh);
  cairo_t* cr = canvas.context();
  if (deformed) {
    canvas.set_color(grey(0.55));
    canvas.set_line(0.9, true);
    stroke_edges(cr, outline, rest);
    canvas.set_line(1.0);
  }

  const bool raster = options.fill == BandFill::raster ||
                      (options.fill == BandFill::automatic && mesh.solids.size() > path_fill_limit);
  if (raster) {
    raster_bands(canvas, mesh, at, values, levels, band_colors);
  } else {
    fill_bands(canvas, mesh, at, values, levels, band_colors);
  }

  if (options.mesh) {
    canvas.set_color(grey(0.15), 0.55);
    canvas.set_line(0.6);
    for (const SolidElement& e : mesh.solids) {
      std::vector<Point> corners;
      for (const int n : e.nodes) corners.push_back(at[n]);
      canvas.polygon(corners);
    }
    cairo_stroke(cr);
  }
  canvas.set_color(colors::black);
  canvas.set_line(1.2);
  stroke_edges(cr, outline, at);
  canvas.set_line(1.0);
  draw_gap_markers(canvas, mesh, at, rest, strip);
  const std::string length_unit = with_unit("", Quantity::length, mesh.units);
  draw_model_axes(canvas, plot, view, (mesh.plane() ? "x" : "r") + length_unit, (mesh.plane() ? "y" : "z") + length_unit);

  // ---- The panel: field name, colour bar, extreme values, gap legend.
  double y = panel.y;
  canvas.set_color(colors::text);
  canvas.text({panel.x, y}, bar_title, t.small, HAlign::left, VAlign::top, true);
  y += 2.3 * t.small;  // room for the top level's label
  const double legend_height = mesh.gaps.empty() ? 0.0 : gap_legend_height(canvas);
  const Rect bar{panel.x, y, bar_width, panel.bottom() - y - 4.5 * t.small - legend_height};
  y = draw_color_bar(canvas, bar, bands_of, band_colors, uniform_value);
  y += 1.2 * t.small;
  canvas.text({panel.x, y}, max_text, t.small, HAlign::left, VAlign::top);
  y += 1.4 * t.small;
  canvas.text({panel.x, y}, min_text, t.small, HAlign::left, VAlign::top);
  y += 2.2 * t.small;

  // ---- Gap legend with counts.
  if (!mesh.gaps.empty()) draw_gap_legend(canvas, mesh, {panel.x, y});
}

}  // namespace saasgaps::plot
