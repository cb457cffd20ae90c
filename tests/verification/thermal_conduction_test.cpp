// Heat conduction through the whole thermal path (ThermalSystem, the k(T) iteration, time
// stepping) against closed forms derived here.
//
// Patch tests. A linear T = a + b r + c z solves div(k grad T) = 0 for a constant tensor k (plane).
// On a straight boundary edge with outward normal n the heat flowing in is -q.n = (k grad T).n, a
// constant per edge: each edge gets its own flux entry. One side is laid along an isotherm and
// held at its temperature. The element space holds the field, so the interior nodes of a distorted
// mesh must reproduce it to round-off. Axisymmetric: T = a + c z with k_rz = 0 (q constant, q_r = 0).
//
// Solid cylinder (axisymmetric), radius R, uniform source s, film h to ambient T_a on r = R, ends
// insulated: (1/r) d/dr (r k dT/dr) = -s with T finite at r = 0 gives T = T_R + s (R^2 - r^2) / (4 k);
// the heat made, s pi R^2 per length, leaves through the film, h 2 pi R (T_R - T_a), so
// T_R = T_a + s R / (2 h).
//
// Slab suddenly held at a surface temperature: 0 < x < L, T = T_i at t = 0, T(0, t) = T_s for t > 0,
// x = L insulated. Separation of variables with X(0) = 0, X'(L) = 0 gives
// theta = (T - T_s) / (T_i - T_s) = sum_n 4 / ((2n+1) pi) sin(lambda_n x) exp(-lambda_n^2 alpha t),
// lambda_n = (2n+1) pi / (2 L), alpha = k / (density c) (the coefficients are the sine series of 1).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/thermal/conduction_kernel.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/mesh_builder.hpp"
#include "support/settling_transient.hpp"
#include "support/state_recorder.hpp"

