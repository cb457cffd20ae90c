// Our own closed-form check of the gap iteration: two concentric steel rings, the inner one heated
// across a small radial gap into the outer one (support/lame_rings.hpp states Lame's solution). The
// gaps' normal stress must be within 2 % of -p and every gap's closure within the tolerance, both in
// axisymmetry (a slice of the rings held in z) and in plane strain (a quarter annulus, gap elements
// at many angles).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis.hpp"
#include "support/lame_rings.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

using namespace testing::lame_rings;  // E, nu, alpha, dT and the radii

void set_gaps(Model& m, double xfact) {
  m.gaps->initial_modulus = 100.0;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
  m.gaps->extrapolation_factor = xfact;
  m.solver.max_iterations = 40;
}

void heat_inner_ring(Model& m, const testing::Grid& inner) {
  testing::fill_temperatures(m, 0.0);
  for (int n : inner.nodes) m.loads.node_temperature[n] = dT;
}

Model axisymmetric_rings(int radial_elements) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {testing::isotropic_material(1, E, nu, alpha)};
  const double h = 0.05;
  const auto slab = [h](double r0, double r1) { return [=](double s, double t) { return Vec2(r0 + s * (r1 - r0), t * h); }; };
  const testing::Grid inner = testing::add_grid(m, radial_elements, 1, slab(a1, b1), 0);
  const testing::Grid outer = testing::add_grid(m, radial_elements, 1, slab(a2, b2), 0);
  m.gaps.emplace();
  GapElement g;
  g.id = 1000;
  g.nodes = {inner.at(radial_elements, 0), outer.at(0, 0), outer.at(0, 1), inner.at(radial_elements, 1)};
  g.angle_deg = 0.0;  // M along r
  m.gaps->elements.push_back(g);
  set_gaps(m, 0.0);
  heat_inner_ring(m, inner);
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) testing::constrain(m, n, std::nullopt, 0.0);
  return m;
}

Model quarter_annulus_rings(int radial_elements, int hoop_elements, double xfact) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, E, nu, alpha)};
  const auto annulus = [](double r0, double r1) {
    return [=](double s, double t) {
      const double r = r0 + s * (r1 - r0), angle = t * std::numbers::pi / 2.0;
      return Vec2(r * std::cos(angle), r * std::sin(angle));
    };
  };
  const testing::Grid inner = testing::add_grid(m, radial_elements, hoop_elements, annulus(a1, b1), 0);
  const testing::Grid outer = testing::add_grid(m, radial_elements, hoop_elements, annulus(a2, b2), 0);
  m.gaps.emplace();
  int id = 1000;
  for (int j = 0; j < hoop_elements; ++j) {
    GapElement g;
    g.id = ++id;
    g.nodes = {inner.at(radial_elements, j), outer.at(0, j), outer.at(0, j + 1), inner.at(radial_elements, j + 1)};
    g.angle_deg = 90.0 * (j + 0.5) / hoop_elements;  // M radial, at the element's mid angle
    m.gaps->elements.push_back(g);
  }
  set_gaps(m, xfact);
  heat_inner_ring(m, inner);
  for (const testing::Grid* ring : {&inner, &outer}) {
    for (int i = 0; i <= radial_elements; ++i) {
      testing::constrain(m, ring->at(i, 0), std::nullopt, 0.0);              // x axis: symmetric in y
      testing::constrain(m, ring->at(i, hoop_elements), 0.0, std::nullopt);  // y axis: symmetric in x
    }
  }
  return m;
}

TEST(RingContact, AxisymmetricContactPressureMatchesLame) {
  const Model m = axisymmetric_rings(12);
  expect_contact(m, solve(m));
}

TEST(RingContact, PlaneStrainQuarterAnnulusWithGapsAtManyAngles) {
  const Model m = quarter_annulus_rings(8, 24, 0.0);
  expect_contact(m, solve(m));
}

TEST(RingContact, ExtrapolationReachesTheSameContactSooner) {
  const Model plain = quarter_annulus_rings(8, 24, 0.0);
  const Model extrapolating = quarter_annulus_rings(8, 24, 0.5);
  const Solution without = solve(plain);
  const Solution with = solve(extrapolating);
  expect_contact(extrapolating, with);
  bool used = false;
  for (const IterationRecord& row : with.history) used = used || row.extrapolated;
  EXPECT_TRUE(used);
  EXPECT_LE(with.iterations, without.iterations);
}

}  // namespace
}  // namespace saasgaps
