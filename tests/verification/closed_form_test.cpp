// Closed forms for the parts of SAAS III the report's tables do not exercise: tension/compression
// (bimodulus) properties, the bilinear secant-modulus plasticity, shear tractions on edges, and the
// body force of a spinning disk.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/analysis/analysis.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

/// A 4 x 2 plane-stress block [0, 2] x [0, 1] of the given material, at the reference temperature.
Model block(const Material& material) {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {material};
  testing::add_grid(m, 4, 2, [](double s, double t) { return Vec2(2.0 * s, t); }, 0);
  testing::fill_temperatures(m, 0.0);
  return m;
}

/// Node index of grid point (i, j) of block().
int at(int i, int j) { return i + 5 * j; }

TEST(ClosedForm, BimodulusMaterialUsesItsCompressionModulusWhereCompressed) {
  Material m = testing::isotropic_material(1, 10.0e6, 0.3);
  m.compression_table = testing::isotropic_material(1, 30.0e6, 0.2).table;
  for (const double stress : {-3000.0, 3000.0}) {
    Model model = block(m);
    // Uniaxial sigma_z: the bottom on rollers, one corner pinned, the top pressed (or pulled).
    for (int i = 0; i <= 4; ++i) testing::constrain(model, at(i, 0), i == 0 ? std::optional(0.0) : std::nullopt, 0.0);
    for (int i = 0; i < 4; ++i) model.loads.pressures.push_back({4 + i, at(i, 2), at(i + 1, 2), -stress, 0.0});
    const Solution s = solve(model);
    ASSERT_EQ(s.status, RunStatus::converged);
    // Compressed along z: E2 from the compression table, nu12 with E1 from the tension table
    // (S_12 = -nu12 / E1 keeps the compliance symmetric). In tension, the tension table alone.
    const double E_z = stress < 0.0 ? 30.0e6 : 10.0e6;
    EXPECT_EQ(s.iterations, stress < 0.0 ? 2 : 1);
    for (const ElementResult& e : s.elements) {
      EXPECT_NEAR(e.stress[zz], stress, 1e-6 * std::abs(stress));
      EXPECT_NEAR(e.strain[zz], stress / E_z, 1e-12);
      EXPECT_NEAR(e.strain[rr], -0.3 * stress / 10.0e6, 1e-12);
    }
  }
}

TEST(ClosedForm, SecantPlasticityFollowsTheBilinearCurve) {
  // A bar pulled to twice its yield strain: sigma = sigma_y + PEMR E (eps - eps_y), and the lateral
  // strain follows the secant Poisson ratio nu_s = 1/2 - (1/2 - nu) E_s / E.
  const double E = 30.0e6, nu = 0.3, yield = 30000.0, pemr = 0.25;
  Material m = testing::isotropic_material(1, E, nu);
  m.plasticity = {{0.0, yield, pemr}};
  Model model = block(m);
  model.solver.plastic_tolerance = 1e-9;
  const double eps = 2.0 * yield / E;
  for (int j = 0; j <= 2; ++j) {
    testing::constrain(model, at(0, j), 0.0, j == 0 ? std::optional(0.0) : std::nullopt);
    testing::constrain(model, at(4, j), eps * 2.0, std::nullopt);
  }
  const Solution s = solve(model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const double sigma = yield + pemr * E * (eps - yield / E);
  const double nu_secant = 0.5 - (0.5 - nu) * (sigma / eps) / E;
  for (const ElementResult& e : s.elements) {
    EXPECT_NEAR(e.stress[rr], sigma, 1e-6 * sigma);
    EXPECT_NEAR(e.strain[zz], -nu_secant * eps, 1e-12);
    EXPECT_TRUE(e.yielded);
    EXPECT_TRUE(e.plastic_converged);
  }
  EXPECT_EQ(s.history.back().yielded_elements, 8);
}

TEST(ClosedForm, ShearTractionsOnTheEdgesGivePureShear) {
  // Shear tau on the top (along +r) and on both sides (up on the right, down on the left), the
  // bottom held: simple shear u_r = tau z / G, so sigma_rz = tau and nothing else, exactly.
  const double tau = 500.0, G = 10.0e6 / 2.6;
  Model model = block(testing::isotropic_material(1, 10.0e6, 0.3));
  for (int i = 0; i <= 4; ++i) testing::constrain(model, at(i, 0), 0.0, 0.0);
  for (int i = 0; i < 4; ++i) model.loads.pressures.push_back({4 + i, at(i, 2), at(i + 1, 2), 0.0, tau});
  for (int j = 0; j < 2; ++j) {
    model.loads.pressures.push_back({4 * j + 3, at(4, j), at(4, j + 1), 0.0, tau});  // right edge, upward
    model.loads.pressures.push_back({4 * j, at(0, j + 1), at(0, j), 0.0, tau});      // left edge, downward
  }
  const Solution s = solve(model);
  for (const ElementResult& e : s.elements) {
    EXPECT_NEAR(e.stress[rz], tau, 1e-9 * tau);
    EXPECT_NEAR(e.stress[rr], 0.0, 1e-9 * tau);
    EXPECT_NEAR(e.stress[zz], 0.0, 1e-9 * tau);
  }
  EXPECT_NEAR(s.nodes[at(4, 2)].u_r, tau / G, 1e-15);
  EXPECT_NEAR(s.nodes[at(4, 2)].u_z, 0.0, 1e-15);
}

TEST(ClosedForm, SpinningThinDiskMatchesThePlaneStressSolution) {
  // A thin solid disk of radius b spinning at omega: sigma_r = (3 + nu)/8 rho omega^2 (b^2 - r^2),
  // sigma_theta = rho omega^2 ((3 + nu) b^2 - (1 + 3 nu) r^2) / 8. Half its thickness, held on the
  // mid-plane (z = 0) and on the axis (u_r = 0).
  const double b = 1.0, half_thickness = 0.02, rho = 7.3e-4, omega = 2000.0, nu = 0.3;
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  Material steel = testing::isotropic_material(1, 30.0e6, nu);
  steel.density = rho;
  m.materials = {steel};
  const int radial = 40;
  const testing::Grid g =
      testing::add_grid(m, radial, 1, [&](double s, double t) { return Vec2(b * s, half_thickness * t); }, 0);
  testing::fill_temperatures(m, 0.0);
  m.loads.body_force.omega = omega;
  for (int i = 0; i <= radial; ++i) testing::constrain(m, g.at(i, 0), i == 0 ? std::optional(0.0) : std::nullopt, 0.0);
  testing::constrain(m, g.at(0, 1), 0.0, std::nullopt);
  const Solution s = solve(m);
  const double scale = (3.0 + nu) / 8.0 * rho * omega * omega * b * b;  // sigma_r at the centre
  for (int e = 2; e < radial - 1; ++e) {
    const double r = b * (e + 0.5) / radial;
    const double sigma_r = (3.0 + nu) / 8.0 * rho * omega * omega * (b * b - r * r);
    const double sigma_theta = rho * omega * omega * ((3.0 + nu) * b * b - (1.0 + 3.0 * nu) * r * r) / 8.0;
    EXPECT_NEAR(s.elements[e].stress[rr], sigma_r, 0.01 * scale) << "r = " << r;
    EXPECT_NEAR(s.elements[e].stress[th], sigma_theta, 0.01 * scale) << "r = " << r;
  }
}

}  // namespace
}  // namespace saasgaps
