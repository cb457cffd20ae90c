#include "solver/gaps/gap_faces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "solver/assembly/element_data.hpp"
#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_geometry.hpp"
#include "solver/fe/element_kernel.hpp"

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

bool runs_across(const GapFaces& faces) { return faces.lean <= max_face_lean; }

namespace {

/// An edge by its node indices, either order.
std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{hi} << 32) | lo;
}

/// Per edge of the gap elements: how many gap elements have it, and whether a solid element has it.
/// One pass over the solids; memory O(gap elements), not O(elements).
struct GapEdges {
  std::unordered_map<std::uint64_t, int> gaps;
  std::unordered_set<std::uint64_t> on_solid;

  GapEdges(const Model& model, std::span<const GapElement> list) {
    // Most solid edges touch no gap: a flag per node spares them the hash lookup (at 10^6 unknowns
    // the lookups were 7 % of reading the model).
    std::vector<bool> on_gap(model.nodes.size(), false);
    for (const GapElement& g : list) {
      for (int k = 0; k < g.node_count; ++k) {
        ++gaps[edge_key(g.nodes[k], g.nodes[(k + 1) % g.node_count])];
        if (g.nodes[k] >= 0 && static_cast<std::size_t>(g.nodes[k]) < on_gap.size()) on_gap[static_cast<std::size_t>(g.nodes[k])] = true;
      }
    }
    for (const Element& e : model.elements) {
      for (int k = 0; k < e.node_count; ++k) {
        const int a = e.nodes[k];
        if (a < 0 || static_cast<std::size_t>(a) >= on_gap.size() || !on_gap[static_cast<std::size_t>(a)]) continue;
        const std::uint64_t key = edge_key(a, e.nodes[(k + 1) % e.node_count]);
        if (gaps.count(key)) on_solid.insert(key);
      }
    }
  }
  [[nodiscard]] bool shared(const GapElement& g, int p, int q) const { return gaps.at(edge_key(g.nodes[p], g.nodes[q])) > 1; }
  [[nodiscard]] bool solid(const GapElement& g, int p, int q) const { return on_solid.count(edge_key(g.nodes[p], g.nodes[q])) > 0; }
};

/// The sides of a gap other than its faces f: a quadrilateral's other pair, a triangle's other edges.
std::vector<std::array<int, 2>> other_sides(const GapFaces& f, int node_count) {
  std::vector<std::array<int, 2>> out;
  for (int k = 0; k < node_count; ++k) {
    const std::array<int, 2> e{k, (k + 1) % node_count};
    const auto same = [&](const std::array<int, 2>& g) {
      return (g[0] == e[0] && g[1] == e[1]) || (g[0] == e[1] && g[1] == e[0]);
    };
    if (!same(f.one) && !(f.two[0] != f.two[1] && same(f.two))) out.push_back(e);
  }
  return out;
}

std::optional<std::string> axis_problem(const Model& model, const GapElement& gap, const GapEdges& edges) {
  const std::array<Vec2, 4> x = corner_coordinates(model, gap.nodes, gap.node_count);
  const GapFaces faces = gap_faces(x, gap.node_count, gap.angle_deg);
  const auto id = [&](int corner) { return model.nodes[gap.nodes[corner]].id; };
  std::vector<std::array<int, 2>> crossed{faces.one};
  if (faces.two[0] != faces.two[1]) crossed.push_back(faces.two);
  const std::vector<std::array<int, 2>> others = other_sides(faces, gap.node_count);
  // Rule (2): an edge another gap element shares is where the gap runs on (an end), not a face; and
  // when the other sides lie on solid elements and a crossed edge does not, those sides are the faces.
  std::string why;
  for (const auto& e : crossed) {
    if (edges.shared(gap, e[0], e[1])) {
      why = "its edge " + std::to_string(id(e[0])) + "-" + std::to_string(id(e[1])) +
            " is also an edge of another gap element, so the gap runs on through it and M runs along the gap";
      break;
    }
  }
  if (why.empty() && faces.two[0] != faces.two[1]) {
    const bool crossed_on_solids = edges.solid(gap, faces.one[0], faces.one[1]) && edges.solid(gap, faces.two[0], faces.two[1]);
    const bool others_on_solids = std::all_of(others.begin(), others.end(), [&](const auto& e) { return edges.solid(gap, e[0], e[1]); });
    if (others_on_solids && !crossed_on_solids) {
      why = "its other sides lie on solid elements and the edges M crosses do not, so M runs along the gap";
    }
  }
  if (runs_across(faces) && why.empty()) return std::nullopt;
  // The faces M should cross: the sides that are not ends, else the thinner pair.
  GapFaces right = long_sides_of(x, gap.node_count, axis(gap.angle_deg));
  if (!why.empty() && gap.node_count == 4) {
    right = quad_faces(x, faces.one == std::array<int, 2>{1, 2}, axis(gap.angle_deg));
  }
  std::ostringstream text;
  text << "angle " << gap.angle_deg << " does not run across gap element " << gap.id << ": ";
  if (why.empty()) {
    text << "no " << (gap.node_count == 4 ? "two opposite edges lie" : "edge lies")
         << " within 30 degrees of perpendicular to M";
  } else {
    text << "M crosses " << faces_text(model, gap, faces) << ", but " << why;
  }
  text << "; the gap's faces are " << faces_text(model, gap, right)
       << ", and M must be within 30 degrees of perpendicular to them: angle " << angle_across(x, right)
       << " (or that plus or minus 180)";
  return text.str();
}

}  // namespace

std::vector<std::optional<std::string>> gap_axis_problems(const Model& model, std::span<const GapElement> gaps) {
  const GapEdges edges(model, gaps);
  std::vector<std::optional<std::string>> out;
  out.reserve(gaps.size());
  for (const GapElement& gap : gaps) out.push_back(axis_problem(model, gap, edges));
  return out;
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
