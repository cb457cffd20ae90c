// Heat conduction on the quadratic families (tri6, quad8, quad9) and quad4i through the whole
// thermal path (ThermalSystem, solve_steady_conduction, solve_transient_conduction, solve_with_heat)
// against closed forms derived here.
//
// Patch test. A linear T = T0 + g.x solves div(k grad T) = 0 for a constant tensor k (plane). On a
// straight boundary edge with outward normal n the heat flowing in is (k g).n, constant per edge:
// each edge its own flux entry; the bottom side lies along an isotherm and is held at its
// temperature. Interior nodes are pushed off the grid, interior mid-side nodes off their chords
// (curved interior edges): the space holds the field, so it is reproduced to round-off.
//
// Slab 0 < x < L (plane), T(0) = T0, a film h to T_a at x = L, the other sides insulated: the
// linear T = T0 + g x with -k g = h (T0 + g L - T_a), g = h (T_a - T0) / (k + h L); quadratic
// elements hold it exactly. With a source s and T = 0 at both ends: T = s x (L - x) / (2 k), a
// quadratic, also held exactly.
//
// Thick wall a < r < b, T(a) = Ti, a film h to T_a at r = b: T = A + B ln r (axisymmetric, and plane
// on a ring sector, where the edges are arcs) with A + B ln a = Ti and -k B / b = h (A + B ln b - T_a):
// B = -h (Ti - T_a) / (k / b + h ln(b / a)).
//
// Solid cylinder (axisymmetric) radius R, source s, film h to T_a: T = T_a + s R / (2 h) + s (R^2 - r^2)
// / (4 k), quadratic in r: held exactly.
//
// Thermal stress of the thick wall (Timoshenko and Goodier, section 151), plane strain (eps_z = 0), the
// surfaces free, temperature rise T(r) above the reference:
//   sigma_theta(r) = E alpha / ((1 - nu) r^2) [ (r^2 + a^2) / (b^2 - a^2) I(b) + I(r) - T r^2 ],
//   I(r) = integral_a^r T rho d rho;  for T = A + B ln r: I = [A rho^2 / 2 + B (rho^2 ln rho / 2 - rho^2 / 4)]_a^r.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "solver/analysis/analysis.hpp"
#include "solver/thermal/conduction_kernel.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/mesh_builder.hpp"

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

constexpr std::array<ElementType, 3> quadratic_types{ElementType::tri6, ElementType::quad8, ElementType::quad9};

std::string name(ElementType t) { return std::string(element_type_names.name(t)); }

/// Outward unit normal of edge a -> b of element e (the element's nodes' mean is inside).
Vec2 outward(const Model& m, const ThermalEdge& e) {
  const Node& a = m.nodes[static_cast<std::size_t>(e.node_a)];
  const Node& b = m.nodes[static_cast<std::size_t>(e.node_b)];
  const Element& el = m.elements[static_cast<std::size_t>(e.element)];
  Vec2 centre = Vec2::Zero();
  for (const int n : el.node_span()) centre += Vec2(m.nodes[static_cast<std::size_t>(n)].r, m.nodes[static_cast<std::size_t>(n)].z);
  centre /= el.node_count;
  Vec2 n = Vec2(b.z - a.z, -(b.r - a.r)).normalized();
  return n.dot(centre - Vec2(a.r, a.z)) > 0.0 ? Vec2(-n) : n;
}

// ---- the patch test ----