namespace saasgaps {
namespace {

using std::numbers::pi;

Material conductor(double k, double density = 0.0, double c = 0.0) {
  Material m = testing::isotropic_material(1, 1.0e6, 0.3);
  m.table[0].k1 = m.table[0].k2 = m.table[0].k3 = k;
  m.table[0].c = c;
  m.density = density;
  m.conducts = true;
  m.stores_heat = c > 0.0;
  return m;
}

/// The edges of grid side j = const (i = 0..ni) or i = const, as thermal edges of their elements.
std::vector<ThermalEdge> side(const Model& m, const testing::Grid& g, bool along_i, int fixed) {
  std::vector<ThermalEdge> edges;
  const int n = along_i ? g.ni : g.nj;
  for (int k = 0; k < n; ++k) {
    const int a = along_i ? g.at(k, fixed) : g.at(fixed, k);
    const int b = along_i ? g.at(k + 1, fixed) : g.at(fixed, k + 1);
    for (std::size_t e = 0; e < m.elements.size(); ++e) {
      const std::span<const int> nodes = m.elements[e].node_span();
      const bool has_a = std::find(nodes.begin(), nodes.end(), a) != nodes.end();
      const bool has_b = std::find(nodes.begin(), nodes.end(), b) != nodes.end();
      if (has_a && has_b) edges.push_back({static_cast<int>(e), a, b});
    }
  }
  return edges;
}

/// Every edge of `edges` as its own flux entry: the inflow (k grad T).n of the linear field.
void add_fluxes(Model& m, const std::vector<ThermalEdge>& edges, const Eigen::Matrix2d& k, const Vec2& gradient) {
  for (const ThermalEdge& e : edges) {
    const Node& a = m.nodes[static_cast<std::size_t>(e.node_a)];
    const Node& b = m.nodes[static_cast<std::size_t>(e.node_b)];
    // The element lies to the left of a -> b (counter-clockwise) or to its right; n points away from it.
    const Element& el = m.elements[static_cast<std::size_t>(e.element)];
    Vec2 centre = Vec2::Zero();
    for (int c = 0; c < el.node_count; ++c) centre += Vec2(m.nodes[el.nodes[c]].r, m.nodes[el.nodes[c]].z);
    centre /= el.node_count;
    const Vec2 t(b.r - a.r, b.z - a.z);
    Vec2 n(t.y(), -t.x());
    n.normalize();
    if (n.dot(centre - Vec2(a.r, a.z)) > 0.0) n = -n;
    ThermalBoundary flux;
    flux.kind = ThermalBoundary::Kind::flux;
    flux.edges = {e};
    flux.value = (k * gradient).dot(n);
    m.thermal->boundary.push_back(flux);
  }
}

/// A 4 x 3 patch: r in [1, 3], the top side from (1, 1.5) down to (3, 1.5 - 2 slope), interior
/// nodes pushed off the grid.
Model distorted_patch(AnalysisType analysis, double slope, const Conductivity& k, testing::Grid& g) {
  Model m;
  m.analysis = analysis;
  m.thickness = 0.4;
  m.materials = {conductor(k.k1)};
  m.materials[0].table[0].k2 = k.k2;
  g = testing::add_grid(
      m, 4, 3, [slope](double s, double t) { return Vec2(1.0 + 2.0 * s, t * (1.5 - 2.0 * slope * s)); }, 0, k.angle_deg);
  for (int j = 1; j < 3; ++j) {
    for (int i = 1; i < 4; ++i) {
      Node& n = m.nodes[g.at(i, j)];
      n.r += 0.09 * std::sin(3.0 * i + j);
      n.z += 0.08 * std::cos(2.0 * i - j);
    }
  }
  m.thermal.emplace();
  return m;
}

void expect_patch_reproduced(AnalysisType analysis, const Conductivity& k, double T0, const Vec2& gradient) {
  // The top side runs along an isotherm: its direction (1, -slope) is perpendicular to the gradient.
  const double slope = gradient.x() / gradient.y();
  testing::Grid g;
  Model m = distorted_patch(analysis, slope, k, g);
  const auto field = [&](const Node& n) { return T0 + gradient.dot(Vec2(n.r, n.z)); };
  ThermalBoundary top;
  top.kind = ThermalBoundary::Kind::temperature;
  top.edges = side(m, g, true, 3);
  top.value = field(m.nodes[g.at(0, 3)]);
  m.thermal->boundary.push_back(top);
  const Eigen::Matrix2d tensor = k.tensor();
  add_fluxes(m, side(m, g, true, 0), tensor, gradient);
  add_fluxes(m, side(m, g, false, 0), tensor, gradient);
  add_fluxes(m, side(m, g, false, 4), tensor, gradient);
  const ThermalResult r = solve_steady_conduction(m);
  EXPECT_EQ(r.iterations, 1);  // a constant k: one solve
  for (const Node& n : m.nodes) EXPECT_NEAR(r.T[n.id - 1], field(n), 1e-10) << "node " << n.id;
  // The element flux is -k grad T everywhere.
  for (const Vec2& q : r.flux) {
    EXPECT_NEAR(q.x(), -(tensor * gradient).x(), 1e-9);
    EXPECT_NEAR(q.y(), -(tensor * gradient).y(), 1e-9);
  }
}

TEST(ThermalPatch, PlaneDistortedMeshReproducesALinearField) {
  expect_patch_reproduced(AnalysisType::plane_stress, {2.0, 2.0, 0.0}, 20.0, Vec2(30.0, 60.0));
  expect_patch_reproduced(AnalysisType::plane_strain, {3.0, 0.4, 33.0}, -5.0, Vec2(-20.0, 50.0));
}

TEST(ThermalPatch, AxisymmetricDistortedMeshReproducesAnAxialField) {
  // slope 0: the top side is horizontal, an isotherm of T = a + c z.
  expect_patch_reproduced(AnalysisType::axisymmetric, {1.5, 1.5, 0.0}, 80.0, Vec2(0.0, -60.0));
  expect_patch_reproduced(AnalysisType::axisymmetric, {0.3, 2.5, 90.0}, 10.0, Vec2(0.0, 70.0));
}

/// The solid cylinder of the header on ni radial elements (r = R (i / ni)), one layer of height 0.1.
struct Cylinder {
  double R = 2.0, k = 3.0, s = 5.0, h = 4.0, ambient = 70.0;
  [[nodiscard]] double exact(double r) const { return ambient + s * R / (2.0 * h) + s * (R * R - r * r) / (4.0 * k); }
};

Model cylinder_model(const Cylinder& c, int ni) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {conductor(c.k)};
  const testing::Grid g =
      testing::add_grid(m, ni, 1, [&c](double s, double t) { return Vec2(c.R * s, 0.1 * t); }, 0);
  m.thermal.emplace();
  ThermalBoundary film;
  film.kind = ThermalBoundary::Kind::film;
  film.edges = side(m, g, false, ni);
  film.value = c.h;
  film.ambient = c.ambient;
  m.thermal->boundary.push_back(film);
  m.thermal->sources.push_back({0, c.s});
  return m;
}

/// The largest nodal error of (T - ambient), relative to the largest rise.
double cylinder_error(const Cylinder& c, int ni) {
  const Model m = cylinder_model(c, ni);
  const ThermalResult r = solve_steady_conduction(m);
  double worst = 0.0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) worst = std::max(worst, std::abs(r.T[n] - c.exact(m.nodes[n].r)));
  return worst / (c.exact(0.0) - c.ambient);
}

