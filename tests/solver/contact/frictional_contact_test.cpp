// FrictionalContact at solver level: a block pressed onto a base (matching meshes, node-to-node
// pairs at zero gap, plane strain, one material), then pushed sideways by a displacement prescribed
// on its top, increment by increment, then pushed back.
#include "solver/contact/frictional_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <array>
#include <vector>

#include "solver/base/errors.hpp"
#include "solver/contact/exact_contact.hpp"
#include "support/friction_models.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

using testing::Cylinders;
using testing::Grid;
using System = testing::CoupledSystem;

constexpr double width = 2.0;   // both bodies
constexpr double height = 0.5;  // each body
constexpr double E = Cylinders::E, nu = Cylinders::nu;
constexpr double press = 10.0;  // N, the total normal force on the block's top

/// The base [0, width] x [-height, 0] held at its bottom, and the block [0, width] x [0, height] on
/// it, ni x layers quads each. merged: one mesh (the block shares the base's top nodes), else two
/// with coincident nodes on z = 0.
struct Blocks {
  Model model;
  Grid base, block;
  std::vector<int> top;  ///< the block's top nodes, left to right
  ContactPairs pairs;    ///< base node (side a) to block node (side b), normal +z; none when merged
};

Blocks blocks(int ni, int layers, bool merged) {
  Blocks b;
  Model& m = b.model;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, E, nu)};
  if (merged) {
    b.base = testing::add_grid(
        m, ni, 2 * layers, [](double s, double t) { return Vec2(width * s, -height + 2 * height * t); }, 0);
    for (int i = 0; i <= ni; ++i) b.top.push_back(b.base.at(i, 2 * layers));
  } else {
    b.base = testing::add_grid(m, ni, layers, [](double s, double t) { return Vec2(width * s, -height + height * t); }, 0);
    b.block = testing::add_grid(m, ni, layers, [](double s, double t) { return Vec2(width * s, height * t); }, 0);
    for (int i = 0; i <= ni; ++i) {
      b.top.push_back(b.block.at(i, layers));
      ContactPair p;
      p.node = {b.base.at(i, layers), b.block.at(i, 0)};
      p.weight = {-1.0, 1.0};
      p.normal = Vec2(0.0, 1.0);
      p.g0 = 0.0;
      p.area = width / ni * (i == 0 || i == ni ? 0.5 : 1.0);
      b.pairs.pairs.push_back(p);
    }
  }
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= ni; ++i) testing::constrain(m, b.base.at(i, 0), 0.0, 0.0);
  return b;
}

/// The model of one load state: the top pressed by `normal` (consistent nodal loads of a uniform
/// pressure) and pushed along r by `push` (prescribed on every top node), or by a force `shear`
/// when push_by_force.
Model loaded(const Blocks& b, double normal, double push, bool push_by_force = false, double shear = 0.0) {
  Model m = b.model;
  const int ni = static_cast<int>(b.top.size()) - 1;
  for (int i = 0; i <= ni; ++i) {
    const double share = (i == 0 || i == ni ? 0.5 : 1.0) / ni;
    m.loads.nodal_forces.push_back({b.top[i], push_by_force ? shear * share : 0.0, -normal * share});
    if (!push_by_force) testing::constrain(m, b.top[i], push, std::nullopt);
  }
  return m;
}

/// One converged increment.
struct Increment {
  double push = 0.0;
  std::vector<double> u;       ///< free displacements
  std::vector<double> x;       ///< (u_r, u_z) per node
  FrictionState state;         ///< after finish_increment
  FrictionState solved;        ///< as the solve left it (position, previous of this increment)
  FrictionReport report;
  double shear = 0.0;          ///< sum of the contact forces on the block along r
  double normal = 0.0;         ///< the same along z
  double imbalance = 0.0;      ///< max |K u - f - C^T lambda|
};

