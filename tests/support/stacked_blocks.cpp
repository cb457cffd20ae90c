#include "support/stacked_blocks.hpp"

#include <cmath>

#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_kernel.hpp"

namespace saasgaps::testing {

std::vector<std::array<int, 2>> row_edges(const Grid& grid, int j) {
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i < grid.ni; ++i) edges.push_back({grid.at(i, j), grid.at(i + 1, j)});
  return edges;
}

std::vector<std::array<int, 2>> column_edges(const Grid& grid, int i) {
  std::vector<std::array<int, 2>> edges;
  for (int j = 0; j < grid.nj; ++j) edges.push_back({grid.at(i, j), grid.at(i, j + 1)});
  return edges;
}

void add_traction(Model& model, const std::vector<std::array<int, 2>>& edges, const Vec2& traction) {
  const auto position = [&model](int node) {
    const Node& n = model.nodes[static_cast<std::size_t>(node)];
    return Vec2(n.r, n.z);
  };
  for (const auto& e : edges) {
    const auto loads = edge_traction_loads(position(e[0]), position(e[1]), traction, model.analysis, model.thickness);
    for (std::size_t k = 0; k < 2; ++k) model.loads.nodal_forces.push_back({e[k], loads[k].x(), loads[k].y()});
  }
}

StackedBlocks stacked_blocks(AnalysisType analysis, double r0, double width, double height, double gap,
                             BlockFace lower, BlockFace upper, int layers) {
  StackedBlocks b;
  b.model.analysis = analysis;
  b.model.thickness = 0.4;
  b.model.materials = {isotropic_material(1, 1.0e6, 0.3), isotropic_material(2, 3.0e6, 0.2)};
  b.lower = add_grid(
      b.model, lower.segments, layers,
      [&](double s, double t) { return Vec2(r0 + width * std::pow(s, lower.grading), height * t); }, 0);
  b.upper = add_grid(
      b.model, upper.segments, layers,
      [&](double s, double t) {
        return Vec2(r0 + width * std::pow(s, upper.grading), height + gap + height * t);
      },
      1);
  b.lower_top = row_edges(b.lower, layers);
  b.upper_bottom = row_edges(b.upper, 0);
  fill_temperatures(b.model, 0.0);
  return b;
}

}  // namespace saasgaps::testing
