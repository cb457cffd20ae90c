#include "plot/pictures/contour_plot.hpp"

#include <algorithm>
#include <deque>
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
#include "plot/result/element_field.hpp"
#include "plot/result/element_map.hpp"
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

// ---------------------------------------------------------------------------------- the samples
/// The field at the points of each element's drawing subdivision (element_map.hpp), element after
/// element: what the bands are drawn from, the levels computed from and the extremes read from,
/// so that the colour bar and the max and min labels describe the field drawn.
struct Samples {
  std::vector<double> values;   ///< per element, its subdivision's points in order
  std::vector<double> weights;  ///< the area each stands for: an equal share of its element
  /// The lowest [0] and the highest [1] sample (NaN skipped): its index, element, model point.
  std::array<std::size_t, 2> extreme{0, 0};
  std::array<std::size_t, 2> element{0, 0};
  std::array<PlanePoint, 2> where{};
};

/// A family's shape functions at a subdivision's points, computed once per family and subdivision
/// (two families may share a subdivision: saas and, above 20,000 elements, quad8 and quad9).
const std::vector<ShapeValues>& shape_at(const ElementFamily& family, const Subdivision& sub) {
  struct Entry {
    const ElementFamily* family;
    const Subdivision* sub;
    std::vector<ShapeValues> values;
  };
  static thread_local std::deque<Entry> cache;  // a deque: the references handed out stay valid
  for (const Entry& entry : cache) {
    if (entry.family == &family && entry.sub == &sub) return entry.values;
  }
  std::vector<ShapeValues> values(sub.points.size());
  for (std::size_t k = 0; k < sub.points.size(); ++k) family.shape(sub.points[k].xi, sub.points[k].eta, values[k]);
  cache.push_back({&family, &sub, std::move(values)});
  return cache.back().values;
}

/// sum_a N_a p[nodes[a]]
template <class P>
std::array<double, 2> mapped(const std::vector<int>& nodes, const ShapeValues& N, const P& position) {
  std::array<double, 2> x{0.0, 0.0};
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const std::array<double, 2> p = position(nodes[a]);
    x[0] += N.N[a] * p[0];
    x[1] += N.N[a] * p[1];
  }
  return x;
}

Samples sample_field(const ResultMesh& mesh, const ElementField& field, bool many) {
  Samples s;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  const auto undeformed = [&mesh](int n) { return std::array<double, 2>{mesh.nodes[n].r, mesh.nodes[n].z}; };
  for (std::size_t e = 0; e < mesh.solids.size(); ++e) {
    const ElementFamily& family = element_family(mesh.solids[e]);
    const std::vector<int> nodes = family_nodes(mesh.solids[e]);
    const Subdivision& sub = drawing_subdivision(family, many);
    const std::vector<ShapeValues>& N = shape_at(family, sub);
    const double share = mesh.area(mesh.solids[e]) / static_cast<double>(sub.points.size());
    for (std::size_t k = 0; k < sub.points.size(); ++k) {
      const PlanePoint at = mapped(nodes, N[k], undeformed);
      const double v = field.value(e, nodes, N[k], at);
      for (const std::size_t end : {0U, 1U}) {
        if (end == 0 ? v < low : v > high) {
          (end == 0 ? low : high) = v;
          s.extreme[end] = s.values.size();
          s.element[end] = e;
          s.where[end] = at;
        }
      }
      s.values.push_back(v);
      s.weights.push_back(share);
    }
  }
  return s;
}

/// Element e's triangles in device px, valued from the samples starting at `first`; returns the
/// next element's first sample.
std::size_t element_triangles(const ResultMesh& mesh, std::size_t e, bool many, const std::vector<Point>& at,
                              const Samples& samples, std::size_t first, std::vector<ValueTriangle>& out) {
  const ElementFamily& family = element_family(mesh.solids[e]);
  const std::vector<int> nodes = family_nodes(mesh.solids[e]);
  const Subdivision& sub = drawing_subdivision(family, many);
  const std::vector<ShapeValues>& N = shape_at(family, sub);
  const auto device = [&at](int n) { return std::array<double, 2>{at[n].x, at[n].y}; };
  std::vector<ValuePoint> points;
  for (std::size_t k = 0; k < sub.points.size(); ++k) {
    const std::array<double, 2> p = mapped(nodes, N[k], device);
    points.push_back({p[0], p[1], samples.values[first + k]});
  }
  for (const auto& [a, b, c] : sub.triangles) {
    out.push_back({points[static_cast<std::size_t>(a)], points[static_cast<std::size_t>(b)],
                   points[static_cast<std::size_t>(c)]});
  }
  return first + sub.points.size();
}