TEST(ThermalClosedForm, SolidCylinderWithSourceAndFilmHasAParabolicProfile) {
  const Cylinder c;
  EXPECT_LT(cylinder_error(c, 10), 0.005);
}

TEST(ThermalClosedForm, SteadyErrorFallsWithTheSquareOfTheMeshSize) {
  const Cylinder c;
  const double coarse = cylinder_error(c, 4);
  const double fine = cylinder_error(c, 8);
  const double finer = cylinder_error(c, 16);
  // Order p from e ~ h^p between successive halvings.
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.2) << coarse << " " << fine;
  EXPECT_NEAR(std::log2(fine / finer), 2.0, 0.2) << fine << " " << finer;
}

double slab_theta(double x, double t, double L, double alpha) {
  double sum = 0.0;
  for (int n = 0; n < 200; ++n) {
    const double lambda = (2 * n + 1) * pi / (2.0 * L);
    sum += 4.0 / ((2 * n + 1) * pi) * std::sin(lambda * x) * std::exp(-lambda * lambda * alpha * t);
  }
  return sum;
}

TEST(ThermalClosedForm, SlabSuddenlyHeldAtASurfaceTemperatureFollowsTheFourierSeries) {
  // L = 1, alpha = k / (density c) = 2 / (4 x 0.5) = 1; 40 elements, time step 0.0005.
  const double L = 1.0, Ti = 70.0, Ts = 1000.0;
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {conductor(2.0, 4.0, 0.5)};
  const testing::Grid g = testing::add_grid(m, 40, 1, [L](double s, double t) { return Vec2(L * s, 0.05 * t); }, 0);
  m.thermal.emplace();
  m.thermal->type = ThermalType::transient;
  ThermalBoundary surface;
  surface.kind = ThermalBoundary::Kind::temperature;
  surface.edges = side(m, g, false, 0);
  surface.value = Ts;
  m.thermal->boundary.push_back(surface);
  m.thermal->initial_temperature = Ti;
  m.thermal->time_step = 0.0005;
  m.thermal->end_time = 0.5;
  m.thermal->output_times = {0.02, 0.05, 0.1, 0.2, 0.5};
  const ThermalResult r = solve_transient_conduction(m);
  ASSERT_EQ(r.history.size(), 5u);
  EXPECT_EQ(r.time_steps, 1000);
  EXPECT_EQ(r.factorizations, 1);  // constant k, c and step: one factorization for every step
  for (std::size_t k = 0; k < r.times.size(); ++k) {
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      const double exact = Ts + (Ti - Ts) * slab_theta(m.nodes[n].r, r.times[k], L, 1.0);
      EXPECT_NEAR(r.history[k][n], exact, 0.01 * (Ts - Ti)) << "t = " << r.times[k] << ", r = " << m.nodes[n].r;
    }
  }
}