void expect_linear_field(ElementType type, AnalysisType analysis, const Conductivity& k, const Vec2& gradient) {
  // The bottom side runs along the isotherm through (1, 0): direction perpendicular to the gradient.
  const Vec2 along = Vec2(gradient.y(), -gradient.x()).normalized() * (gradient.y() >= 0.0 ? 1.0 : -1.0);
  const Vec2 up(-along.y(), along.x());
  const auto map = [&](double s, double t) -> Vec2 { return Vec2(1.0, 0.0) + 2.0 * s * along + 1.5 * t * up; };
  // Interior nodes off the grid; interior mid-side nodes off their chords (curved interior edges).
  const auto offset = [](int I, int J) -> Vec2 {
    if (I == 0 || J == 0 || I == 6 || J == 6) return Vec2::Zero();
    return Vec2(0.05 * std::sin(3.0 * I + J), 0.04 * std::cos(2.0 * I - J));
  };
  Model m;
  m.analysis = analysis;
  m.thickness = 0.4;
  m.materials = {conductor(k.k1)};
  m.materials[0].table[0].k2 = k.k2;
  const testing::QuadraticGrid g = testing::add_quadratic_grid(m, type, 3, 3, map, 0, offset);
  for (Element& el : m.elements) el.angle_deg = k.angle_deg;
  m.thermal.emplace();
  const auto field = [&](const Node& n) { return 20.0 + gradient.dot(Vec2(n.r, n.z)); };
  m.thermal->boundary.push_back(
      {ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, g, 'b'), field(m.nodes[g.at(0, 0)]), 0.0});
  const Eigen::Matrix2d tensor = k.tensor();
  for (const char side : {'r', 't', 'l'}) {
    for (const ThermalEdge& e : testing::quadratic_grid_side(m, g, side)) {
      m.thermal->boundary.push_back({ThermalBoundary::Kind::flux, {e}, (tensor * gradient).dot(outward(m, e)), 0.0});
    }
  }
  const ThermalResult r = solve_steady_conduction(m);
  double worst = 0.0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) worst = std::max(worst, std::abs(r.T[n] - field(m.nodes[n])));
  std::printf("patch %s: largest nodal error %.2e (field range ~%.0f)\n", name(type).c_str(), worst, 3.0 * gradient.norm());
  EXPECT_LT(worst, 1e-10) << name(type);
  for (const Vec2& q : r.flux) EXPECT_LT((q + tensor * gradient).norm(), 1e-9) << name(type);
}

TEST(QuadraticConduction, DistortedCurvedPatchReproducesALinearField) {
  for (const ElementType type : {ElementType::tri6, ElementType::quad8, ElementType::quad9, ElementType::quad4i}) {
    expect_linear_field(type, AnalysisType::plane_stress, {2.0, 2.0, 0.0}, Vec2(30.0, 60.0));
    expect_linear_field(type, AnalysisType::plane_strain, {3.0, 0.4, 33.0}, Vec2(-20.0, 50.0));
  }
}

// ---- the slab: a film, a source ----

TEST(QuadraticConduction, SlabWithAFilmIsLinearToRoundOff) {
  const double L = 2.0, k = 3.0, h = 5.0, T0 = 400.0, Ta = 20.0;
  const double g = h * (Ta - T0) / (k + h * L);
  for (const ElementType type : quadratic_types) {
    Model m;
    m.analysis = AnalysisType::plane_strain;
    m.materials = {conductor(k)};
    const auto grid = testing::add_quadratic_grid(m, type, 4, 2, [&](double s, double t) { return Vec2(L * s, 0.5 * t); }, 0);
    m.thermal.emplace();
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'l'), T0, 0.0});
    m.thermal->boundary.push_back({ThermalBoundary::Kind::film, testing::quadratic_grid_side(m, grid, 'r'), h, Ta});
    const ThermalResult r = solve_steady_conduction(m);
    for (std::size_t n = 0; n < m.nodes.size(); ++n) EXPECT_NEAR(r.T[n], T0 + g * m.nodes[n].r, 1e-11 * T0) << name(type);
  }
}

TEST(QuadraticConduction, SlabWithASourceHasItsParabolaAtTheNodesToRoundOff) {
  const double L = 2.0, k = 3.0, s = 7.0;
  for (const ElementType type : quadratic_types) {
    Model m;
    m.analysis = AnalysisType::plane_stress;
    m.thickness = 0.2;
    m.materials = {conductor(k)};
    const auto grid = testing::add_quadratic_grid(m, type, 3, 1, [&](double x, double t) { return Vec2(L * x, 0.5 * t); }, 0);
    m.thermal.emplace();
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'l'), 0.0, 0.0});
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'r'), 0.0, 0.0});
    m.thermal->sources.push_back({0, s});
    const ThermalResult r = solve_steady_conduction(m);
    const double peak = s * L * L / (8.0 * k);
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      const double x = m.nodes[n].r;
      EXPECT_NEAR(r.T[n], s * x * (L - x) / (2.0 * k), 1e-12 * peak) << name(type) << " x = " << x;
    }
  }
}

TEST(QuadraticConduction, SolidCylinderWithSourceAndFilmHasItsParabolaToRoundOff) {
  const double R = 2.0, k = 3.0, s = 5.0, h = 4.0, Ta = 70.0;
  const auto exact = [&](double r) { return Ta + s * R / (2.0 * h) + s * (R * R - r * r) / (4.0 * k); };
  for (const ElementType type : quadratic_types) {
    Model m;
    m.analysis = AnalysisType::axisymmetric;
    m.materials = {conductor(k)};
    const auto grid = testing::add_quadratic_grid(m, type, 3, 1, [&](double x, double t) { return Vec2(R * x, 0.1 * t); }, 0);
    m.thermal.emplace();
    m.thermal->boundary.push_back({ThermalBoundary::Kind::film, testing::quadratic_grid_side(m, grid, 'r'), h, Ta});
    m.thermal->sources.push_back({0, s});
    const ThermalResult r = solve_steady_conduction(m);
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      EXPECT_NEAR(r.T[n], exact(m.nodes[n].r), 1e-12 * exact(0.0)) << name(type) << " r = " << m.nodes[n].r;
    }
  }
}