// ----------------------------------------------------------------------------------------- edges
/// An element's edge as drawn: its points from corner to corner in device px, through the
/// mid-side node along the element's own map, in the straight pieces of the element's drawing
/// subdivision (drawing_edge_pieces): the outline and the mesh lines follow the bands' edges
/// (finer pieces left white slivers between the bands and a curved outline).
void add_edge_path(cairo_t* cr, const SolidElement& e, int edge, const std::vector<Point>& at, bool many) {
  const ElementFamily& family = element_family(e);
  const std::vector<int> nodes = family_nodes(e);
  const EdgeNodes& nodes_of_edge = family.edges[static_cast<std::size_t>(edge)];
  const auto& p0 = family.node_positions[static_cast<std::size_t>(nodes_of_edge.first())];
  const auto& p1 = family.node_positions[static_cast<std::size_t>(nodes_of_edge.last())];
  const int pieces = drawing_edge_pieces(family, many);
  const auto device = [&at](int n) { return std::array<double, 2>{at[n].x, at[n].y}; };
  ShapeValues N;
  for (int k = 0; k <= pieces; ++k) {
    const double t = static_cast<double>(k) / pieces;
    family.shape(p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1]), N);
    const std::array<double, 2> p = mapped(nodes, N, device);
    if (k == 0) cairo_move_to(cr, p[0], p[1]);
    else cairo_line_to(cr, p[0], p[1]);
  }
}

/// Edges of solid elements used by exactly one of them: the outline of the bodies, as (element,
/// edge) in increasing order of the edge's (lower corner, higher corner). (Sorted in a flat vector:
/// a map of the 10^6 edges of a large mesh cost 100 MB.)
std::vector<std::array<std::size_t, 2>> boundary_edges(const ResultMesh& mesh) {
  struct Edge {
    int low, high;
    std::size_t element;
    int edge;
  };
  std::vector<Edge> all;
  for (std::size_t e = 0; e < mesh.solids.size(); ++e) {
    const ElementFamily& family = element_family(mesh.solids[e]);
    const std::vector<int> nodes = family_nodes(mesh.solids[e]);
    for (int k = 0; k < family.edge_count(); ++k) {
      const EdgeNodes& edge = family.edges[static_cast<std::size_t>(k)];
      const int p = nodes[static_cast<std::size_t>(edge.first())], q = nodes[static_cast<std::size_t>(edge.last())];
      all.push_back({std::min(p, q), std::max(p, q), e, k});
    }
  }
  const auto key = [](const Edge& a) { return std::array<int, 2>{a.low, a.high}; };
  std::sort(all.begin(), all.end(), [&key](const Edge& a, const Edge& b) { return key(a) < key(b); });
  std::vector<std::array<std::size_t, 2>> edges;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while (j < all.size() && key(all[j]) == key(all[i])) ++j;
    if (j - i == 1) edges.push_back({all[i].element, static_cast<std::size_t>(all[i].edge)});
    i = j;
  }
  return edges;
}

void stroke_edges(cairo_t* cr, const ResultMesh& mesh, const std::vector<std::array<std::size_t, 2>>& edges,
                  const std::vector<Point>& at, bool many) {
  for (const auto& [e, edge] : edges) add_edge_path(cr, mesh.solids[e], static_cast<int>(edge), at, many);
  cairo_stroke(cr);
}

