// Heat across contact pairs (model.contact with `conductance`) against closed forms derived here.
//
// Two concentric cylinders (axisymmetric), a < r < b of conductivity k1 and b + g < r < c of k2,
// meshed on their own with different divisions along z (non-matching), joined by a contact pair
// (side A the inner cylinder's outer face r = b, side B the outer one's inner face r = b + g).
// T(a) = Ta, T(c) = Tc, ends insulated, so T depends on r only and the heat per radian and length
// Q / 2 pi = q is the same through every cylinder r = const. The interface passes h (T_A - T_B) per
// area of side A (contact_conductance.hpp), 2 pi b h (T_A - T_B) per length, so the three
// resistances in series are
//   R = ln(b / a) / k1 + 1 / (h b) + ln(c / (b + g)) / k2,   q = (Ta - Tc) / R,
// T = Ta - (q / k1) ln(r / a) in the inner cylinder, T = Tc + (q / k2) ln(c / r) in the outer one,
// and the temperature jumps by q / (h b) across the interface. Touching (g = 0): h is the `closed`
// value; open (g > 0): h = gas_conductivity / g.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <Eigen/Dense>

#include "solver/thermal/contact_conductance.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/mesh_builder.hpp"
#include "support/settling_transient.hpp"
#include "support/stacked_blocks.hpp"

namespace saasgaps {
namespace {

Material conductor(int id, double k) {
  Material m = testing::isotropic_material(id, 1.0e6, 0.3);
  m.table[0].k1 = m.table[0].k2 = m.table[0].k3 = k;
  m.conducts = true;
  return m;
}

/// The edges of grid column i as thermal edges of their elements.
std::vector<ThermalEdge> column(const Model& m, const testing::Grid& g, int i) {
  std::vector<ThermalEdge> edges;
  for (const auto& [a, b] : testing::column_edges(g, i)) {
    for (std::size_t e = 0; e < m.elements.size(); ++e) {
      const std::span<const int> nodes = m.elements[e].node_span();
      if (std::find(nodes.begin(), nodes.end(), a) != nodes.end() &&
          std::find(nodes.begin(), nodes.end(), b) != nodes.end()) {
        edges.push_back({static_cast<int>(e), a, b});
      }
    }
  }
  return edges;
}

struct Cylinders {
  double a = 1.0, b = 2.0, g = 0.0, c = 3.0, k1 = 2.0, k2 = 5.0, Ta = 500.0, Tc = 100.0;
  double h = 1.5;  // the interface's conductance: closed, or gas / g when open
  [[nodiscard]] double resistance() const { return std::log(b / a) / k1 + 1.0 / (h * b) + std::log(c / (b + g)) / k2; }
  [[nodiscard]] double flow() const { return (Ta - Tc) / resistance(); }  // q = Q / 2 pi
  [[nodiscard]] double exact(double r, bool inner) const {
    return inner ? Ta - flow() / k1 * std::log(r / a) : Tc + flow() / k2 * std::log(c / r);
  }
  [[nodiscard]] double jump() const { return flow() / (h * b); }
};

struct CylinderModel {
  Model model;
  testing::Grid inner, outer;
};

/// n radial divisions in each cylinder; 3 divisions along z in the inner one, 5 in the outer one.
CylinderModel cylinders(const Cylinders& t, int n, const InterfaceConductance& conductance) {
  CylinderModel out;
  Model& m = out.model;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {conductor(1, t.k1), conductor(2, t.k2)};
  constexpr double height = 0.1;
  out.inner = testing::add_grid(m, n, 3, [&t](double s, double z) { return Vec2(t.a + (t.b - t.a) * s, height * z); }, 0);
  const double inside = t.b + t.g;
  out.outer = testing::add_grid(m, n, 5, [&](double s, double z) { return Vec2(inside + (t.c - inside) * s, height * z); }, 1);
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"inner", testing::column_edges(out.inner, n)}, {"outer", testing::column_edges(out.outer, 0)}};
  SurfacePair& pair = contact.pairs.emplace_back();
  pair.surfaces = {0, 1};
  pair.conductance = conductance;
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, column(m, out.inner, 0), t.Ta, 0.0});
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, column(m, out.outer, n), t.Tc, 0.0});
  return out;
}