TEST(ThermalTransient, AStepThatDoesNotDivideTheOutputTimesLandsOnEachExactly) {
  Model m = cylinder_model(Cylinder{}, 4);
  m.materials[0].table[0].c = 1.0;
  m.materials[0].density = 1.0;
  m.thermal->type = ThermalType::transient;
  m.thermal->initial_temperature = 70.0;
  m.thermal->time_step = 0.3;
  m.thermal->end_time = 1.0;
  m.thermal->output_times = {0.7, 1.0};
  const ThermalResult r = solve_transient_conduction(m);
  EXPECT_EQ(r.times, (std::vector<double>{0.7, 1.0}));
  // 0.3, 0.6, 0.7 (shortened), 1.0: four steps; the short one needs its own factorization, and the
  // step after it the first one's again.
  EXPECT_EQ(r.time_steps, 4);
  EXPECT_EQ(r.factorizations, 3);
}

TEST(ThermalSteady, TemperatureDependentConductivityIsIteratedToConvergence) {
  // A plane wall 0 < x < 1 between T(0) = 100 and T(1) = 300 with k = k0 (1 + beta T): the Kirchhoff
  // transform u = T + beta T^2 / 2 is linear in x, so T(x) solves T + beta T^2 / 2 = u0 + (u1 - u0) x.
  Model m;
  m.analysis = AnalysisType::plane_stress;
  Material mat = conductor(1.0);
  const double beta = 0.004;
  PropertyRow hot = mat.table[0];
  mat.table[0].T = 0.0;
  hot.T = 1000.0;
  hot.k1 = hot.k2 = hot.k3 = 1.0 + beta * 1000.0;
  mat.table.push_back(hot);
  m.materials = {mat};
  const testing::Grid g = testing::add_grid(m, 40, 1, [](double s, double t) { return Vec2(s, 0.05 * t); }, 0);
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, g, false, 0), 100.0, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, g, false, 40), 300.0, 0.0});
  const ThermalResult r = solve_steady_conduction(m);
  EXPECT_GT(r.iterations, 2);
  EXPECT_LE(r.iterations, max_conduction_iterations);
  const auto u = [beta](double T) { return T + 0.5 * beta * T * T; };
  for (const Node& n : m.nodes) {
    const double target = u(100.0) + (u(300.0) - u(100.0)) * n.r;
    const double exact = (-1.0 + std::sqrt(1.0 + 2.0 * beta * target)) / beta;
    EXPECT_NEAR(r.T[n.id - 1], exact, 0.002 * 200.0) << "x = " << n.r;
  }
}

TEST(ThermalSteady, ABodyWithNothingHoldingItsTemperatureIsASingularModel) {
  Model m = cylinder_model(Cylinder{}, 4);
  m.thermal->boundary[0].kind = ThermalBoundary::Kind::flux;
  EXPECT_THROW((void)solve_steady_conduction(m), SingularModelError);
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

// A free plane-stress strip 0 < x < L, 0 < y < H with T(0) = T0, T(L) = T1 computed by conduction
// (k constant, insulated top and bottom: T linear in x, reproduced exactly). The stress analysis
// must get these temperatures exactly as given ones: the run equals the same model solved with
// loads.temperatures set to the closed form. Along y = 0 the strip stretches freely, eps_x = alpha T
// (the SAAS elements take each element's mean temperature, exact for the mean strain of a linear
// field), so u_x(L, 0) = alpha integral_0^L T dx = alpha L (T0 + T1) / 2 with u(0, 0) = 0 and
// u_y(L, 0) = 0 holding it.
TEST(ThermalStress, ALinearTemperatureComputedByConductionLeavesAFreeStripStressFree) {
  const double L = 2.0, H = 0.5, T0 = 100.0, T1 = 300.0, alpha = 1.0e-5, k = 4.0;
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {conductor(k)};
  m.materials[0].table[0].alpha1 = m.materials[0].table[0].alpha2 = m.materials[0].table[0].alpha3 = alpha;
  const testing::Grid g = testing::add_grid(m, 8, 2, [&](double s, double t) { return Vec2(L * s, H * t); }, 0);
  testing::constrain(m, g.at(0, 0), 0.0, 0.0);
  testing::constrain(m, g.at(8, 0), std::nullopt, 0.0);
  testing::fill_temperatures(m, 0.0);
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, g, false, 0), T0, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, g, false, 8), T1, 0.0});
  const Solution s = solve_with_heat(m);
  ASSERT_TRUE(s.thermal.has_value());
  EXPECT_EQ(s.status, RunStatus::converged);
  for (const Node& n : m.nodes) EXPECT_NEAR(s.thermal->T[n.id - 1], T0 + (T1 - T0) * n.r / L, 1e-9);
  for (const Vec2& q : s.thermal->flux) EXPECT_NEAR(q.x(), -k * (T1 - T0) / L, 1e-9);
  EXPECT_NEAR(s.nodes[g.at(8, 0)].u_r, alpha * L * (T0 + T1) / 2.0, 1e-12);
  Model given = m;
  given.thermal.reset();
  for (std::size_t n = 0; n < m.nodes.size(); ++n) given.loads.node_temperature[n] = T0 + (T1 - T0) * m.nodes[n].r / L;
  const Solution reference = solve(given);
  ASSERT_EQ(reference.elements.size(), s.elements.size());
  const double scale = m.materials[0].table[0].E1 * alpha * (T1 - T0);
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    EXPECT_LT((s.elements[e].stress - reference.elements[e].stress).cwiseAbs().maxCoeff(), 1e-12 * scale);
  }
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

