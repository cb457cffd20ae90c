#include "solver/recovery/symmetry_lines.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "solver/model/load_schedule.hpp"

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

}  // namespace saasgaps
