#include "ring_fit.hpp"

#include <cmath>
#include <numbers>

#include "mesh_builder.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/gaps/gap_closure.hpp"

namespace saasgaps::testing {

std::function<Vec2(double, double)> quarter_annulus(double r0, double r1) {
  return [=](double s, double t) {
    const double r = r0 + s * (r1 - r0), angle = t * std::numbers::pi / 2.0;
    return Vec2(r * std::cos(angle), r * std::sin(angle));
  };
}

Model quarter_ring_fit(AnalysisType analysis, int radial, int hoop, double eccentricity) {
  using F = RingFit;
  Model m;
  m.analysis = analysis;
  m.materials = {isotropic_material(1, F::E, F::nu, F::alpha)};
  const Grid inner = add_grid(m, radial, hoop, quarter_annulus(F::a1, F::b1), 0);
  const Grid outer = add_grid(
      m, radial, hoop,
      [eccentricity](double s, double t) {
        const double bore = F::a2 + eccentricity * F::delta * t;
        return quarter_annulus(bore, F::b2)(s, t);
      },
      0);
  std::vector<int> inner_face, outer_face;
  for (int j = 0; j <= hoop; ++j) {
    inner_face.push_back(inner.at(radial, j));
    outer_face.push_back(outer.at(0, j));
  }
  // (outer_k, outer_k+1, inner_k+1, inner_k) is counter-clockwise.
  add_gap_row(m, outer_face, inner_face, [hoop](int k) { return 90.0 * (k + 0.5) / hoop; });
  fill_temperatures(m, 0.0);
  for (int n : inner.nodes) m.loads.node_temperature[n] = F::dT;
  for (const Grid* ring : {&inner, &outer}) {
    for (int i = 0; i <= radial; ++i) {
      constrain(m, ring->at(i, 0), std::nullopt, 0.0);     // x axis: symmetric in y
      constrain(m, ring->at(i, hoop), 0.0, std::nullopt);  // y axis: symmetric in x
    }
  }
  return m;
}

Model axisymmetric_ring_fit(int radial, double height) {
  using F = RingFit;
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {isotropic_material(1, F::E, F::nu, F::alpha)};
  const auto slab = [height](double r0, double r1) {
    return [=](double s, double t) { return Vec2(r0 + s * (r1 - r0), t * height); };
  };
  const Grid inner = add_grid(m, radial, 1, slab(F::a1, F::b1), 0);
  const Grid outer = add_grid(m, radial, 1, slab(F::a2, F::b2), 0);
  add_gap_row(m, {outer.at(0, 0), outer.at(0, 1)}, {inner.at(radial, 0), inner.at(radial, 1)},
              [](int) { return 0.0; });  // M along r; outer face first: counter-clockwise
  fill_temperatures(m, 0.0);
  for (int n : inner.nodes) m.loads.node_temperature[n] = F::dT;
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) constrain(m, n, std::nullopt, 0.0);
  return m;
}

void assemble_with_gaps_at_floor(const Model& model, StiffnessSystem& system) {
  const SolidMaterials materials(model);
  const MaterialState state = materials.initial();
  system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
  const GapClosure gaps(*model.gaps);
  GapModuli floor;
  floor.tensile = gaps.floor_modulus();
  floor.normal.assign(model.gap_count(), floor.tensile);
  system.assemble_gaps([&](std::size_t g) { return gaps.law(g, floor, model.analysis); });
}

void use_exact_contact(Model& model) {
  model.gaps->method = GapMethod::exact;
  model.gaps->initial_modulus = 100.0;
  model.gaps->tensile_schedule = {20.0, 5.0, 1.0};
}

}  // namespace saasgaps::testing