// Two concentric cylinders (axisymmetric): a < r < b of conductivity k1 and b' < r < c of k2, joined
// by a row of gap elements of width w = b' - b with conductance H per area, T(a) = Ta, T(c) = Tc, ends
// insulated. The heat per radian-length Q = 2 pi (Ta - Tc) / R flows through three resistances in
// series, R = ln(b / a) / k1 + ln(b' / b) / (H w) + ln(c / b') / k2 (the gap element conducts
// k_M = H w across its width, a layer of thickness w: its resistance ln(b'/b) / (H w) is 1 / (H b)
// to O(w / b)). So T = Ta - (Q / 2 pi k1) ln(r / a) in the inner cylinder, T = Tc + (Q / 2 pi k2)
// ln(c / r) in the outer one, and the temperature jumps by (Q / 2 pi) ln(b' / b) / (H w) across the gap.
struct TwoCylinders {
  double a = 1.0, b = 2.0, w = 1.0e-3, c = 3.0, k1 = 2.0, k2 = 5.0, H = 1.5, Ta = 500.0, Tc = 100.0;
  [[nodiscard]] double outer_inside() const { return b + w; }
  [[nodiscard]] double resistance() const {
    return std::log(b / a) / k1 + std::log(outer_inside() / b) / (H * w) + std::log(c / outer_inside()) / k2;
  }
  [[nodiscard]] double exact(double r) const {
    const double q = (Ta - Tc) / resistance();  // Q / 2 pi
    return r <= b ? Ta - q / k1 * std::log(r / a) : Tc + q / k2 * std::log(c / r);
  }
};

Model two_cylinders(const TwoCylinders& t, int n, testing::Grid& inner, testing::Grid& outer) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {conductor(t.k1), conductor(t.k2)};
  m.materials[1].id = 2;
  inner = testing::add_grid(m, n, 1, [&t](double s, double z) { return Vec2(t.a + (t.b - t.a) * s, 0.1 * z); }, 0);
  outer = testing::add_grid(
      m, n, 1, [&t](double s, double z) { return Vec2(t.outer_inside() + (t.c - t.outer_inside()) * s, 0.1 * z); }, 1);
  // Counter-clockwise: up the outer cylinder's inner side, down the inner cylinder's outer side.
  testing::add_gap_row(m, {outer.at(0, 0), outer.at(0, 1)}, {inner.at(n, 0), inner.at(n, 1)}, [](int) { return 0.0; });
  m.gaps->conductance = InterfaceConductance{{{0.0, t.H}}, 0.0};
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, inner, false, 0), t.Ta, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, outer, false, n), t.Tc, 0.0});
  return m;
}

