// Heat runs on models with nodes no solid element has: report problems 2 and 3's ground nodes
// (corners of their gap elements only) and one node of no element. Nothing conducts to them unless
// the gaps conduct, so their temperature is not a result of the conduction: it stays at the reference
// temperature in a steady run and at the initial temperature in a transient one
// (solver/thermal/thermal_system.hpp, docs/model.md). Before that rule their zero rows made the conduction
// matrix singular.
//
// Problem 2 is a strip of nine elements heated uniformly by 1100 over its reference temperature,
// resting on gaps to the ground. Here one end of the strip is held at reference + 1100, the rest is
// insulated: the steady conduction heats the whole strip to that temperature, so the stresses must
// be problem 2's own; gap elements take no temperature, so the ground nodes' cannot change them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "solver/thermal/thermal_analysis.hpp"
#include "support/examples.hpp"

namespace saasgaps {
namespace {

constexpr double reference = 70.0;
constexpr double initial = 40.0;    // transient runs
constexpr double heating = 1100.0;  // problem 2's temperature over its reference (0 there)

struct GapNodes {
  Model model;
  std::set<int> ground;  // node indices in gap elements only
  int loose = 0;         // the node index of no element
};

int node_index(const Model& m, int id) {
  const auto it = std::find_if(m.nodes.begin(), m.nodes.end(), [id](const Node& n) { return n.id == id; });
  return static_cast<int>(it - m.nodes.begin());
}

/// The report problem of `example` with `thermal` of the given type: the edge id_a-id_b of its
/// first element held at reference + heating, a conductor with capacity, and a node of no element,
/// held in r and z.
GapNodes heated(const std::string& example, ThermalType type, int id_a, int id_b) {
  GapNodes p;
  Model& m = p.model;
  m = testing::example_model(example);
  m.reference_temperature = reference;
  m.loads.node_temperature.clear();
  for (Material& mat : m.materials) {
    for (PropertyRow& row : mat.table) {
      row.k1 = row.k2 = row.k3 = 2.0;
      row.c = 0.5;
    }
    mat.density = 1.0;
    mat.conducts = mat.stores_heat = true;
  }
  m.nodes.push_back({m.nodes.back().id + 1, 4.0, -3.0});
  p.loose = static_cast<int>(m.nodes.size()) - 1;
  m.constraints.push_back({p.loose, 0.0, 0.0});
  Thermal& thermal = m.thermal.emplace();
  thermal.type = type;
  thermal.boundary.push_back(
      {ThermalBoundary::Kind::temperature, {{0, node_index(m, id_a), node_index(m, id_b)}}, reference + heating, 0.0});
  if (type == ThermalType::transient) {
    thermal.initial_temperature = initial;
    thermal.time_step = 0.5;
    thermal.end_time = 80.0;
    thermal.output_times = {5.0, 20.0, 80.0};
  }
  std::set<int> solid;
  for (const Element& el : m.elements) solid.insert(el.nodes.begin(), el.nodes.begin() + el.node_count);
  for (const GapElement& g : m.gaps->elements) {
    for (int a = 0; a < g.node_count; ++a) {
      if (!solid.contains(g.nodes[a])) p.ground.insert(g.nodes[a]);
    }
  }
  return p;
}

/// Problem 2 heated from the left end of its strip (nodes 14 and 2 of element 1).
GapNodes problem2(ThermalType type) { return heated("report-problem2.json", type, 14, 2); }

TEST(ThermalGapNodes, SteadyRunHoldsGroundNodesAtTheReferenceAndGivesProblem2sStresses) {
  const GapNodes p = problem2(ThermalType::steady);
  ASSERT_EQ(p.ground.size(), 14u);
  const Solution s = solve_with_heat(p.model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_TRUE(s.thermal.has_value());
  const std::vector<double>& T = s.thermal->T;
  for (std::size_t n = 0; n < T.size(); ++n) {
    const int i = static_cast<int>(n);
    if (p.ground.contains(i) || i == p.loose) {
      EXPECT_EQ(T[n], reference) << "node " << p.model.nodes[n].id;
    } else {
      EXPECT_NEAR(T[n], reference + heating, 1e-9 * heating) << "node " << p.model.nodes[n].id;
    }
  }
  // Problem 2 as the report gives it: the strip 1100 over the reference, the ground nodes at 0.
  const Solution given = solve(testing::example_model("report-problem2.json"));
  ASSERT_EQ(given.status, RunStatus::converged);
  ASSERT_EQ(s.nodes.size(), given.nodes.size() + 1);
  double scale = 0.0;
  for (const NodeResult& n : given.nodes) scale = std::max({scale, std::abs(n.u_r), std::abs(n.u_z)});
  ASSERT_GT(scale, 0.0);
  for (std::size_t n = 0; n < given.nodes.size(); ++n) {
    EXPECT_NEAR(s.nodes[n].u_r, given.nodes[n].u_r, 1e-9 * scale) << "node " << given.nodes[n].id;
    EXPECT_NEAR(s.nodes[n].u_z, given.nodes[n].u_z, 1e-9 * scale) << "node " << given.nodes[n].id;
  }
  // Gap states are left out: gap 10's eps_M is 0 in both runs up to round-off (1e-25), whose sign
  // makes it open or partial.
  ASSERT_EQ(s.gaps.size(), given.gaps.size());
  double strain = 0.0;
  for (const GapResult& g : given.gaps) strain = std::max(strain, std::abs(g.eps_m));
  for (std::size_t g = 0; g < s.gaps.size(); ++g) {
    EXPECT_NEAR(s.gaps[g].eps_m, given.gaps[g].eps_m, 1e-9 * strain) << "gap " << given.gaps[g].id;
  }
  double stress = 0.0;
  for (const ElementResult& e : given.elements) stress = std::max(stress, e.stress.cwiseAbs().maxCoeff());
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(s.elements[e].stress[c], given.elements[e].stress[c], 1e-9 * stress)
          << "element " << given.elements[e].id;
    }
  }
}

TEST(ThermalGapNodes, TransientRunKeepsGroundNodesAtTheInitialTemperature) {
  const GapNodes p = problem2(ThermalType::transient);
  const Solution s = solve_with_heat(p.model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_TRUE(s.thermal.has_value());
  const ThermalResult& heat = *s.thermal;
  ASSERT_EQ(heat.history.size(), 3u);
  // A constant step: one factorization, the later steps assemble only their right-hand sides.
  EXPECT_EQ(heat.factorizations, 1);
  const int far_end = node_index(p.model, 23);  // the strip's other end, 9 elements away
  for (std::size_t k = 0; k < heat.history.size(); ++k) {
    SCOPED_TRACE("t = " + std::to_string(heat.times[k]));
    const std::vector<double>& T = heat.history[k];
    const auto at = [&T](int n) { return T[static_cast<std::size_t>(n)]; };
    for (int n : p.ground) EXPECT_EQ(at(n), initial) << "node " << p.model.nodes[n].id;
    EXPECT_EQ(at(p.loose), initial);
    EXPECT_GT(at(far_end), initial);  // the heat has reached the far end
    EXPECT_LT(at(far_end), reference + heating);
    if (k > 0) {
      EXPECT_GT(at(far_end), heat.history[k - 1][static_cast<std::size_t>(far_end)]);
    }
  }
}

TEST(ThermalGapNodes, GapsAtZeroConductanceLeaveTheirGroundNodesOutAndTouchingOnesConductToThem) {
  // Touching gaps conduct, open ones do not (no gas): a ground node takes the strip's temperature
  // through a touching gap, and keeps the reference temperature where all of its gaps are open.
  GapNodes p = problem2(ThermalType::steady);
  p.model.gaps->conductance = InterfaceConductance{{{0.0, 5.0}}, 0.0};
  const Solution s = solve_with_heat(p.model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  std::set<int> touched;
  for (std::size_t g = 0; g < s.gaps.size(); ++g) {
    if (s.gaps[g].state != GapState::closed && s.gaps[g].state != GapState::overclosed) continue;
    const GapElement& gap = p.model.gaps->elements[g];
    touched.insert(gap.nodes.begin(), gap.nodes.begin() + gap.node_count);
  }
  const std::vector<double>& T = s.thermal->T;
  int held = 0, conducted = 0;
  for (int n : p.ground) {
    if (touched.contains(n)) {
      ++conducted;
      EXPECT_NEAR(T[static_cast<std::size_t>(n)], reference + heating, 1e-9 * heating)
          << "node " << p.model.nodes[n].id;
    } else {
      ++held;
      EXPECT_EQ(T[static_cast<std::size_t>(n)], reference) << "node " << p.model.nodes[n].id;
    }
  }
  EXPECT_GT(held, 0);
  EXPECT_GT(conducted, 0);
}

TEST(ThermalGapNodes, Problem3sGroundNodesKeepTheReferenceOrTheInitialTemperature) {
  // Case 1's 19 ground nodes under its retainer's gaps, heated from an edge of element 2 (nodes 3 and 2).
  for (const ThermalType type : {ThermalType::steady, ThermalType::transient}) {
    const bool steady = type == ThermalType::steady;
    SCOPED_TRACE(steady ? "steady" : "transient");
    GapNodes p = heated("report-problem3-case1.json", type, 3, 2);
    if (!steady) p.model.thermal->output_times = {5.0};
    ASSERT_EQ(p.ground.size(), 19u);
    const Solution s = solve_with_heat(p.model);
    ASSERT_EQ(s.status, RunStatus::converged) << s.message;
    const std::vector<double>& T = s.thermal->T;
    for (int n : p.ground) EXPECT_EQ(T[static_cast<std::size_t>(n)], steady ? reference : initial) << "node " << n;
    EXPECT_EQ(T[static_cast<std::size_t>(p.loose)], steady ? reference : initial);
    EXPECT_EQ(*std::max_element(T.begin(), T.end()), reference + heating);
  }
}

}  // namespace
}  // namespace saasgaps
