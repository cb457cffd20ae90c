#include "shrink_fit_rings.hpp"

#include <cmath>
#include <numbers>

#include "lame_rings.hpp"
#include "mesh_builder.hpp"
#include "stacked_blocks.hpp"

namespace saasgaps::testing::shrink_fit_rings {

double lame_interference_pressure(AnalysisType type) {
  // Plane strain and the axisymmetric slice held in z share lame_rings' plane-strain closed form.
  const lame_rings::RingPair rings{a1, b, b2, E1, nu1, E2, nu2};
  return type == AnalysisType::plane_stress ? lame_rings::plane_stress_interference_pressure(rings, delta)
                                            : lame_rings::plane_strain_interference_pressure(rings, delta);
}

Model shrink_fit(AnalysisType type, int radial, std::array<int, 2> around) {
  Model m;
  m.analysis = type;
  m.materials = {isotropic_material(1, E1, nu1), isotropic_material(2, E2, nu2)};
  const Grid inner = add_ring(m, a1, b + 0.5 * delta, radial, around[0], 0);
  const Grid outer = add_ring(m, b - 0.5 * delta, b2, radial, around[1], 1);
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"shaft", column_edges(inner, radial)}, {"hub", column_edges(outer, 0)}};
  contact.pairs.emplace_back().surfaces = {0, 1};
  for (const Grid* g : {&inner, &outer}) {
    if (type == AnalysisType::axisymmetric) {
      for (const int n : g->nodes) constrain(m, n, std::nullopt, 0.0);
      continue;
    }
    constrain(m, g->at(0, 0), std::nullopt, 0.0);
    constrain(m, g->at(0, g->nj / 2), std::nullopt, 0.0);
    constrain(m, g->at(0, g->nj / 4), 0.0, std::nullopt);
  }
  fill_temperatures(m, 0.0);
  return m;
}

Model quarter_shrink_fit(int radial, std::array<int, 2> around, double eccentricity, ElementType type) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {isotropic_material(1, E1, nu1), isotropic_material(2, E2, nu2)};
  const auto annulus = [](double r0, double r1, double bore_shift) {
    return [=](double s, double t) {
      const double bore = r0 + bore_shift * t;
      const double r = bore + s * (r1 - bore), angle = t * std::numbers::pi / 2.0;
      return Vec2(r * std::cos(angle), r * std::sin(angle));
    };
  };
  // Grid i runs radially, j round the quarter (counter-clockwise elements).
  const QuadraticGrid shaft = add_quadratic_grid(m, type, radial, around[0], annulus(a1, b + 0.5 * delta, 0.0), 0);
  const QuadraticGrid hub =
      add_quadratic_grid(m, type, radial, around[1], annulus(b - 0.5 * delta, b2, eccentricity * delta), 1);
  const auto column = [](const QuadraticGrid& g, int i) {
    std::vector<std::array<int, 2>> edges;
    for (int j = 0; j < g.nj; ++j) edges.push_back({g.corner(i, j), g.corner(i, j + 1)});
    return edges;
  };
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"shaft", column(shaft, radial)}, {"hub", column(hub, 0)}};
  contact.pairs.emplace_back().surfaces = {0, 1};
  for (const QuadraticGrid* g : {&shaft, &hub}) {
    for (const int n : g->row_nodes(0)) constrain(m, n, std::nullopt, 0.0);      // on the x axis: u_y = 0
    for (const int n : g->row_nodes(g->nj)) constrain(m, n, 0.0, std::nullopt);  // on the y axis: u_x = 0
  }
  fill_temperatures(m, 0.0);
  return m;
}

}  // namespace saasgaps::testing::shrink_fit_rings
