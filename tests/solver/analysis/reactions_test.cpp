// Support reactions (solver/reactions.hpp): the force the supports exert on each constrained node,
// checked against statics: a bar pulled at one end, an axisymmetric cylinder pressed on its end, a
// block held by rigid supports through gap elements (both contact methods), a restrained thermal
// expansion, and a stepped run.
#include "solver/analysis/reactions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/analysis/analysis.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

const NodeReaction* reaction_of(const Solution& s, int node_id) {
  for (const NodeReaction& r : s.reactions) {
    if (r.id == node_id) return &r;
  }
  return nullptr;
}

/// Sum of the reactions along r and z.
Vec2 total(const Solution& s) {
  Vec2 sum = Vec2::Zero();
  for (const NodeReaction& r : s.reactions) sum += Vec2(r.f_r, r.f_z);
  return sum;
}

/// A bar [0, 4] x [0, 1] of 4 x 1 quads, plane stress.
Model bar() {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.thickness = 0.5;
  m.materials = {testing::isotropic_material(1, 30.0e6, 0.3, 1.0e-5)};
  testing::add_grid(m, 4, 1, [](double s, double t) { return Vec2(4.0 * s, t); }, 0);
  testing::fill_temperatures(m, 0.0);
  return m;
}

TEST(Reactions, ABarInTensionIsHeldByMinusTheAppliedLoad) {
  Model m = bar();
  // Left end held along r, its lower node also along z (statically determinate: free to contract).
  testing::constrain(m, 0, 0.0, 0.0);
  testing::constrain(m, 5, 0.0, std::nullopt);
  constexpr double P = 1000.0;
  m.loads.nodal_forces = {{4, P / 2, 0.0}, {9, P / 2, 0.0}};
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged);
  ASSERT_EQ(s.reactions.size(), 2U);
  // Uniform stress: each end node carries half the load, the reaction is minus the applied load.
  EXPECT_EQ(s.reactions[0].id, m.nodes[0].id);
  EXPECT_NEAR(s.reactions[0].f_r, -P / 2, 1e-9 * P);
  EXPECT_NEAR(s.reactions[0].f_z, 0.0, 1e-9 * P);
  EXPECT_EQ(s.reactions[1].id, m.nodes[5].id);
  EXPECT_NEAR(s.reactions[1].f_r, -P / 2, 1e-9 * P);
  EXPECT_EQ(s.reactions[1].f_z, 0.0) << "u_z of node 5 is free: its support exerts nothing along z";
}

TEST(Reactions, AnAxisymmetricCylinderPressedOnItsEndIsHeldByPressureTimesArea) {
  // A thick cylinder a = 1 .. b = 2, height 1: the bottom held along z, the top under axial
  // pressure p and the bore under internal pressure q (which has no z resultant).
  constexpr double a = 1.0, b = 2.0, p = 500.0, q = 300.0;
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {testing::isotropic_material(1, 10.0e6, 0.3)};
  const testing::Grid g = testing::add_grid(m, 4, 3, [](double s, double t) { return Vec2(a + (b - a) * s, t); }, 0);
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= g.ni; ++i) testing::constrain(m, g.at(i, 0), std::nullopt, 0.0);
  for (int i = 0; i < g.ni; ++i) {
    m.loads.pressures.push_back({i + g.ni * (g.nj - 1), g.at(i, g.nj), g.at(i + 1, g.nj), p, 0.0});
  }
  for (int j = 0; j < g.nj; ++j) m.loads.pressures.push_back({g.ni * j, g.at(0, j), g.at(0, j + 1), q, 0.0});
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged);
  ASSERT_EQ(s.reactions.size(), static_cast<std::size_t>(g.ni + 1));
  const double full_ring = p * std::numbers::pi * (b * b - a * a);
  EXPECT_NEAR(total(s).y(), full_ring, 1e-9 * full_ring);
  for (const NodeReaction& r : s.reactions) {
    EXPECT_EQ(r.f_r, 0.0);
    EXPECT_GT(r.f_z, 0.0) << "node " << r.id << ": the supports push up";
  }
}

/// A block [0, 2] x [1, 2] over rigid supports: a row of nodes at z = 0.99 held in r and z, joined
/// to the block's bottom by gap elements (M axis along z); the block is held along r at its left
/// edge and pressed down by p on its top.
Model block_on_gaps(GapMethod method) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, 10.0e6, 0.3)};
  const testing::Grid block = testing::add_grid(m, 4, 2, [](double s, double t) { return Vec2(2.0 * s, 1.0 + t); }, 0);
  const testing::Grid base = testing::add_grid(m, 4, 1, [](double s, double t) { return Vec2(2.0 * s, 0.99 - t); }, 0);
  m.elements.resize(static_cast<std::size_t>(block.ni * block.nj));  // the base is nodes only
  std::vector<int> below, above;
  for (int i = 0; i <= 4; ++i) {
    below.push_back(base.at(i, 0));
    above.push_back(block.at(i, 0));
  }
  // The base's second row of nodes belongs to no element: drop it (the grid put it last).
  m.nodes.resize(m.nodes.size() - 5);
  testing::fill_temperatures(m, 0.0);
  testing::add_gap_row(m, below, above, [](int) { return 90.0; });
  m.gaps->method = method;
  m.gaps->tensile_schedule = {1.0e4, 1.0e2, 1.0};
  for (int n : below) testing::constrain(m, n, 0.0, 0.0);
  for (int j = 0; j <= block.nj; ++j) testing::constrain(m, block.at(0, j), 0.0, std::nullopt);
  for (int i = 0; i < block.ni; ++i) {
    m.loads.pressures.push_back({i + block.ni * (block.nj - 1), block.at(i, block.nj), block.at(i + 1, block.nj), 1000.0, 0.0});
  }
  return m;
}