TEST(ThermalGaps, ConcentricCylindersWithAnInterfaceConductanceHaveTheJumpAndBothLogProfiles) {
  const TwoCylinders t;
  testing::Grid inner, outer;
  const int n = 16;
  const Model m = two_cylinders(t, n, inner, outer);
  const std::vector<double> closed(m.gaps->elements.size(), t.H);
  const ThermalResult r = solve_steady_conduction(m, closed);
  for (const Node& node : m.nodes) {
    EXPECT_NEAR(r.T[node.id - 1], t.exact(node.r), 0.002 * (t.Ta - t.Tc)) << "r = " << node.r;
  }
  const double jump = r.T[inner.at(n, 0)] - r.T[outer.at(0, 0)];
  const double exact_jump = t.exact(t.b) - t.exact(t.outer_inside());
  EXPECT_NEAR(jump, exact_jump, 0.002 * exact_jump);
  // The jump is the interface's: about 1 / (H b) of R, a sizeable share of the whole drop.
  EXPECT_GT(exact_jump, 0.2 * (t.Ta - t.Tc));
}

TEST(ThermalGaps, GapConductanceFollowsTheContactStateAndPressure) {
  const TwoCylinders t;
  testing::Grid inner, outer;
  Model m = two_cylinders(t, 2, inner, outer);
  m.gaps->conductance = InterfaceConductance{{{0.0, 1.0}, {1000.0, 8.0}}, 0.0002};
  GapResult touching;
  touching.state = GapState::closed;
  touching.sigma_m = -500.0;  // compression: pressure 500, halfway up the table
  EXPECT_DOUBLE_EQ(gap_conductances(m, std::vector<GapResult>{touching})[0], 4.5);
  touching.sigma_m = -5000.0;  // beyond the table: its last h
  EXPECT_DOUBLE_EQ(gap_conductances(m, std::vector<GapResult>{touching})[0], 8.0);
  GapResult open;
  open.state = GapState::open;
  open.eps_m = 1.0;  // opened to twice its width
  EXPECT_NEAR(gap_conductances(m, std::vector<GapResult>{open})[0], 0.0002 / (2.0 * t.w), 1e-12);
  // Before any stress solve every gap is open at its width.
  EXPECT_NEAR(gap_conductances(m, {})[0], 0.0002 / t.w, 1e-12);
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

TEST(ThermalTransient, EachOutputTimeIsALoadStepOfTheStressAnalysis) {
  Model m = cylinder_model(Cylinder{}, 4);
  m.materials[0].table[0].c = 1.0;
  m.materials[0].table[0].alpha1 = m.materials[0].table[0].alpha2 = m.materials[0].table[0].alpha3 = 1.0e-5;
  m.materials[0].density = 1.0;
  m.thermal->type = ThermalType::transient;
  m.thermal->initial_temperature = 70.0;
  m.thermal->time_step = 0.1;
  m.thermal->end_time = 1.0;
  m.thermal->output_times = {0.5, 1.0};
  testing::fill_temperatures(m, 70.0);
  for (const Node& n : m.nodes) {
    if (n.z == 0.0) testing::constrain(m, static_cast<int>(&n - m.nodes.data()), std::nullopt, 0.0);
  }
  const Solution s = solve_with_heat(m);
  ASSERT_TRUE(s.thermal.has_value());
  ASSERT_EQ(s.steps.size(), 2u);
  EXPECT_EQ(s.steps[0].name, "t = 0.5");
  EXPECT_EQ(s.steps[1].name, "t = 1");
  EXPECT_EQ(s.steps[1].status, StepStatus::converged);
  EXPECT_EQ(s.thermal->T, s.thermal->history.back());
  // Each step solves the stresses of its time's temperatures: the last equals a plain run with them.
  Model given = m;
  given.thermal.reset();
  given.loads.node_temperature = s.thermal->T;
  const Solution reference = solve(given);
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    EXPECT_LT((s.elements[e].stress - reference.elements[e].stress).cwiseAbs().maxCoeff(), 1e-9);
  }
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

/// The cylinders with thermal expansion and gaps that close (classic method), held at u_z = 0 on z = 0.
Model expanding_cylinders(const TwoCylinders& t, int n, testing::Grid& inner, testing::Grid& outer) {
  Model m = two_cylinders(t, n, inner, outer);
  for (Material& mat : m.materials) mat.table[0].alpha1 = mat.table[0].alpha2 = mat.table[0].alpha3 = 1.0e-4;
  m.gaps->initial_modulus = 100.0;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
  m.gaps->conductance = InterfaceConductance{{{0.0, 1.0}, {2000.0, 8.0}}, 0.001};
  m.solver.max_iterations = 60;
  testing::fill_temperatures(m, 0.0);
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    if (m.nodes[k].z == 0.0) testing::constrain(m, static_cast<int>(k), std::nullopt, 0.0);
  }
  return m;
}

