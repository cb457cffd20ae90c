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

#include "contact_conductance.hpp"
#include "support/mesh_builder.hpp"
#include "support/stacked_blocks.hpp"
#include "thermal_analysis.hpp"

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
      const auto& nodes = m.elements[e].nodes;
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

}  // namespace
}  // namespace saasgaps
