#include "gap_faces.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "element_data.hpp"
#include "element_kernel.hpp"

namespace saasgaps {

namespace {

Vec2 axis(double angle_deg) {
  const double angle = angle_deg * std::numbers::pi / 180.0;
  return {std::cos(angle), std::sin(angle)};
}

/// |cos| of the angle between edge p-q and M: |sin| of its angle to the perpendicular to M.
double lean(const std::array<Vec2, 4>& x, int p, int q, const Vec2& m) {
  return std::abs((x[q] - x[p]).normalized().dot(m));
}

/// A quadrilateral's faces 0-1 / 3-2 (first) or 1-2 / 0-3, measured against M.
GapFaces quad_faces(const std::array<Vec2, 4>& x, bool first, const Vec2& m) {
  GapFaces f;
  f.one = first ? std::array<int, 2>{0, 1} : std::array<int, 2>{1, 2};
  f.two = first ? std::array<int, 2>{3, 2} : std::array<int, 2>{0, 3};
  f.lean = std::max(lean(x, f.one[0], f.one[1], m), lean(x, f.two[0], f.two[1], m));
  f.separation = (0.5 * (x[f.one[0]] + x[f.one[1]]) - 0.5 * (x[f.two[0]] + x[f.two[1]])).norm();
  f.length = 0.5 * ((x[f.one[1]] - x[f.one[0]]).norm() + (x[f.two[1]] - x[f.two[0]]).norm());
  return f;
}

GapFaces triangle_faces(const std::array<Vec2, 4>& x, int e0, const Vec2& m) {
  GapFaces f;
  const int e1 = (e0 + 1) % 3, lone = (e0 + 2) % 3;
  f.one = {e0, e1};
  f.two = {lone, lone};
  f.lean = lean(x, e0, e1, m);
  const Vec2 edge = x[e1] - x[e0];
  f.length = edge.norm();
  f.separation = std::abs(twice_signed_area(x[e0], x[e1], x[lone])) / f.length;
  return f;
}

/// The faces a correct M would run across: the pair (or edge) with the smallest s / L.
GapFaces long_sides_of(const std::array<Vec2, 4>& x, int node_count, const Vec2& m) {
  const auto thinner = [](const GapFaces& a, const GapFaces& b) {
    return a.separation * b.length <= b.separation * a.length;
  };
  if (node_count == 4) {
    const GapFaces a = quad_faces(x, true, m), b = quad_faces(x, false, m);
    return thinner(a, b) ? a : b;
  }
  GapFaces best = triangle_faces(x, 0, m);
  for (int e = 1; e < 3; ++e) {
    const GapFaces f = triangle_faces(x, e, m);
    if (!thinner(best, f)) best = f;
  }
  return best;
}

/// The angle in (-90, 90] of the normal to the faces f (their mean direction).
double angle_across(const std::array<Vec2, 4>& x, const GapFaces& f) {
  Vec2 along = (x[f.one[1]] - x[f.one[0]]).normalized();
  if (f.two[0] != f.two[1]) along += (x[f.two[1]] - x[f.two[0]]).normalized();
  double angle = std::atan2(along.x(), -along.y()) * 180.0 / std::numbers::pi;
  if (angle <= -90.0) angle += 180.0;
  if (angle > 90.0) angle -= 180.0;
  return angle;
}

std::string faces_text(const Model& model, const GapElement& gap, const GapFaces& f) {
  const auto id = [&](int corner) { return model.nodes[gap.nodes[corner]].id; };
  std::ostringstream text;
  text << "nodes " << id(f.one[0]) << "-" << id(f.one[1]);
  if (f.two[0] == f.two[1]) {
    text << " and node " << id(f.two[0]);
  } else {
    text << " and " << id(f.two[0]) << "-" << id(f.two[1]);
  }
  return text.str();
}

}  // namespace

GapFaces gap_faces(const std::array<Vec2, 4>& x, int node_count, double angle_deg) {
  const Vec2 m = axis(angle_deg);
  if (node_count == 4) {
    const GapFaces a = quad_faces(x, true, m), b = quad_faces(x, false, m);
    return a.lean <= b.lean ? a : b;
  }
  int best = 0;
  for (int e = 1; e < 3; ++e) {
    if (lean(x, e, (e + 1) % 3, m) < lean(x, best, (best + 1) % 3, m)) best = e;
  }
  return triangle_faces(x, best, m);
}

bool runs_across(const GapFaces& faces) {
  // Rule (2) with a margin of round-off: a square gap is as long as it is wide either way.
  return faces.lean <= max_face_lean && faces.separation <= faces.length * (1.0 + 1.0e-9);
}

std::optional<std::string> gap_axis_problem(const Model& model, const GapElement& gap) {
  const std::array<Vec2, 4> x = corner_coordinates(model, gap.nodes, gap.node_count);
  const GapFaces faces = gap_faces(x, gap.node_count, gap.angle_deg);
  if (runs_across(faces)) return std::nullopt;
  const bool across = faces.lean <= max_face_lean;
  const GapFaces right = long_sides_of(x, gap.node_count, axis(gap.angle_deg));
  std::ostringstream text;
  text << "angle " << gap.angle_deg << " does not run across gap element " << gap.id << ": ";
  if (!across) {
    text << "no " << (gap.node_count == 4 ? "two opposite edges lie" : "edge lies")
         << " within 30 degrees of perpendicular to M";
  } else {
    text << "M crosses " << faces_text(model, gap, faces) << ", which are " << faces.separation
         << " apart but only " << faces.length << " long, so M runs along the gap";
  }
  text << "; the gap's faces are its long sides, " << faces_text(model, gap, right)
       << ", and M must be within 30 degrees of perpendicular to them: angle " << angle_across(x, right)
       << " (or that plus or minus 180)";
  return text.str();
}

double gap_face_area(const Model& model, const GapElement& gap) {
  const std::array<Vec2, 4> x = corner_coordinates(model, gap.nodes, gap.node_count);
  const GapFaces f = gap_faces(x, gap.node_count, gap.angle_deg);
  const auto area = [&](int p, int q) {
    const auto loads = edge_traction_loads(x[p], x[q], Vec2(1.0, 0.0), model.analysis, model.thickness);
    return loads[0].x() + loads[1].x();
  };
  const double one = area(f.one[0], f.one[1]);
  return 0.5 * (one + (f.two[0] == f.two[1] ? 0.0 : area(f.two[0], f.two[1])));
}

}  // namespace saasgaps