// Coupled: the inner cylinder, held hot at r = a, grows across the gap (open at first, conducting
// through the gas only) into the outer one, held cold at r = c. The passes must end with the gaps
// touching and the temperatures those of a conduction solve with the conductances of the final
// contact state (the fixed point the stopping rule claims).
TEST(ThermalGaps, TemperaturesAndContactAreIteratedTogetherToAFixedPoint) {
  TwoCylinders t;
  t.Ta = 400.0;
  t.Tc = 0.0;
  testing::Grid inner, outer;
  const int n = 8;
  Model m = expanding_cylinders(t, n, inner, outer);
  testing::StateRecorder recorder;
  const Solution s = solve_with_heat(m, &recorder);
  ASSERT_TRUE(s.thermal.has_value());
  EXPECT_EQ(s.status, RunStatus::converged);
  EXPECT_GE(s.thermal->passes, 2);
  // A thermal row per pass: the held temperatures bound T, and the last pass changed T by no more
  // than the stopping rule allows.
  ASSERT_EQ(recorder.thermal.size(), static_cast<std::size_t>(s.thermal->passes));
  for (std::size_t k = 0; k < recorder.thermal.size(); ++k) {
    const ThermalRecord& row = recorder.thermal[k];
    EXPECT_EQ(row.kind, ThermalRowKind::steady);
    EXPECT_EQ(row.index, static_cast<int>(k) + 1);
    EXPECT_EQ(row.pass, static_cast<int>(k) + 1);
    EXPECT_EQ(row.iterations, 1);  // a constant k: one solve per pass
    EXPECT_EQ(row.max_T, t.Ta);
    EXPECT_EQ(row.min_T, t.Tc);
  }
  EXPECT_EQ(recorder.thermal.front().pass_change, 0.0);
  EXPECT_EQ(recorder.thermal.front().max_change, t.Ta);  // from the reference temperature 0
  EXPECT_GT(recorder.thermal[1].pass_change, 0.0);
  EXPECT_LE(recorder.thermal.back().pass_change, coupling_tolerance * (1.0 + t.Ta));
  for (const GapResult& g : s.gaps) EXPECT_TRUE(g.state == GapState::closed || g.state == GapState::overclosed);
  const ThermalResult fixed_point = solve_steady_conduction(m, gap_conductances(m, s.gaps));
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    EXPECT_NEAR(s.thermal->T[k], fixed_point.T[k], 1e-6 * (t.Ta - t.Tc)) << "node " << m.nodes[k].id;
  }
  // Touching faces conduct far better than the gas did at first: the jump is a fraction of the drop.
  EXPECT_LT(s.thermal->T[inner.at(n, 0)] - s.thermal->T[outer.at(0, 0)], 0.5 * (t.Ta - t.Tc));
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

// The same cylinders in a transient run: the gaps conduct through the gas until the first output
// time's stress step closes them; by t = 32 the run sits on the steady coupled solution within 0.5 %.
TEST(ThermalGaps, TransientRunWithGapConductanceApproachesTheSteadyCoupledSolution) {
  TwoCylinders t;
  t.Ta = 400.0;
  t.Tc = 0.0;
  testing::Grid inner, outer;
  Model m = expanding_cylinders(t, 4, inner, outer);
  const auto [steady, s] = testing::steady_then_settling_transient(m);
  ASSERT_TRUE(s.thermal.has_value() && steady.thermal.has_value());
  EXPECT_EQ(s.thermal->history.size(), 7u);
  EXPECT_LE(s.thermal->factorizations, 7);
  for (const GapResult& g : s.gaps) EXPECT_TRUE(g.state == GapState::closed || g.state == GapState::overclosed);
  // The first interval ran with the gas's conductance, the last with touching faces.
  const auto jump = [&](const std::vector<double>& T) { return T[inner.at(4, 0)] - T[outer.at(0, 0)]; };
  EXPECT_GT(jump(s.thermal->history.front()), 1.5 * jump(s.thermal->history.back()));
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    EXPECT_NEAR(s.thermal->T[k], steady.thermal->T[k], 0.005 * (t.Ta - t.Tc)) << "node " << m.nodes[k].id;
  }
}

