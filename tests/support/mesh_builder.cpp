#include "mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace saasgaps::testing {

int max_node_id(const Model& model) {
  int id = 0;
  for (const Node& n : model.nodes) id = std::max(id, n.id);
  return id;
}

int max_element_id(const Model& model) {
  int id = 0;
  for (const Element& e : model.elements) id = std::max(id, e.id);
  if (model.gaps) {
    for (const GapElement& g : model.gaps->elements) id = std::max(id, g.id);
  }
  return id;
}

Grid add_grid(Model& model, int ni, int nj, const std::function<Vec2(double, double)>& map, int material,
              double angle_deg) {
  Grid grid{ni, nj, {}};
  int node_id = max_node_id(model);
  for (int j = 0; j <= nj; ++j) {
    for (int i = 0; i <= ni; ++i) {
      const Vec2 x = map(static_cast<double>(i) / ni, static_cast<double>(j) / nj);
      grid.nodes.push_back(static_cast<int>(model.nodes.size()));
      model.nodes.push_back({++node_id, x.x(), x.y()});
    }
  }
  int element_id = max_element_id(model);
  for (int j = 0; j < nj; ++j) {
    for (int i = 0; i < ni; ++i) {
      Element e;
      e.id = ++element_id;
      e.nodes = {grid.at(i, j), grid.at(i + 1, j), grid.at(i + 1, j + 1), grid.at(i, j + 1)};
      e.node_count = 4;
      e.material = material;
      e.angle_deg = angle_deg;
      model.elements.push_back(e);
    }
  }
  return grid;
}

QuadraticGrid add_quadratic_grid(Model& model, ElementType type, int ni, int nj,
                                 const std::function<Vec2(double, double)>& map, int material,
                                 const std::function<Vec2(int, int)>& offset) {
  const bool quadratic = type == ElementType::tri6 || type == ElementType::quad8 || type == ElementType::quad9;
  const bool centres = type == ElementType::tri6 || type == ElementType::quad9;
  QuadraticGrid grid{ni, nj, {}, {}};
  int node_id = max_node_id(model);
  for (int J = 0; J <= 2 * nj; ++J) {
    for (int I = 0; I <= 2 * ni; ++I) {
      const bool middle = I % 2 == 1 || J % 2 == 1;
      const bool centre = I % 2 == 1 && J % 2 == 1;
      if ((middle && !quadratic) || (centre && !centres)) {
        grid.nodes.push_back(-1);
        continue;
      }
      Vec2 x = map(static_cast<double>(I) / (2 * ni), static_cast<double>(J) / (2 * nj));
      if (offset) x += offset(I, J);
      grid.nodes.push_back(static_cast<int>(model.nodes.size()));
      model.nodes.push_back({++node_id, x.x(), x.y()});
    }
  }
  int element_id = max_element_id(model);
  const auto add = [&](ElementType t, std::initializer_list<int> nodes) {
    Element e;
    e.id = ++element_id;
    e.type = t;
    e.node_count = static_cast<int>(nodes.size());
    std::copy(nodes.begin(), nodes.end(), e.nodes.begin());
    e.material = material;
    model.elements.push_back(e);
    return static_cast<int>(model.elements.size()) - 1;
  };
  for (int j = 0; j < nj; ++j) {
    for (int i = 0; i < ni; ++i) {
      const int I = 2 * i, J = 2 * j;
      const int c0 = grid.at(I, J), c1 = grid.at(I + 2, J), c2 = grid.at(I + 2, J + 2), c3 = grid.at(I, J + 2);
      switch (type) {
        case ElementType::tri6:
          grid.cells.push_back({add(type, {c0, c1, c2, grid.at(I + 1, J), grid.at(I + 2, J + 1), grid.at(I + 1, J + 1)}),
                                add(type, {c0, c2, c3, grid.at(I + 1, J + 1), grid.at(I + 1, J + 2), grid.at(I, J + 1)})});
          break;
        case ElementType::quad8:
          grid.cells.push_back({add(type, {c0, c1, c2, c3, grid.at(I + 1, J), grid.at(I + 2, J + 1), grid.at(I + 1, J + 2),
                                           grid.at(I, J + 1)}),
                                -1});
          break;
        case ElementType::quad9:
          grid.cells.push_back({add(type, {c0, c1, c2, c3, grid.at(I + 1, J), grid.at(I + 2, J + 1), grid.at(I + 1, J + 2),
                                           grid.at(I, J + 1), grid.at(I + 1, J + 1)}),
                                -1});
          break;
        default: grid.cells.push_back({add(type, {c0, c1, c2, c3}), -1}); break;
      }
    }
  }
  return grid;
}