/// Every node within 0.2 % of the drop of its cylinder's log profile, and the jump at every height
/// of side A (against B's temperature there, linear along z) within 0.2 % of q / (h b).
void expect_closed_form(const Cylinders& t, const CylinderModel& c, const ThermalResult& r) {
  const int n = c.inner.ni;
  for (const int k : c.inner.nodes) {
    const Node& node = c.model.nodes[static_cast<std::size_t>(k)];
    EXPECT_NEAR(r.T[k], t.exact(node.r, true), 0.002 * (t.Ta - t.Tc)) << "inner r = " << node.r << ", z = " << node.z;
  }
  for (const int k : c.outer.nodes) {
    const Node& node = c.model.nodes[static_cast<std::size_t>(k)];
    EXPECT_NEAR(r.T[k], t.exact(node.r, false), 0.002 * (t.Ta - t.Tc)) << "outer r = " << node.r << ", z = " << node.z;
  }
  // T along the outer cylinder's inner face is uniform in z to round-off: its bottom node will do.
  const double outer_face = r.T[c.outer.at(0, 0)];
  for (int j = 0; j <= c.inner.nj; ++j) {
    const double jump = r.T[c.inner.at(n, j)] - outer_face;
    EXPECT_NEAR(jump, t.jump(), 0.002 * t.jump()) << "side A node " << j;
  }
}

TEST(ThermalContact, ConcentricCylindersTouchingOnNonMatchingMeshesHaveTheJumpAndBothLogProfiles) {
  const Cylinders t;
  const CylinderModel c = cylinders(t, 16, InterfaceConductance{{{0.0, t.h}}, 0.0});
  const ThermalResult r = solve_steady_conduction(c.model);  // before any stress solve: touching at gap 0
  expect_closed_form(t, c, r);
  // The interface is a sizeable share of the whole resistance, so the jump is tested, not noise.
  EXPECT_GT(t.jump(), 0.2 * (t.Ta - t.Tc));
}

TEST(ThermalContact, AnOpenGapConductsThroughTheGasOnly) {
  Cylinders t;
  t.g = 2.0e-3;
  const double gas = 3.0e-3;
  t.h = gas / t.g;
  // The closed value differs, so a point wrongly counted as touching would show.
  const CylinderModel c = cylinders(t, 16, InterfaceConductance{{{0.0, 40.0}}, gas});
  const ContactConductance pairs(c.model);
  ASSERT_EQ(pairs.row_count(), 4u);  // the 4 nodes of side A
  for (const double H : pairs.conductances({})) EXPECT_NEAR(H, t.h, 1e-9 * t.h);
  expect_closed_form(t, c, solve_steady_conduction(c.model));
}

TEST(ThermalContact, ConductanceFollowsEachPointsStateAndPressure) {
  const Cylinders t;
  const CylinderModel c = cylinders(t, 2, InterfaceConductance{{{0.0, 1.0}, {1000.0, 8.0}}, 0.0002});
  const ContactConductance pairs(c.model);
  ContactPairResult result;
  result.points.resize(pairs.row_count());
  result.points[0] = {0.0, 0.0, 0.0, 500.0, 0.0, 0.0, ContactPointState::stick};  // halfway up the table
  result.points[1] = {0.0, 0.0, 0.0, 5000.0, 0.0, 0.0, ContactPointState::stick};  // beyond it: its last h
  result.points[2] = {0.0, 0.0, 0.004, 0.0, 0.0, 0.0, ContactPointState::open};   // gas across 0.004
  result.points[3] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, ContactPointState::open};     // at zero gap: touching
  const std::vector<double> H = pairs.conductances(std::vector<ContactPairResult>{result});
  EXPECT_DOUBLE_EQ(H[0], 4.5);
  EXPECT_DOUBLE_EQ(H[1], 8.0);
  EXPECT_DOUBLE_EQ(H[2], 0.0002 / 0.004);
  EXPECT_DOUBLE_EQ(H[3], 1.0);
  EXPECT_EQ(pairs.touching(std::vector<ContactPairResult>{result}), (std::vector<bool>{true, true, false, true}));
}