TEST(Reactions, SupportsUnderGapElementsCarryTheContactForce) {
  for (GapMethod method : {GapMethod::classic, GapMethod::exact}) {
    SCOPED_TRACE(method == GapMethod::exact ? "exact" : "classic");
    const Model m = block_on_gaps(method);
    const Solution s = solve(m);
    ASSERT_EQ(s.status, RunStatus::converged) << s.message;
    // The gap nodes at the base carry the whole 1000 x 2 (plane strain, thickness 1) upward; the
    // left edge's supports along r balance what the base's supports take along r.
    const Vec2 sum = total(s);
    EXPECT_NEAR(sum.y(), 2000.0, 1e-9 * 2000.0);
    EXPECT_NEAR(sum.x(), 0.0, 1e-9 * 2000.0);
    double base_z = 0.0;
    for (int n = 15; n < 20; ++n) {
      const NodeReaction* r = reaction_of(s, m.nodes[static_cast<std::size_t>(n)].id);
      ASSERT_NE(r, nullptr);
      base_z += r->f_z;
    }
    EXPECT_NEAR(base_z, 2000.0, 1e-9 * 2000.0) << "every upward reaction comes through the gaps";
  }
}

TEST(Reactions, ARestrainedThermalExpansionIsHeldByReactionsThatSumToZero) {
  Model m = bar();
  m.reference_temperature = 0.0;
  for (double& T : m.loads.node_temperature) T = 100.0;
  // Both ends held along r: the bar cannot expand, the supports push it in from both sides.
  for (int n : {0, 5, 4, 9}) testing::constrain(m, n, 0.0, std::nullopt);
  testing::constrain(m, 0, std::nullopt, 0.0);
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged);
  // sigma_rr = -E alpha dT over the section 1 x 0.5 (plane stress, free to expand along z).
  const double thrust = 30.0e6 * 1.0e-5 * 100.0 * 0.5;
  double left = 0.0;
  for (const NodeReaction& r : s.reactions) {
    if (r.id == m.nodes[0].id || r.id == m.nodes[5].id) left += r.f_r;
  }
  EXPECT_NEAR(left, thrust, 1e-9 * thrust) << "the left supports push along +r";
  EXPECT_NEAR(total(s).x(), 0.0, 1e-9 * thrust);
  EXPECT_NEAR(total(s).y(), 0.0, 1e-9 * thrust);
}

TEST(Reactions, ASteppedRunEndsWithTheReactionsOfItsLastLoads) {
  Model m = bar();
  testing::constrain(m, 0, 0.0, 0.0);
  testing::constrain(m, 5, 0.0, std::nullopt);
  m.loads.nodal_forces = {{4, 500.0, 0.0}, {9, 500.0, 0.0}};
  Loads half = m.loads;
  for (NodalForce& f : half.nodal_forces) f.f_r *= 0.5;
  m.steps = {{"half", 2, half, {}}, {"full", 3, m.loads, {}}};
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_NEAR(total(s).x(), -1000.0, 1e-9 * 1000.0);
}

/// Stops the run at the first boundary after `iterations` iterations.
class StopAfter final : public IterationObserver {
 public:
  explicit StopAfter(int iterations) : iterations_(iterations) {}
  void on_iteration(const IterationRecord& row, const RestartState&) override { done_ = row.iteration; }
  bool stop_requested() override { return done_ >= iterations_; }

 private:
  int iterations_;
  int done_ = 0;
};

TEST(Reactions, ARunStoppedBetweenIncrementsHasTheReactionsOfTheIncrementItSolved) {
  Model m = bar();
  testing::constrain(m, 0, 0.0, 0.0);
  testing::constrain(m, 5, 0.0, std::nullopt);
  // 100 of the load goes straight into a support: what the supports carry depends on the load
  // factor even where the bar's stiffness does not.
  m.loads.nodal_forces = {{4, 500.0, 0.0}, {9, 500.0, 0.0}, {0, 100.0, 0.0}};
  m.steps = {{"ramp", 4, m.loads, {}}};
  // A linear bar converges in one iteration per increment: stopped after the first, the run has
  // already begun the second, whose loads are 2/4 of the total; the state is the first's, at 1/4.
  StopAfter stop(1);
  const Solution s = solve(m, &stop);
  ASSERT_EQ(s.status, RunStatus::stopped) << s.message;
  ASSERT_EQ(s.iterations, 1);
  EXPECT_NEAR(total(s).x(), -1100.0 / 4, 1e-9 * 1100.0);
}

TEST(Reactions, NothingSolvedHasNoReactions) {
  Model m = bar();
  testing::constrain(m, 0, 0.0, 0.0);
  testing::constrain(m, 5, 0.0, std::nullopt);
  m.solver.max_iterations = 0;
  EXPECT_TRUE(solve(m).reactions.empty());
}

}  // namespace
}  // namespace saasgaps