/// One increment per load state of `path` (all with the same prescribed components), from `state`
/// (the end of an earlier increment, or nothing), each with a system and solver of its own.
std::vector<Increment> run(const Model& model, const ContactPairs& pairs, double mu, const std::vector<Model>& path,
                           FrictionState state = {}) {
  System system(path.front(), pairs);
  FrictionalContact contact(model, system.dofs(), system.pattern(), pairs, std::vector<double>(pairs.pairs.size(), mu));
  std::vector<Increment> out;
  for (const Model& now : path) {
    const std::vector<double> f = system.rhs(now);
    Increment inc;
    inc.u.assign(f.size(), 0.0);
    inc.report = contact.solve(system.cholesky(), system.values(), f, state, inc.u);
    inc.solved = state;
    std::vector<double> load(f.size(), 0.0);
    for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
      const Vec2 n = pairs.pairs[i].normal;
      const Vec2 t(-n.y(), n.x());
      const Vec2 on_block = state.normal_force[i] * n + state.tangential_force[i] * t;
      inc.shear += on_block.x();
      inc.normal += on_block.y();
      contact.rows().add_load(FrictionalContact::normal_row(i), state.normal_force[i], load);
      contact.rows().add_load(FrictionalContact::tangential_row(i), state.tangential_force[i], load);
    }
    inc.imbalance = system.imbalance(inc.u, f, load);
    inc.x = system.full(now, inc.u);
    finish_increment(state);
    inc.state = state;
    out.push_back(std::move(inc));
  }
  return out;
}

/// The block pressed (one increment), then pushed to each value of `pushes`, one increment each.
std::vector<Increment> run(const Blocks& b, double mu, const std::vector<double>& pushes) {
  std::vector<Model> path{loaded(b, press, 0.0)};
  for (const double push : pushes) path.push_back(loaded(b, press, push));
  std::vector<Increment> out = run(b.model, b.pairs, mu, path);
  for (std::size_t k = 1; k < out.size(); ++k) out[k].push = pushes[k - 1];
  return out;
}

std::vector<double> ramp(double from, double to, int increments) {
  std::vector<double> path;
  for (int k = 1; k <= increments; ++k) path.push_back(from + (to - from) * k / increments);
  return path;
}