// Coupled: the inner cylinder, held hot at r = a, grows across an open gap (conducting through the gas
// only at first) into the outer one, held cold at r = c, and presses on it. The passes must end with
// every point of side A in contact and the temperatures those of a conduction solve with the
// conductances of the final contact state (the fixed point the stopping rule claims).
TEST(ThermalContact, TemperaturesAndContactAreIteratedTogetherToAFixedPoint) {
  Cylinders t;
  t.g = 1.0e-3;
  t.Ta = 400.0;
  t.Tc = 0.0;
  CylinderModel c = cylinders(t, 8, InterfaceConductance{{{0.0, 1.0}, {2000.0, 8.0}}, 1.0e-3});
  Model& m = c.model;
  for (Material& mat : m.materials) mat.table[0].alpha1 = mat.table[0].alpha2 = mat.table[0].alpha3 = 1.0e-4;
  testing::fill_temperatures(m, 0.0);
  for (std::size_t k = 0; k < m.nodes.size(); ++k) testing::constrain(m, static_cast<int>(k), std::nullopt, 0.0);
  const Solution s = solve_with_heat(m);
  ASSERT_TRUE(s.thermal.has_value());
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_GE(s.thermal->passes, 2);
  ASSERT_EQ(s.contact.size(), 1u);
  for (const ContactPointResult& p : s.contact[0].points) {
    EXPECT_EQ(p.state, ContactPointState::stick);
    EXPECT_GT(p.pressure, 0.0);
  }
  const ContactConductance pairs(m);
  const ThermalResult fixed_point = solve_steady_conduction(m, {}, pairs.conductances(s.contact));
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    EXPECT_NEAR(s.thermal->T[k], fixed_point.T[k], 1e-6 * (t.Ta - t.Tc)) << "node " << m.nodes[k].id;
  }
  // Touching faces conduct far better than the gas (h = 1 across the gap) did at first.
  const ThermalResult first = solve_steady_conduction(m);
  const int n = c.inner.ni;
  EXPECT_LT(s.thermal->T[c.inner.at(n, 0)] - s.thermal->T[c.outer.at(0, 0)],
            0.5 * (first.T[c.inner.at(n, 0)] - first.T[c.outer.at(0, 0)]));
}

// Coupled ring (issue 21's "What it must show"): the inner cylinder, held hot at r = a, grows across
// the gap g into the outer one, held cold at r = c, and the contact it makes conducts h(p). Every node
// is held at u_z = 0, so the stress state is plane strain (eps_z = 0) and everything depends on r only.
// The one-dimensional computation below is iterated to its fixed point and must agree with the
// thermal-contact passes within 1 %.
//
// Conduction: the log profiles of Cylinders with the interface's h (touching: h(p) of the table;
// open: gas / gap).
// Lame with a temperature T(r) = A + B ln r in a ring r0 < r < r1 (plane strain, reference 0): with
// I(r) = int_r0^r T s ds = [A s^2 / 2 + B (s^2 ln s / 2 - s^2 / 4)]_r0^r,
//   u(r)       = (1 + nu) / (1 - nu) alpha I(r) / r + C1 r + C2 / r,
//   sigma_r(r) = E / ((1 + nu)(1 - 2 nu)) C1 - E / (1 + nu) C2 / r^2 - E alpha / (1 - nu) I(r) / r^2
// (from sigma_r = E / ((1 + nu)(1 - 2 nu)) ((1 - nu) u' + nu u / r - (1 + nu) alpha T)). The five
// unknowns C1, C2 of each ring and the contact pressure p solve sigma_r(a) = 0, sigma_r(b) = -p,
// sigma_r(b + g) = -p, sigma_r(c) = 0 and closure u_inner(b) - u_outer(b + g) = g; p <= 0 means the
// gap stays open (p = 0, gap g - u_inner(b) + u_outer(b + g)).
struct Ring1D {
  Cylinders t;
  double E = 1.0e6, nu = 0.3, alpha = 1.0e-5;
  InterfaceConductance conductance;

  struct State {
    double p = 0.0;    // contact pressure (0 when open)
    double gap = 0.0;  // open gap (0 when touching)
    double h = 0.0;    // the interface's conductance
  };

