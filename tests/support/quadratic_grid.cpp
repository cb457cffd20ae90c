#include "support/quadratic_grid.hpp"

#include <cassert>

#include "support/mesh_builder.hpp"

namespace saasgaps::testing {

QuadraticGrid add_quadratic_grid(Model& model, int ni, int nj, const std::function<Vec2(double, double)>& map,
                                 int material, ElementType type) {
  assert(type == ElementType::quad8 || type == ElementType::quad9);
  QuadraticGrid grid{ni, nj, {}};
  int node_id = max_node_id(model);
  for (int j = 0; j <= 2 * nj; ++j) {
    for (int i = 0; i <= 2 * ni; ++i) {
      // quad8 has no node where both lattice indices are odd (an element's centre).
      if (type == ElementType::quad8 && i % 2 == 1 && j % 2 == 1) {
        grid.nodes.push_back(-1);
        continue;
      }
      const Vec2 x = map(static_cast<double>(i) / (2 * ni), static_cast<double>(j) / (2 * nj));
      grid.nodes.push_back(static_cast<int>(model.nodes.size()));
      model.nodes.push_back({++node_id, x.x(), x.y()});
    }
  }
  int element_id = max_element_id(model);
  for (int j = 0; j < nj; ++j) {
    for (int i = 0; i < ni; ++i) {
      const int I = 2 * i;
      const int J = 2 * j;
      Element e;
      e.id = ++element_id;
      e.type = type;
      e.node_count = type == ElementType::quad8 ? 8 : 9;
      // Corners counter-clockwise, then mid-sides of edges 1-2, 2-3, 3-4, 4-1, then the centre.
      e.nodes = {grid.at(I, J),         grid.at(I + 2, J),     grid.at(I + 2, J + 2),
                 grid.at(I, J + 2),     grid.at(I + 1, J),     grid.at(I + 2, J + 1),
                 grid.at(I + 1, J + 2), grid.at(I, J + 1),     grid.at(I + 1, J + 1)};
      if (type == ElementType::quad8) e.nodes[8] = -1;
      e.material = material;
      model.elements.push_back(e);
    }
  }
  return grid;
}

}  // namespace saasgaps::testing
