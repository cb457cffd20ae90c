#include "solver/fe/element_family.hpp"

#include <cassert>
#include <vector>

#include <Eigen/Dense>

#include "solver/fe/families/families.hpp"

namespace saasgaps {

namespace {

/// The table: one entry per ElementType, in the enumeration's order (checked below).
const std::array<const ElementFamily*, 6> families{&saas_family,  &tri3_family,  &tri6_family,
                                                   &quad8_family, &quad9_family, &quad4i_family};

/// The polynomial terms that interpolate `count` material points: 1; 1, xi, eta (three points);
/// 1, xi, eta, xi eta (2 x 2); the biquadratic terms (3 x 3).
std::vector<double> terms(int count, double xi, double eta) {
  switch (count) {
    case 1: return {1.0};
    case 3: return {1.0, xi, eta};
    case 4: return {1.0, xi, eta, xi * eta};
    case 9: {
      const double x2 = xi * xi;
      const double e2 = eta * eta;
      return {1.0, xi, eta, xi * eta, x2, e2, x2 * eta, xi * e2, x2 * e2};
    }
    default: assert(false && "material point sets have 1, 3, 4 or 9 points"); return {};
  }
}

struct PointMaps {
  Extrapolation to_nodes;
  std::array<double, max_material_points> to_centre{};
};

/// value(x) = terms(x) . A^-1 values, A the terms at the points.
PointMaps point_maps(const ElementFamily& f, Integration integration) {
  const auto points = f.material_points(integration);
  const int n = static_cast<int>(points.size());
  Eigen::MatrixXd A(n, n);
  for (int p = 0; p < n; ++p) {
    const std::vector<double> t = terms(n, points[static_cast<std::size_t>(p)].xi, points[static_cast<std::size_t>(p)].eta);
    for (int k = 0; k < n; ++k) A(p, k) = t[static_cast<std::size_t>(k)];
  }
  const Eigen::MatrixXd A_inv = A.inverse();
  const auto at = [&](double xi, double eta, std::array<double, max_material_points>& row) {
    const std::vector<double> t = terms(n, xi, eta);
    const Eigen::Map<const Eigen::RowVectorXd> term_row(t.data(), n);
    const Eigen::RowVectorXd weights = term_row * A_inv;
    for (int p = 0; p < n; ++p) row[static_cast<std::size_t>(p)] = weights[p];
  };
  PointMaps m;
  m.to_nodes.nodes = f.node_count;
  m.to_nodes.points = n;
  for (int a = 0; a < f.node_count; ++a) {
    const auto& x = f.node_positions[static_cast<std::size_t>(a)];
    at(x[0], x[1], m.to_nodes.E[static_cast<std::size_t>(a)]);
  }
  const auto c = reference_centre(f.cell);
  at(c[0], c[1], m.to_centre);
  return m;
}

const std::array<std::array<PointMaps, 2>, 6>& all_point_maps() {
  static const std::array<std::array<PointMaps, 2>, 6> maps = [] {
    std::array<std::array<PointMaps, 2>, 6> out{};
    for (std::size_t t = 0; t < families.size(); ++t) {
      assert(static_cast<std::size_t>(families[t]->type) == t && "the table follows ElementType's order");
      out[t][0] = point_maps(*families[t], Integration::full);
      out[t][1] = point_maps(*families[t], Integration::reduced);
    }
    return out;
  }();
  return maps;
}

const PointMaps& maps_of(ElementType type, Integration integration) {
  return all_point_maps()[static_cast<std::size_t>(type)][integration == Integration::full ? 0 : 1];
}

}  // namespace

const ElementFamily& family(ElementType type) { return *families[static_cast<std::size_t>(type)]; }

std::optional<ElementType> default_element_type(int node_count) {
  switch (node_count) {
    case 3: return ElementType::tri3;
    case 4: return ElementType::saas;
    case 6: return ElementType::tri6;
    case 8: return ElementType::quad8;
    case 9: return ElementType::quad9;
    default: return std::nullopt;
  }
}

std::optional<ElementType> element_type_of_gmsh(int gmsh_type) {
  // saas before quad4i: a Gmsh quadrangle is the report's element unless asked otherwise.
  for (const ElementFamily* f : families) {
    if (f->gmsh_type == gmsh_type) return f->type;
  }
  return std::nullopt;
}

const Extrapolation& extrapolation(ElementType type, Integration integration) {
  return maps_of(type, integration).to_nodes;
}

std::span<const double> centre_weights(ElementType type, Integration integration) {
  const PointMaps& m = maps_of(type, integration);
  return std::span<const double>(m.to_centre).first(static_cast<std::size_t>(m.to_nodes.points));
}

std::array<double, 2> reference_centre(CellShape shape) {
  return shape == CellShape::triangle ? std::array<double, 2>{1.0 / 3.0, 1.0 / 3.0} : std::array<double, 2>{0.0, 0.0};
}

}  // namespace saasgaps