// ---- the thick wall ----

struct Wall {
  double a = 1.0, b = 2.0, k = 3.0, h = 5.0, Ti = 300.0, Ta = 20.0;
  [[nodiscard]] double B() const { return -h * (Ti - Ta) / (k / b + h * std::log(b / a)); }
  [[nodiscard]] double A() const { return Ti - B() * std::log(a); }
  [[nodiscard]] double T(double r) const { return A() + B() * std::log(r); }
};

/// The largest nodal error of the wall on `radial` elements through it, relative to Ti - T(b).
/// Axisymmetric: a slice of height 0.25; plane: the quarter ring, its arcs curved edges (mid-side
/// nodes on the circles).
double wall_error(ElementType type, AnalysisType analysis, int radial) {
  const Wall w;
  Model m;
  m.analysis = analysis;
  m.materials = {conductor(w.k)};
  const auto map = [&](double s, double t) -> Vec2 {
    const double r = w.a + (w.b - w.a) * s;
    if (analysis == AnalysisType::axisymmetric) return Vec2(r, 0.25 * t);
    return Vec2(r * std::cos(0.5 * pi * t), r * std::sin(0.5 * pi * t));
  };
  const auto grid = testing::add_quadratic_grid(m, type, radial, analysis == AnalysisType::axisymmetric ? 1 : 6, map, 0);
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'l'), w.Ti, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::film, testing::quadratic_grid_side(m, grid, 'r'), w.h, w.Ta});
  const ThermalResult r = solve_steady_conduction(m);
  double worst = 0.0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    worst = std::max(worst, std::abs(r.T[n] - w.T(std::hypot(m.nodes[n].r, analysis == AnalysisType::axisymmetric ? 0.0 : m.nodes[n].z))));
  }
  const double relative = worst / (w.Ti - w.T(w.b));
  std::printf("wall %s %s, %d through: largest nodal error %.3e of Ti - T(b)\n", name(type).c_str(),
              std::string(analysis_type_names.name(analysis)).c_str(), radial, relative);
  return relative;
}

TEST(QuadraticConduction, ThickWallFollowsTheLogarithm) {
  // Observed: quad8 2.0e-5 (axisymmetric) and 1.6e-5 (plane, curved arcs); quad9 2.0e-5 and 2.4e-5;
  // tri6 1.8e-4 and 4.0e-4.
  EXPECT_LT(wall_error(ElementType::quad8, AnalysisType::axisymmetric, 4), 3e-5);
  EXPECT_LT(wall_error(ElementType::quad8, AnalysisType::plane_strain, 4), 3e-5);
  EXPECT_LT(wall_error(ElementType::quad9, AnalysisType::axisymmetric, 4), 3e-5);
  EXPECT_LT(wall_error(ElementType::quad9, AnalysisType::plane_strain, 4), 3e-5);
  EXPECT_LT(wall_error(ElementType::tri6, AnalysisType::axisymmetric, 4), 2.5e-4);
  EXPECT_LT(wall_error(ElementType::tri6, AnalysisType::plane_strain, 4), 5e-4);
}

// ---- a transient: the slab suddenly held at a surface temperature (thermal_conduction_test.cpp) ----

double slab_theta(double x, double t, double L, double alpha) {
  double sum = 0.0;
  for (int n = 0; n < 200; ++n) {
    const double lambda = (2 * n + 1) * pi / (2.0 * L);
    sum += 4.0 / ((2 * n + 1) * pi) * std::sin(lambda * x) * std::exp(-lambda * lambda * alpha * t);
  }
  return sum;
}