// Radiation. A plane slab 0 < x < L held at T0 on x = 0 and radiating to an ambient Ta on x = L
// (other edges insulated; temperatures absolute): the steady T is linear, and the heat conducted
// through the slab leaves by radiation, k (T0 - T_L) / L = e sigma (T_L^4 - Ta^4), a quartic in T_L
// with one root between Ta and T0 (the left side falls, the right side rises), found by bisection.
struct RadiatingSlab {
  double L = 0.5, k = 20.0, T0 = 1200.0, Ta = 300.0, e = 0.8, sigma = 5.670374e-8;
  [[nodiscard]] double surface() const {
    double lo = Ta, hi = T0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      const double excess = k * (T0 - mid) / L - e * sigma * (mid * mid * mid * mid - Ta * Ta * Ta * Ta);
      (excess > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

Model radiating_slab(const RadiatingSlab& s, testing::Grid& g) {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {conductor(s.k, 2.0, 3.0)};
  g = testing::add_grid(m, 6, 2, [&s](double x, double y) { return Vec2(s.L * x, 0.1 * y); }, 0);
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, side(m, g, false, 0), s.T0, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::radiation, side(m, g, false, g.ni), s.e * s.sigma, s.Ta});
  return m;
}

TEST(ThermalRadiation, SlabRadiatingToAnAmbientHasTheSurfaceTemperatureOfItsQuartic) {
  const RadiatingSlab s;
  testing::Grid g;
  const Model m = radiating_slab(s, g);
  const ThermalResult r = solve_steady_conduction(m);
  const double TL = s.surface();
  // The radiation is a sizeable share of the problem: T_L well away from both ends.
  ASSERT_GT(TL - s.Ta, 0.2 * (s.T0 - s.Ta));
  ASSERT_LT(TL - s.Ta, 0.8 * (s.T0 - s.Ta));
  for (const Node& n : m.nodes) {
    EXPECT_NEAR(r.T[static_cast<std::size_t>(n.id - 1)], s.T0 + (TL - s.T0) * n.r / s.L, 1e-8 * s.T0) << "x = " << n.r;
  }
  EXPECT_GT(r.iterations, 2);  // Newton's passes, each refactorized
  EXPECT_LT(r.iterations, 12);
}

TEST(ThermalRadiation, TransientSlabRadiatingSettlesOnTheSteadySurfaceTemperature) {
  const RadiatingSlab s;
  testing::Grid g;
  Model m = radiating_slab(s, g);
  m.materials[0].stores_heat = true;
  m.thermal->type = ThermalType::transient;
  m.thermal->initial_temperature = s.T0;
  m.thermal->time_step = 0.002;  // alpha = 20 / 6: L^2 / alpha = 0.075
  m.thermal->end_time = 1.5;
  m.thermal->output_times = {0.01, 1.5};
  const ThermalResult r = solve_transient_conduction(m);
  const double TL = s.surface();
  // Cooling starts at the radiating face.
  EXPECT_LT(r.history[0][static_cast<std::size_t>(g.at(g.ni, 0))], s.T0 - 10.0);
  EXPECT_NEAR(r.history[0][static_cast<std::size_t>(g.at(0, 0))], s.T0, 1e-9 * s.T0);
  for (const Node& n : m.nodes) {
    EXPECT_NEAR(r.T[static_cast<std::size_t>(n.id - 1)], s.T0 + (TL - s.T0) * n.r / s.L, 1e-4 * s.T0) << "x = " << n.r;
  }
}

}  // namespace
}  // namespace saasgaps
