#include "plot/pictures/gap_markers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "plot/draw/color_map.hpp"
#include "plot/draw/figure.hpp"
#include "plot/draw/polygon.hpp"

namespace saasgaps::plot {

namespace {

struct GapStyle {
  Rgb fill;
  Rgb outline;
  bool dashed;
  const char* legend;
};

GapStyle gap_style(GapState state) {
  switch (state) {
    case GapState::closed: return {grey(0.30), grey(0.15), false, "closed"};
    case GapState::overclosed: return {colors::black, colors::black, false, "overclosed"};
    case GapState::partial: return {grey(0.80), grey(0.45), false, "partial"};
    case GapState::open: return {colors::white, grey(0.20), true, "open"};
  }
  return {colors::white, colors::black, false, "?"};
}

/// The gap's two faces, node indices: face_a[k] and face_b[k] are joined by an edge that crosses the
/// gap (the edges most nearly along M). A triangle's single corner on one side repeats.
struct GapFaces {
  std::array<int, 2> a, b;
};

GapFaces gap_faces(const ResultMesh& mesh, const GapElement& g) {
  const double mr = std::cos(g.angle_deg * std::numbers::pi / 180.0);
  const double mz = std::sin(g.angle_deg * std::numbers::pi / 180.0);
  const std::size_t n = g.nodes.size();
  // |cos| of the angle between edge i (node i to node i + 1) and M.
  std::vector<double> along_m(n);
  for (std::size_t i = 0; i < n; ++i) {
    const MeshNode& p = mesh.nodes[g.nodes[i]];
    const MeshNode& q = mesh.nodes[g.nodes[(i + 1) % n]];
    const double length = std::hypot(q.r - p.r, q.z - p.z);
    along_m[i] = length > 0.0 ? std::abs((q.r - p.r) * mr + (q.z - p.z) * mz) / length : 0.0;
  }
  const auto node = [&](std::size_t i) { return g.nodes[i % n]; };
  if (n == 4) {
    // Crossing edges are opposite: 0 and 2 (faces 3-0 and 1-2) or 1 and 3 (faces 0-1 and 2-3).
    const std::size_t i = along_m[0] + along_m[2] >= along_m[1] + along_m[3] ? 0 : 1;
    return {{node(i), node(i + 3)}, {node(i + 1), node(i + 2)}};
  }
  // Triangle: the edge least along M is a face; the opposite corner is the other side.
  const std::size_t face = static_cast<std::size_t>(std::min_element(along_m.begin(), along_m.end()) - along_m.begin());
  return {{node(face + 2), node(face + 2)}, {node(face), node(face + 1)}};
}

}  // namespace

void draw_gap_markers(const Canvas& canvas, const ResultMesh& mesh, const std::vector<Point>& at,
                      const std::vector<Point>& undeformed, double strip) {
  cairo_t* cr = canvas.context();
  std::vector<bool> in_solid(mesh.nodes.size(), false);
  for (const SolidElement& e : mesh.solids) {
    for (const int n : e.nodes) in_solid[n] = true;
  }
  const auto mid = [](Point p, Point q) { return Point{(p.x + q.x) / 2.0, (p.y + q.y) / 2.0}; };
  for (const GapElement& g : mesh.gaps) {
    const GapFaces f = gap_faces(mesh, g);
    const bool a_attached = in_solid[f.a[0]] && in_solid[f.a[1]];
    const bool b_attached = in_solid[f.b[0]] && in_solid[f.b[1]];
    const bool one_sided = a_attached != b_attached;
    std::array<Point, 2> anchor;
    if (one_sided) {
      const std::array<int, 2>& face = a_attached ? f.a : f.b;
      anchor = {at[face[0]], at[face[1]]};
    } else {
      anchor = {mid(at[f.a[0]], at[f.b[0]]), mid(at[f.a[1]], at[f.b[1]])};
    }
    const double dx = anchor[1].x - anchor[0].x, dy = anchor[1].y - anchor[0].y;
    const double length = std::hypot(dx, dy);
    std::vector<Point> shape;
    for (const int n : g.nodes) shape.push_back(at[n]);
    std::vector<Point> rest;
    for (const int n : g.nodes) rest.push_back(undeformed[n]);
    const double a_now = signed_area(shape), a_rest = signed_area(rest);
    const bool as_is = length <= 1e-9 || (a_now * a_rest > 0.0 && std::abs(a_now) / length >= strip);
    if (!as_is) {
      // Unit normal pointing from face a towards face b (in the undeformed drawing, where the gap
      // is the right way round).
      Point normal{-dy / length, dx / length};
      const Point from = mid(undeformed[f.a[0]], undeformed[f.a[1]]);
      const Point to = mid(undeformed[f.b[0]], undeformed[f.b[1]]);
      if (normal.x * (to.x - from.x) + normal.y * (to.y - from.y) < 0.0) normal = {-normal.x, -normal.y};
      if (one_sided && b_attached) normal = {-normal.x, -normal.y};  // outwards from face b's body
      // One-sided: outwards from the body's face; between two bodies: centred on the mid-line.
      const double o0 = one_sided ? 0.0 : -strip / 2.0, o1 = o0 + strip;
      shape = {{anchor[0].x + o0 * normal.x, anchor[0].y + o0 * normal.y},
               {anchor[1].x + o0 * normal.x, anchor[1].y + o0 * normal.y},
               {anchor[1].x + o1 * normal.x, anchor[1].y + o1 * normal.y},
               {anchor[0].x + o1 * normal.x, anchor[0].y + o1 * normal.y}};
    }
    const GapStyle style = gap_style(g.state);
    canvas.polygon(shape);
    canvas.set_color(style.fill);
    cairo_fill_preserve(cr);
    canvas.set_color(style.outline);
    canvas.set_line(0.8, style.dashed);
    cairo_stroke(cr);
  }
  canvas.set_line(1.0);
}

double gap_legend_width(const Canvas& canvas) {
  const Typography t = typography(canvas);
  return 1.6 * t.small + canvas.text_width("overclosed (0000)", t.small);
}

double gap_legend_height(const Canvas& canvas) { return 7.6 * typography(canvas).small; }

double draw_gap_legend(const Canvas& canvas, const ResultMesh& mesh, Point top_left) {
  const Typography t = typography(canvas);
  const double swatch = 1.1 * t.small;
  double y = top_left.y;
  canvas.set_color(colors::text);
  canvas.text({top_left.x, y}, "gap elements", t.small, HAlign::left, VAlign::top, true);
  y += 1.6 * t.small;
  for (const GapState s : all_gap_states) {
    const GapStyle style = gap_style(s);
    const auto count = std::count_if(mesh.gaps.begin(), mesh.gaps.end(), [s](const GapElement& g) { return g.state == s; });
    cairo_rectangle(canvas.context(), top_left.x + 0.5, y + 0.5, swatch, 0.6 * swatch);
    canvas.set_color(style.fill);
    cairo_fill_preserve(canvas.context());
    canvas.set_color(style.outline);
    canvas.set_line(0.8, style.dashed);
    cairo_stroke(canvas.context());
    canvas.set_color(colors::text);
    canvas.text({top_left.x + swatch + 0.5 * t.small, y + 0.3 * swatch},
                std::string(style.legend) + " (" + std::to_string(count) + ")", t.small, HAlign::left, VAlign::middle);
    y += 1.5 * t.small;
  }
  canvas.set_line(1.0);
  return y - top_left.y;
}

}  // namespace saasgaps::plot