TEST(QuadraticConduction, SlabSuddenlyHeldAtASurfaceTemperatureFollowsTheFourierSeries) {
  // L = 1, alpha = k / (density c) = 2 / (4 x 0.5) = 1; 20 quadratic elements (41 nodes along x).
  const double L = 1.0, Ti = 70.0, Ts = 1000.0;
  for (const ElementType type : quadratic_types) {
    Model m;
    m.analysis = AnalysisType::plane_stress;
    m.materials = {conductor(2.0, 4.0, 0.5)};
    const auto grid = testing::add_quadratic_grid(m, type, 20, 1, [L](double s, double t) { return Vec2(L * s, 0.05 * t); }, 0);
    m.thermal.emplace();
    m.thermal->type = ThermalType::transient;
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'l'), Ts, 0.0});
    m.thermal->initial_temperature = Ti;
    m.thermal->time_step = 0.0005;
    m.thermal->end_time = 0.5;
    m.thermal->output_times = {0.02, 0.05, 0.1, 0.2, 0.5};
    const ThermalResult r = solve_transient_conduction(m);
    ASSERT_EQ(r.history.size(), 5u);
    EXPECT_EQ(r.time_steps, 1000);
    EXPECT_EQ(r.factorizations, 1);
    double worst = 0.0;
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      for (std::size_t n = 0; n < m.nodes.size(); ++n) {
        const double exact = Ts + (Ti - Ts) * slab_theta(m.nodes[n].r, r.times[k], L, 1.0);
        worst = std::max(worst, std::abs(r.history[k][n] - exact) / (Ts - Ti));
      }
    }
    std::printf("slab transient %s: largest error %.3e of Ts - Ti\n", name(type).c_str(), worst);
    // Observed 3.47e-3 (tri6), 3.44e-3 (quad8, quad9): backward Euler's error at t = 0.02 (the same for
    // every family), not the space's.
    EXPECT_LT(worst, 4e-3) << name(type);
  }
}

// ---- thermal stress of the thick wall ----

TEST(QuadraticConduction, ThickWallHoopStressFromTheComputedTemperatures) {
  const Wall w;
  const double E = 200.0e3, nu = 0.3, alpha = 1.2e-5;
  const auto I = [&](double r) {
    const auto F = [&](double x) { return w.A() * x * x / 2.0 + w.B() * (x * x * std::log(x) / 2.0 - x * x / 4.0); };
    return F(r) - F(w.a);
  };
  const auto hoop = [&](double r) {
    return E * alpha / ((1.0 - nu) * r * r) * ((r * r + w.a * w.a) / (w.b * w.b - w.a * w.a) * I(w.b) + I(r) - w.T(r) * r * r);
  };
  for (const ElementType type : {ElementType::quad8, ElementType::quad9}) {
    const int radial = 8;
    const double height = 0.25;
    Model m;
    m.analysis = AnalysisType::axisymmetric;
    m.reference_temperature = 0.0;
    m.materials = {testing::isotropic_material(1, E, nu, alpha)};
    m.materials[0].table[0].k1 = m.materials[0].table[0].k2 = m.materials[0].table[0].k3 = w.k;
    m.materials[0].conducts = true;
    const auto grid = testing::add_quadratic_grid(
        m, type, radial, 1, [&](double s, double t) { return Vec2(w.a + (w.b - w.a) * s, height * t); }, 0);
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      if (m.nodes[n].z == 0.0 || m.nodes[n].z == height) testing::constrain(m, static_cast<int>(n), std::nullopt, 0.0);
    }
    testing::fill_temperatures(m, 0.0);
    m.thermal.emplace();
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(m, grid, 'l'), w.Ti, 0.0});
    m.thermal->boundary.push_back({ThermalBoundary::Kind::film, testing::quadratic_grid_side(m, grid, 'r'), w.h, w.Ta});
    const Solution s = solve_with_heat(m);
    ASSERT_EQ(s.status, RunStatus::converged) << s.message;
    // The mid-side nodes have their own temperatures, on the logarithm.
    for (std::size_t n = 0; n < m.nodes.size(); ++n) EXPECT_NEAR(s.thermal->T[n], w.T(m.nodes[n].r), 1e-3);
    double worst = 0.0;
    for (int e = 0; e < radial; ++e) {
      const double r = w.a + (w.b - w.a) * (e + 0.5) / radial;
      const double computed = s.elements[static_cast<std::size_t>(e)].stress[th];
      worst = std::max(worst, std::abs(computed / hoop(r) - 1.0) * std::abs(hoop(r)) / std::abs(hoop(w.a)));
      if (e == 0) {
        std::printf("thermal hoop %s: bore element centre r = %.4f: %.4f vs %.4f (%+.3e); bore closed form %.4f\n",
                    name(type).c_str(), r, computed, hoop(r), computed / hoop(r) - 1.0, hoop(w.a));
      }
    }
    std::printf("thermal hoop %s: largest centre error %.3e of the bore's hoop stress\n", name(type).c_str(), worst);
    // Observed 3.0e-3 (quad8 and quad9; the bore element's centre -3.8e-3 of the value there).
    EXPECT_LT(worst, 4e-3) << name(type);
  }
}

}  // namespace
}  // namespace saasgaps