std::vector<ThermalEdge> quadratic_grid_side(const Model& model, const QuadraticGrid& grid, char side) {
  std::vector<ThermalEdge> edges;
  const bool along_i = side == 'b' || side == 't';
  const int n = along_i ? grid.ni : grid.nj;
  for (int k = 0; k < n; ++k) {
    int a = 0, b = 0, cell = 0;
    switch (side) {
      case 'b': a = grid.at(2 * k, 0), b = grid.at(2 * k + 2, 0), cell = k; break;
      case 't': a = grid.at(2 * k, 2 * grid.nj), b = grid.at(2 * k + 2, 2 * grid.nj), cell = k + grid.ni * (grid.nj - 1); break;
      case 'l': a = grid.at(0, 2 * k), b = grid.at(0, 2 * k + 2), cell = grid.ni * k; break;
      default: a = grid.at(2 * grid.ni, 2 * k), b = grid.at(2 * grid.ni, 2 * k + 2), cell = grid.ni - 1 + grid.ni * k; break;
    }
    for (const int e : grid.cells[static_cast<std::size_t>(cell)]) {
      if (e < 0) continue;
      const std::span<const int> nodes = model.elements[static_cast<std::size_t>(e)].node_span();
      const auto corners = nodes.first(nodes.size() == 6 ? 3 : 4);
      if (std::ranges::find(corners, a) != corners.end() && std::ranges::find(corners, b) != corners.end()) {
        edges.push_back({e, a, b});
      }
    }
  }
  return edges;
}

void add_gap_row(Model& model, const std::vector<int>& a, const std::vector<int>& b,
                 const std::function<double(int)>& angle_of) {
  if (!model.gaps) model.gaps.emplace();
  int element_id = max_element_id(model);
  for (std::size_t k = 0; k + 1 < a.size(); ++k) {
    GapElement g;
    g.id = ++element_id;
    g.nodes = {a[k], a[k + 1], b[k + 1], b[k]};
    g.node_count = 4;
    g.angle_deg = angle_of(static_cast<int>(k));
    model.gaps->elements.push_back(g);
  }
}

std::vector<std::array<int, 2>> QuadraticGrid::row_edges(int j) const {
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i < ni; ++i) edges.push_back({corner(i, j), corner(i + 1, j)});
  return edges;
}

std::vector<int> QuadraticGrid::row_nodes(int j) const {
  std::vector<int> row;
  for (int I = 0; I <= 2 * ni; ++I) {
    if (at(I, 2 * j) >= 0) row.push_back(at(I, 2 * j));
  }
  return row;
}

Material isotropic_material(int id, double E, double nu, double alpha) {
  Material m;
  m.id = id;
  m.isotropic = true;
  PropertyRow row;
  row.E1 = row.E2 = row.E3 = E;
  row.nu12 = row.nu13 = row.nu23 = nu;
  row.G12 = E / (2.0 * (1.0 + nu));
  row.alpha1 = row.alpha2 = row.alpha3 = alpha;
  m.table.push_back(row);
  return m;
}

void fill_temperatures(Model& model, double temperature) {
  model.loads.node_temperature.resize(model.nodes.size(), temperature);
}

void constrain(Model& model, int node, std::optional<double> u_r, std::optional<double> u_z) {
  model.constraints.push_back({node, u_r, u_z});
}

Grid add_ring(Model& m, double r0, double r1, int radial, int around, int material) {
  const bool plane = m.analysis != AnalysisType::axisymmetric;
  constexpr double h = 0.2;
  Grid g = add_grid(
      m, radial, around,
      [&](double s, double t) {
        const double r = r0 + (r1 - r0) * s;
        if (!plane) return Vec2(r, h * t);
        const double angle = 2.0 * std::numbers::pi * t;
        return Vec2(r * std::cos(angle), r * std::sin(angle));
      },
      material);
  if (!plane) return g;
  // Close the ring: the last row of nodes (added last) is the first one.
  for (int i = 0; i <= radial; ++i) {
    const int last = g.at(i, around), first = g.at(i, 0);
    for (Element& e : m.elements) std::replace(e.nodes.begin(), e.nodes.end(), last, first);
    g.nodes[static_cast<std::size_t>(i + (radial + 1) * around)] = first;
  }
  m.nodes.resize(m.nodes.size() - static_cast<std::size_t>(radial + 1));
  return g;
}

}  // namespace saasgaps::testing