  /// T = A + B ln r in each ring for interface conductance h.
  [[nodiscard]] std::array<Eigen::Vector2d, 2> profiles(double h) const {
    Cylinders c = t;
    c.h = h;
    const double q = c.flow();
    return {Eigen::Vector2d(t.Ta + q / t.k1 * std::log(t.a), -q / t.k1),
            Eigen::Vector2d(t.Tc + q / t.k2 * std::log(t.c), -q / t.k2)};
  }

  /// Contact pressure and gap for interface conductance h (Lame, the closure condition).
  [[nodiscard]] State mechanics(double h) const {
    const auto T = profiles(h);
    const double inside = t.b + t.g;
    const auto I = [](const Eigen::Vector2d& AB, double r0, double r) {
      const auto F = [&AB](double s) { return AB[0] * s * s / 2.0 + AB[1] * (s * s * std::log(s) / 2.0 - s * s / 4.0); };
      return F(r) - F(r0);
    };
    const double s1 = E / ((1.0 + nu) * (1.0 - 2.0 * nu));
    const double s2 = -E / (1.0 + nu);
    const double st = -E * alpha / (1.0 - nu);
    const double ut = (1.0 + nu) / (1.0 - nu) * alpha;
    // Rows: sigma_r(a) = 0, sigma_r(b) + p = 0, sigma_r(b + g) + p = 0, sigma_r(c) = 0, closure.
    Eigen::Matrix<double, 5, 5> M = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> f = Eigen::Matrix<double, 5, 1>::Zero();
    const auto stress_row = [&](int row, int ring, double r, double r0, const Eigen::Vector2d& AB, double p) {
      M(row, 2 * ring) = s1;
      M(row, 2 * ring + 1) = s2 / (r * r);
      M(row, 4) = p;
      f[row] = -st * I(AB, r0, r) / (r * r);
    };
    stress_row(0, 0, t.a, t.a, T[0], 0.0);
    stress_row(1, 0, t.b, t.a, T[0], 1.0);
    stress_row(2, 1, inside, inside, T[1], 1.0);
    stress_row(3, 1, t.c, inside, T[1], 0.0);
    const double thermal_in = ut * I(T[0], t.a, t.b) / t.b;  // u_inner(b) = thermal_in + C1 b + C2 / b
    const double thermal_out = ut * I(T[1], inside, inside) / inside;
    M(4, 0) = t.b;
    M(4, 1) = 1.0 / t.b;
    M(4, 2) = -inside;
    M(4, 3) = -1.0 / inside;
    f[4] = t.g - thermal_in + thermal_out;
    const Eigen::Matrix<double, 5, 1> x = M.fullPivLu().solve(f);
    if (x[4] > 0.0) return {x[4], 0.0, closed_conductance(conductance, x[4])};
    // Open: the rings expand freely (p = 0); the gap left is g minus the closure.
    M.col(4).setZero();
    M.row(4).setZero();
    M(4, 4) = 1.0;
    f[4] = 0.0;
    const Eigen::Matrix<double, 5, 1> free = M.fullPivLu().solve(f);
    const double closure = thermal_in + free[0] * t.b + free[1] / t.b - thermal_out - free[2] * inside - free[3] / inside;
    const double gap = t.g - closure;
    return {0.0, gap, conductance.gas_conductivity / gap};
  }

  /// The fixed point h -> T -> (p, gap) -> h, from the open gap at its initial width.
  [[nodiscard]] State solve() const {
    double h = conductance.gas_conductivity / t.g;
    for (int pass = 0; pass < 200; ++pass) {
      const State s = mechanics(h);
      if (std::abs(s.h - h) <= 1.0e-13 * h) return s;
      h = s.h;
    }
    ADD_FAILURE() << "the one-dimensional fixed point did not settle";
    return mechanics(h);
  }
};

/// The ring model: the cylinders with thermal expansion, every node held at u_z = 0.
CylinderModel expanding_rings(const Ring1D& ring, int n) {
  CylinderModel c = cylinders(ring.t, n, ring.conductance);
  Model& m = c.model;
  for (Material& mat : m.materials) mat.table[0].alpha1 = mat.table[0].alpha2 = mat.table[0].alpha3 = ring.alpha;
  testing::fill_temperatures(m, 0.0);
  for (std::size_t k = 0; k < m.nodes.size(); ++k) testing::constrain(m, static_cast<int>(k), std::nullopt, 0.0);
  return c;
}