double largest(std::span<const double> x) {
  double m = 0.0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

constexpr double mu = 0.3;
constexpr double far = 0.02;  // the push: several times what the interface takes to slip everywhere

/// Pushes to `far` in `out` increments, then back towards 0 in `back` increments of far / 20.
std::vector<double> there_and_back(int out, int back) {
  std::vector<double> path = ramp(0.0, far, out);
  const std::vector<double> returning = ramp(far, far * (1.0 - back / 20.0), back);
  path.insert(path.end(), returning.begin(), returning.end());
  return path;
}

TEST(FrictionalContact, PushedBlockRisesToMuNThenSlipsEverywhereAndUnloadingShowsHysteresis) {
  const Blocks b = blocks(8, 2, false);
  const std::vector<Increment> run_ = run(b, mu, there_and_back(20, 20));
  const std::size_t points = b.pairs.pairs.size();
  // The cost (docs/contact.md, "Friction"): one factorization in the press and one in the first
  // push (the factor of "every touching point sticks", kept from then on while the same points
  // touch); 1 to 3 solves when every point sticks or every point slips from the start, at most 15
  // (3 active sets) otherwise.
  int factorizations = 0;
  for (const Increment& inc : run_) {
    EXPECT_LE(inc.report.factorizations, 1) << "push " << inc.push;
    factorizations += inc.report.factorizations;
    EXPECT_LE(inc.report.active_set_iterations, 3) << "push " << inc.push;
    const bool uniform = inc.report.active_set_iterations == 1 &&
                         (inc.report.sticking == static_cast<int>(points) || inc.report.slipping == static_cast<int>(points));
    EXPECT_LE(inc.report.multiplier_iterations, uniform ? 3 : 15) << "push " << inc.push;
  }
  EXPECT_EQ(factorizations, 2);

  // Pressed: everything sticks, the normal force is N, no shear.
  EXPECT_NEAR(run_[0].normal, press, 1e-9 * press);
  EXPECT_NEAR(run_[0].shear, 0.0, 1e-9 * press);
  EXPECT_EQ(run_[0].report.sticking, static_cast<int>(points));

  // Loading: the friction force on the block opposes the push (-r) and rises to mu N, then holds.
  double before = 0.0;
  bool below = false;
  for (int k = 1; k <= 20; ++k) {
    const Increment& inc = run_[k];
    const double shear = -inc.shear;
    EXPECT_GE(shear, before - 1e-9 * press) << "increment " << k;
    EXPECT_LE(shear, mu * press * (1 + 1e-9)) << "increment " << k;
    below = below || shear < 0.9 * mu * press;
    before = shear;
  }
  EXPECT_TRUE(below) << "the shear rises through the stick range";
  for (int k = 15; k <= 20; ++k) {
    EXPECT_NEAR(-run_[k].shear, mu * press, 0.005 * mu * press) << "increment " << k;
    EXPECT_EQ(run_[k].report.slipping, static_cast<int>(points)) << "increment " << k;
  }
  // Unloading: the first step back sticks (the shear falls but keeps its sign), the end slips back.
  EXPECT_LT(-run_[21].shear, 0.95 * mu * press);
  EXPECT_GT(run_[21].report.sticking, 0);
  const Increment& end = run_.back();
  EXPECT_NEAR(end.shear, mu * press, 0.005 * mu * press) << "back at push 0 the shear is reversed";
  EXPECT_EQ(end.report.slipping, static_cast<int>(points));
  // Hysteresis: the same push, two shears, and the block does not return to where it was.
  const Increment& up = run_[10];
  const Increment& down = run_[30];
  EXPECT_DOUBLE_EQ(up.push, down.push);
  EXPECT_GT(down.shear - up.shear, mu * press);
  for (std::size_t i = 0; i < points; ++i) {
    EXPECT_GT(end.state.slip[i], 0.5 * far) << "point " << i;
    EXPECT_GT(std::abs(end.state.previous[i]), 1e-4) << "a residual offset of block against base, point " << i;
  }
}

TEST(FrictionalContact, ARunResumedFromTheStateBetweenIncrementsIsTheUninterruptedRunToTheLastBit) {
  // What a restart state must carry is FrictionState: resumed with a new system, factorization and
  // solver after push 12 (partly stuck, on the way back), the rest is identical.
  const Blocks b = blocks(8, 2, false);
  const std::vector<double> pushes = there_and_back(10, 10);
  const std::vector<Increment> whole = run(b, mu, pushes);
  for (const std::size_t k : {std::size_t{5}, std::size_t{12}}) {
    std::vector<Model> rest;
    for (std::size_t j = k; j < pushes.size(); ++j) rest.push_back(loaded(b, press, pushes[j]));
    const std::vector<Increment> resumed = run(b.model, b.pairs, mu, rest, whole[k].state);
    for (std::size_t j = 0; j < resumed.size(); ++j) {
      const Increment& one = whole[k + 1 + j];
      const Increment& two = resumed[j];
      EXPECT_EQ(one.u, two.u) << "resumed after increment " << k << ", increment " << k + 1 + j;
      EXPECT_EQ(one.state.tangential_force, two.state.tangential_force);
      EXPECT_EQ(one.state.slip, two.state.slip);
      EXPECT_EQ(one.state.state, two.state.state);
    }
  }
}

TEST(FrictionalContact, CoulombHoldsPointByPointToRoundOffInEveryIncrement) {
  const Blocks b = blocks(8, 2, false);
  const std::vector<Increment> run_ = run(b, mu, there_and_back(20, 10));
  int stick = 0, slip = 0;
  for (std::size_t k = 0; k < run_.size(); ++k) {
    const Increment& inc = run_[k];
    const double length = largest(inc.x);
    const double force = press;
    EXPECT_LT(inc.imbalance, 1e-10 * force) << "increment " << k;
    EXPECT_LT(inc.report.complementarity, 1e-10) << "increment " << k;
    EXPECT_LT(inc.report.friction_residual, 1e-10) << "increment " << k;
    for (std::size_t i = 0; i < b.pairs.pairs.size(); ++i) {
      const ContactPair& p = b.pairs.pairs[i];
      const Vec2 ua(inc.x[2 * p.node[0]], inc.x[2 * p.node[0] + 1]);
      const Vec2 ub(inc.x[2 * p.node[1]], inc.x[2 * p.node[1] + 1]);
      const double g = p.normal.dot(ub - ua);
      const double h = Vec2(-p.normal.y(), p.normal.x()).dot(ub - ua);
      const double v = h - inc.solved.previous[i];
      const double ln = inc.solved.normal_force[i];
      const double lt = inc.solved.tangential_force[i];
      const auto state = static_cast<SlipState>(inc.solved.state[i]);
      EXPECT_DOUBLE_EQ(inc.solved.position[i] + 1.0, h + 1.0);
      ASSERT_NE(state, SlipState::open) << "pressed: every point touches";
      EXPECT_NEAR(g, 0.0, 1e-10 * length) << "increment " << k << " point " << i;
      EXPECT_GT(ln, 0.0);
      if (state == SlipState::stick) {
        ++stick;
        EXPECT_NEAR(v, 0.0, 1e-10 * length) << "increment " << k << " point " << i;
        EXPECT_LE(std::abs(lt), mu * ln + 1e-10 * force) << "increment " << k << " point " << i;
      } else {
        ++slip;
        const int s = inc.solved.direction[i];
        EXPECT_NEAR(lt, -mu * ln * s, 1e-10 * force) << "increment " << k << " point " << i;
        EXPECT_GE(s * v, -1e-10 * length) << "slips along its direction, increment " << k << " point " << i;
      }
    }
  }
  EXPECT_GT(stick, 0);
  EXPECT_GT(slip, 0);
}

TEST(FrictionalContact, ZeroFrictionIsTheFrictionlessExactAnswer) {
  const Blocks b = blocks(8, 2, false);
  const std::vector<double> path = ramp(0.0, far, 4);
  const std::vector<Increment> frictional = run(b, 0.0, path);

  System system(loaded(b, press, 0.0), b.pairs);
  ExactContact exact(b.model, system.dofs(), system.pattern(), b.pairs);
  ContactState state;
  for (std::size_t k = 0; k < frictional.size(); ++k) {
    const Model now = loaded(b, press, frictional[k].push);
    const std::vector<double> f = system.rhs(now);
    std::vector<double> u(f.size(), 0.0);
    exact.solve(system.cholesky(), system.values(), f, state, u);
    const double scale = largest(u);
    for (std::size_t e = 0; e < u.size(); ++e) {
      ASSERT_NEAR(frictional[k].u[e], u[e], 1e-10 * scale) << "increment " << k << " equation " << e;
    }
    for (std::size_t i = 0; i < state.force.size(); ++i) {
      EXPECT_NEAR(frictional[k].solved.normal_force[i], state.force[i], 1e-10 * press);
      EXPECT_EQ(frictional[k].solved.tangential_force[i], 0.0);
    }
    EXPECT_EQ(frictional[k].report.slipping, static_cast<int>(state.force.size()));
  }
}

TEST(FrictionalContact, HugeFrictionIsTheTiedMergedMesh) {
  // A push small enough that every point stays pressed (no corner lifts off).
  const std::vector<double> path = ramp(0.0, 0.1 * far, 5);
  const Blocks b = blocks(8, 2, false);
  const std::vector<Increment> tied = run(b, 1.0e6, path);
  const Blocks merged = blocks(8, 2, true);
  System system(loaded(merged, press, 0.0), merged.pairs);
  for (std::size_t k = 0; k < tied.size(); ++k) {
    EXPECT_EQ(tied[k].report.sticking, static_cast<int>(b.pairs.pairs.size())) << "increment " << k;
    const Model now = loaded(merged, press, tied[k].push);
    const std::vector<double> f = system.rhs(now);
    system.cholesky().factorize(system.values());
    std::vector<double> u(f.size(), 0.0);
    system.cholesky().solve(f, u);
    const std::vector<double> x = system.full(now, u);
    const double scale = largest(x);
    // Node (i, j) of the merged mesh is the base's (i, j) for j <= 2, the block's (i, j - 2) above.
    for (int j = 0; j <= 4; ++j) {
      for (int i = 0; i <= 8; ++i) {
        const int one = merged.base.at(i, j);
        const int two = j <= 2 ? b.base.at(i, j) : b.block.at(i, j - 2);
        for (int c = 0; c < 2; ++c) {
          EXPECT_NEAR(tied[k].x[2 * two + c], x[2 * one + c], 1e-9 * scale)
              << "increment " << k << " node (" << i << ", " << j << ") component " << c;
        }
      }
    }
  }
}

TEST(FrictionalContact, AShearForceAboveMuNSlidesTheBlockAwayWithAClearError) {
  const Blocks b = blocks(4, 1, false);
  // The block held along r by friction alone: its top is loaded, not prescribed.
  System system(loaded(b, press, 0.0, true, 0.0), b.pairs);
  FrictionalContact contact(b.model, system.dofs(), system.pattern(), b.pairs,
                            std::vector<double>(b.pairs.pairs.size(), mu));
  FrictionState state;
  std::vector<double> u(static_cast<std::size_t>(system.dofs().size()), 0.0);
  // Below mu N the block holds (partial slip at most) ...
  const FrictionReport held =
      contact.solve(system.cholesky(), system.values(), system.rhs(loaded(b, press, 0.0, true, 0.5 * mu * press)), state, u);
  EXPECT_GT(held.sticking, 0);
  finish_increment(state);
  // ... above it nothing can.
  try {
    contact.solve(system.cholesky(), system.values(), system.rhs(loaded(b, press, 0.0, true, 1.2 * mu * press)), state, u);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("slides away"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("5 contact points slipping"), std::string::npos) << e.what();
  }
}

TEST(FrictionalContact, CattaneoMindlinStickZoneHalfWidthWithinOneElementPlusFivePercent) {
  // Interface nodes every h = 0.1, for a near 1.
  constexpr double spacing = 0.1;
  const Cylinders c = testing::cylinders(0.18, spacing);
  const auto sheared = [&c](double Q) { return testing::sheared(c, Q); };
  const double P = run(c.model, c.pairs, mu, {sheared(0.0)}).front().normal;
  const std::vector<double> ratios{0.25, 0.5, 0.75};
  std::vector<Model> path{sheared(0.0)};
  for (const double r : ratios) path.push_back(sheared(r * mu * P));
  const std::vector<Increment> run_ = run(c.model, c.pairs, mu, path);
  const double E_star = E / (2 * (1 - nu * nu));
  for (std::size_t k = 0; k < run_.size(); ++k) {
    const Increment& inc = run_[k];
    const double Pk = inc.normal;
    const double Q = std::abs(inc.shear);
    const double a = std::sqrt(4 * Pk * Cylinders::radius / (std::numbers::pi * E_star));
    const double c_theory = a * std::sqrt(1 - Q / (mu * Pk));
    // Each side: the stick zone ends between its outermost sticking node and the next node out.
    double contact_edge = 0.0;
    std::array<double, 2> stick_edge{0.0, 0.0}, slip_start{a, a};
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      const auto state = static_cast<SlipState>(inc.solved.state[i]);
      const std::size_t side = c.x[i] < 0 ? 0 : 1;
      const double at = std::abs(c.x[i]);
      if (state != SlipState::open) contact_edge = std::max(contact_edge, at);
      if (state == SlipState::stick) stick_edge[side] = std::max(stick_edge[side], at);
      if (state == SlipState::slip) slip_start[side] = std::min(slip_start[side], at);
    }
    EXPECT_NEAR(contact_edge, a, spacing) << "increment " << k << ": Hertz";
    EXPECT_LT(inc.report.friction_residual, 1e-10);
    for (std::size_t side = 0; side < 2; ++side) {
      const double c_measured = k == 0 ? contact_edge : 0.5 * (stick_edge[side] + slip_start[side]);
      EXPECT_NEAR(c_measured / a, c_theory / a, spacing / a + 0.05 * c_theory / a)
          << "increment " << k << " Q / (mu P) = " << Q / (mu * Pk) << " side " << side;
    }
    // The cost (docs/contact.md, "Friction"): a factorization in the press and in the first shear
    // increment, none after (the same points touch: the factor of all of them sticking is kept),
    // a few active sets.
    EXPECT_EQ(inc.report.factorizations, k <= 1 ? 1 : 0) << "increment " << k;
    EXPECT_LE(inc.report.active_set_iterations, 5) << "increment " << k;
    EXPECT_LE(inc.report.multiplier_iterations, 10) << "increment " << k;
  }
}

}  // namespace
}  // namespace saasgaps