// ----------------------------------------------------------------------------------------- bands
/// Fills the bands between levels over the solid elements. Level k's path is every triangle's part
/// where v >= levels[k]; painting the levels in increasing order leaves each point the colour of
/// its band, and since one path holds all triangles, antialiasing leaves no seams along the
/// element edges.
void fill_bands(const Canvas& canvas, const ResultMesh& mesh, const std::vector<Point>& at, const Samples& samples,
                bool many, const std::vector<double>& levels, const std::vector<Rgb>& colors) {
  cairo_t* cr = canvas.context();
  std::vector<ValueTriangle> triangles;
  triangles.reserve(2 * mesh.solids.size());
  for (std::size_t e = 0, first = 0; e < mesh.solids.size(); ++e) {
    first = element_triangles(mesh, e, many, at, samples, first, triangles);
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
void raster_bands(const Canvas& canvas, const ResultMesh& mesh, const std::vector<Point>& at, const Samples& samples,
                  bool many, const std::vector<double>& levels, const std::vector<Rgb>& colors) {
  BandRaster raster(canvas.width(), canvas.height(), levels, colors);
  const std::size_t bands = levels.size() - 1;
  std::vector<std::vector<std::array<Point, 2>>> iso_lines(bands);  // [k]: level k's segments, k >= 1
  std::vector<ValueTriangle> triangles;
  for (std::size_t e = 0, first = 0; e < mesh.solids.size(); ++e) {
    triangles.clear();
    first = element_triangles(mesh, e, many, at, samples, first, triangles);
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

ContourLegend draw_contour_plot(const Canvas& canvas, const PlotResult& result, const ContourOptions& options) {
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
  const ElementField field_values(result, field, options.centre);
  const bool many = mesh.solids.size() > path_fill_limit;
  const Samples samples = sample_field(mesh, field_values, many);
  const double low = samples.values[samples.extreme[0]], high = samples.values[samples.extreme[1]];
  if (!std::isfinite(low) || !std::isfinite(high)) throw std::invalid_argument("the field has no finite values");
  // Levels, colour bar and extremes from the same samples: the field drawn.
  const BandLevels bands_of = band_levels(samples.values, samples.weights, options.max_bands, options.levels);
  const std::vector<double>& levels = bands_of.levels;
  const ColorMap colors_of = ColorMap::named(ColorMap::for_range(options.color_map, low, high));
  const std::vector<Rgb> band_colors = colors_of.band_colors(levels);
  const bool uniform = bands_of.uniform;
  const auto extreme_text = [&](const char* what, int k) {
    const auto i = static_cast<std::size_t>(k);
    const std::string element = "element " + std::to_string(mesh.solids[samples.element[i]].id);
    // A field constant in each element has its extreme in the whole element, not at a point.
    if (field_values.source() == FieldSource::element) {
      return std::string(what) + " " + format_value(samples.values[samples.extreme[i]]) + " in " + element;
    }
    return std::string(what) + " " + format_value(samples.values[samples.extreme[i]]) + " at (" +
           format_value(samples.where[i][0]) + ", " + format_value(samples.where[i][1]) + "), " + element;
  };
  const ContourLegend legend{levels, low, high, mesh.solids[samples.element[0]].id, mesh.solids[samples.element[1]].id,
                             samples.where[0], samples.where[1], field_values.source()};

  // ---- Header and layout: the mesh on the left, the colour bar and legends on the right.
  const bool deformed = options.automatic_deformation || options.deformation_scale.has_value();
  const double deformation = options.automatic_deformation ? automatic_deformation_scale(mesh)
                                                           : options.deformation_scale.value_or(0.0);
  std::string subtitle = field_label(field, mesh, options.centre) + " " + unit_phrase(field.quantity, mesh.units) +
                         ", " + source_phrase(field_values.source()) +
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
  const std::string max_text = extreme_text("max", 1);
  const std::string min_text = extreme_text("min", 0);
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
  const std::vector<std::array<std::size_t, 2>> outline = boundary_edges(mesh);
  cairo_t* cr = canvas.context();
  if (deformed) {
    canvas.set_color(grey(0.55));
    canvas.set_line(0.9, true);
    stroke_edges(cr, mesh, outline, rest, many);
    canvas.set_line(1.0);
  }

  const bool raster = options.fill == BandFill::raster ||
                      (options.fill == BandFill::automatic && mesh.solids.size() > path_fill_limit);
  if (raster) {
    raster_bands(canvas, mesh, at, samples, many, levels, band_colors);
  } else {
    fill_bands(canvas, mesh, at, samples, many, levels, band_colors);
  }

  if (options.mesh) {
    canvas.set_color(grey(0.15), 0.55);
    canvas.set_line(0.6);
    for (const SolidElement& e : mesh.solids) {
      for (int k = 0; k < element_family(e).edge_count(); ++k) add_edge_path(cr, e, k, at, many);
    }
    cairo_stroke(cr);
  }
  canvas.set_color(colors::black);
  canvas.set_line(1.2);
  stroke_edges(cr, mesh, outline, at, many);
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
  return legend;
}

}  // namespace saasgaps::plot
