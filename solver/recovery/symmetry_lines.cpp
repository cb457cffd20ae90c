#include "solver/recovery/symmetry_lines.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "solver/model/load_schedule.hpp"
#include "solver/recovery/boundary_edges.hpp"

namespace saasgaps {

namespace {

/// Nodes where a tangential force may act on the line: no mirror there.
void mark_loaded(std::vector<std::uint8_t>& loaded, const Loads& loads, const std::vector<MirrorKind>& kind) {
  for (const NodalForce& f : loads.nodal_forces) {
    const auto n = static_cast<std::size_t>(f.node);
    const double along = kind[n] == MirrorKind::z_line ? f.f_r : f.f_z;
    if (along != 0.0) loaded[n] = 1;
  }
  for (const EdgePressure& p : loads.pressures) {
    if (p.shear == 0.0) continue;
    loaded[static_cast<std::size_t>(p.node_a)] = 1;
    loaded[static_cast<std::size_t>(p.node_b)] = 1;
  }
}

}  // namespace

void mark_contact_nodes(const Model& model, std::vector<std::uint8_t>& marked) {
  if (model.gaps) {
    for (const GapElement& g : model.gaps->elements) {
      for (const int n : g.node_span()) marked[static_cast<std::size_t>(n)] = 1;
    }
  }
  if (model.contact) {
    for (const SurfaceDefinition& s : model.contact->surfaces) {
      for (const auto& [a, b] : s.edges) {
        marked[static_cast<std::size_t>(a)] = 1;
        marked[static_cast<std::size_t>(b)] = 1;
      }
    }
  }
}

bool SymmetryLines::same_line(const Model& model, std::size_t a, std::size_t b) const {
  if (!on_line(a) || kind[a] != kind[b] || value[a] != value[b]) return false;
  const Node& na = model.nodes[a];
  const Node& nb = model.nodes[b];
  return kind[a] == MirrorKind::z_line ? std::abs(na.z - nb.z) <= tolerance : std::abs(na.r - nb.r) <= tolerance;
}

Vec2 SymmetryLines::mirror_point(const Model& model, std::size_t n, const Vec2& x) const {
  assert(on_line(n));
  const Node& at = model.nodes[n];
  return kind[n] == MirrorKind::z_line ? Vec2(x.x(), 2.0 * at.z - x.y()) : Vec2(2.0 * at.r - x.x(), x.y());
}

Vec4 SymmetryLines::mirror_value(std::size_t n, const Vec4& v) const {
  assert(on_line(n));
  return v.cwiseProduct(kind[n] == MirrorKind::z_line ? z_sign : r_sign);
}

SymmetryLines stress_symmetry_lines(const Model& model) {
  SymmetryLines lines;
  const std::size_t count = model.nodes.size();
  if (model.constraints.empty() && model.steps.empty()) return lines;

  const std::vector<double> prescribed = final_prescribed(model);
  lines.kind.assign(count, MirrorKind::none);
  lines.value.assign(count, 0.0);
  double size = 0.0;
  for (const Node& n : model.nodes) size = std::max({size, std::abs(n.r), std::abs(n.z)});
  lines.tolerance = 1e-9 * std::max(size, 1e-300);
  for (std::size_t n = 0; n < count; ++n) {
    const double u_r = prescribed[2 * n], u_z = prescribed[2 * n + 1];
    if (!std::isnan(u_z) && std::isnan(u_r)) {
      lines.kind[n] = MirrorKind::z_line;
      lines.value[n] = u_z;
    } else if (!std::isnan(u_r) && std::isnan(u_z) &&
               (model.analysis != AnalysisType::axisymmetric || std::abs(model.nodes[n].r) <= lines.tolerance)) {
      lines.kind[n] = MirrorKind::r_line;
      lines.value[n] = u_r;
    }
  }

  std::vector<std::uint8_t> loaded(count, 0);
  mark_loaded(loaded, model.loads, lines.kind);
  for (const Step& s : model.steps) {
    if (s.loads) mark_loaded(loaded, *s.loads, lines.kind);
  }
  mark_contact_nodes(model, loaded);
  for (std::size_t n = 0; n < count; ++n) {
    if (loaded[n] != 0) lines.kind[n] = MirrorKind::none;
  }
  return lines;
}

SymmetryLines heat_symmetry_lines(const Model& model) {
  SymmetryLines lines;
  if (!model.thermal) return lines;
  const std::size_t count = model.nodes.size();
  double size = 0.0;
  for (const Node& n : model.nodes) size = std::max({size, std::abs(n.r), std::abs(n.z)});
  lines.tolerance = 1e-9 * std::max(size, 1e-300);
  lines.z_sign = Vec4(1.0, -1.0, 1.0, 1.0);
  lines.r_sign = Vec4(-1.0, 1.0, 1.0, 1.0);

  // The edges with a condition, by element and end corners.
  std::vector<std::array<int, 3>> conditioned;
  for (const ThermalBoundary& b : model.thermal->boundary) {
    for (const ThermalEdge& e : b.edges) conditioned.push_back({e.element, std::min(e.node_a, e.node_b), std::max(e.node_a, e.node_b)});
  }
  std::sort(conditioned.begin(), conditioned.end());
  std::vector<std::uint8_t> contact(count, 0);
  mark_contact_nodes(model, contact);

  // Per node: bit 0 on an insulated z line, bit 1 on an insulated r line; bits 2, 3 the same for
  // conditioned edges.
  constexpr std::uint8_t z_bit = 1, r_bit = 2;
  std::vector<std::uint8_t> on(count, 0);
  const BoundaryEdges boundary = boundary_edges(model);
  for (const EdgeRef& edge : boundary.edge) {
    int n_count = 0;
    const auto nodes = edge_nodes(model, edge, n_count);
    const auto node = [&](int k) { return model.nodes[static_cast<std::size_t>(nodes[static_cast<std::size_t>(k)])]; };
    bool same_z = true, same_r = true;
    for (int k = 1; k < n_count; ++k) {
      same_z = same_z && std::abs(node(k).z - node(0).z) <= lines.tolerance;
      same_r = same_r && std::abs(node(k).r - node(0).r) <= lines.tolerance;
    }
    if (model.analysis == AnalysisType::axisymmetric) same_r = same_r && std::abs(node(0).r) <= lines.tolerance;
    if (!same_z && !same_r) continue;
    const int a = nodes[0], b = nodes[static_cast<std::size_t>(n_count - 1)];
    const std::array<int, 3> key{static_cast<int>(edge.element), std::min(a, b), std::max(a, b)};
    const bool insulated = !std::binary_search(conditioned.begin(), conditioned.end(), key) &&
                           contact[static_cast<std::size_t>(a)] == 0 && contact[static_cast<std::size_t>(b)] == 0;
    const std::uint8_t bits = static_cast<std::uint8_t>((same_z ? z_bit : 0) | (same_r ? r_bit : 0));
    for (int k = 0; k < n_count; ++k) on[static_cast<std::size_t>(nodes[static_cast<std::size_t>(k)])] |= insulated ? bits : static_cast<std::uint8_t>(bits << 2);
  }
  lines.kind.assign(count, MirrorKind::none);
  lines.value.assign(count, 0.0);
  for (std::size_t n = 0; n < count; ++n) {
    // On one kind of insulated line, and no conditioned edge along that kind (a conditioned edge
    // across the line, as at a corner, is mirrored with the rest).
    const bool z = (on[n] & z_bit) != 0 && (on[n] & (z_bit << 2)) == 0;
    const bool r = (on[n] & r_bit) != 0 && (on[n] & (r_bit << 2)) == 0;
    if (z && (on[n] & r_bit) == 0) lines.kind[n] = MirrorKind::z_line;
    if (r && (on[n] & z_bit) == 0) lines.kind[n] = MirrorKind::r_line;
  }
  return lines;
}

}  // namespace saasgaps