Ring1D heated_ring() {
  Ring1D ring;
  ring.t.g = 1.0e-3;
  ring.t.Ta = 400.0;
  ring.t.Tc = 0.0;
  ring.conductance = InterfaceConductance{{{0.0, 1.0}, {2000.0, 8.0}}, 1.0e-3};
  return ring;
}

TEST(ThermalContact, RingHeatedFromInsideGrowsIntoAColdRingAsTheOneDimensionalFixedPointSays) {
  const Ring1D ring = heated_ring();
  const Ring1D::State exact = ring.solve();
  // The fixed point is inside the table (h interpolated in p), far from the gas's h = 1, so both the
  // pressure and the conductance it sets are tested.
  ASSERT_GT(exact.p, 100.0);
  ASSERT_LT(exact.p, 1900.0);
  const CylinderModel c = expanding_rings(ring, 8);
  const Solution s = solve_with_heat(c.model);
  ASSERT_TRUE(s.thermal.has_value());
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_GE(s.thermal->passes, 3);
  ASSERT_EQ(s.contact.size(), 1u);
  for (const ContactPointResult& point : s.contact[0].points) {
    EXPECT_NEAR(point.pressure, exact.p, 0.01 * exact.p) << "side A point at z = " << point.z;
  }
  Cylinders t = ring.t;
  t.h = exact.h;
  const int n = c.inner.ni;
  for (const int k : c.inner.nodes) {
    EXPECT_NEAR(s.thermal->T[k], t.exact(c.model.nodes[k].r, true), 0.01 * (t.Ta - t.Tc)) << "inner node " << k;
  }
  for (const int k : c.outer.nodes) {
    EXPECT_NEAR(s.thermal->T[k], t.exact(c.model.nodes[k].r, false), 0.01 * (t.Ta - t.Tc)) << "outer node " << k;
  }
  const double jump = s.thermal->T[c.inner.at(n, 0)] - s.thermal->T[c.outer.at(0, 0)];
  EXPECT_NEAR(jump, t.jump(), 0.01 * t.jump());
}

// Transient, the same rings starting cold: the first interval conducts through the gas only; at each
// output time the stress step's contact state sets the conductances of the next (transient_coupling.hpp).
// By t = 32 (about a hundred of the slowest mode's time constants) the run must sit on the steady
// coupled solution within 0.5 %, having refactorized only when an output time changed the conductances.
TEST(ThermalContact, TransientRunWithContactConductanceApproachesTheSteadyCoupledSolution) {
  const Ring1D ring = heated_ring();
  CylinderModel c = expanding_rings(ring, 4);
  Model& m = c.model;
  const auto [steady, s] = testing::steady_then_settling_transient(m);
  ASSERT_TRUE(s.thermal.has_value() && steady.thermal.has_value());
  ASSERT_EQ(s.steps.size(), 7u);
  EXPECT_EQ(s.thermal->time_steps, 128);
  EXPECT_LE(s.thermal->factorizations, 7);
  // The early interval ran with the gas's conductance, the late ones touching: the first output time's
  // interface jump is far larger than the last one's.
  const int n = c.inner.ni;
  const auto jump = [&](const std::vector<double>& T) { return T[c.inner.at(n, 0)] - T[c.outer.at(0, 0)]; };
  EXPECT_GT(jump(s.thermal->history.front()), 1.5 * jump(s.thermal->history.back()));
  for (std::size_t k = 0; k < m.nodes.size(); ++k) {
    EXPECT_NEAR(s.thermal->T[k], steady.thermal->T[k], 0.005 * (ring.t.Ta - ring.t.Tc)) << "node " << k;
  }
  ASSERT_EQ(s.contact.size(), 1u);
  for (std::size_t j = 0; j < s.contact[0].points.size(); ++j) {
    const double p = steady.contact[0].points[j].pressure;
    EXPECT_NEAR(s.contact[0].points[j].pressure, p, 0.005 * p) << "side A point " << j;
  }
}

}  // namespace
}  // namespace saasgaps
