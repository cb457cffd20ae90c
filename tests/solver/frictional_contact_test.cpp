// FrictionalContact at solver level: a block pressed onto a base (matching meshes, node-to-node
// pairs at zero gap, plane strain, one material), then pushed sideways by a displacement prescribed
// on its top, increment by increment, then pushed back.
#include "frictional_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <array>
#include <vector>

#include "assembler.hpp"
#include "errors.hpp"
#include "exact_contact.hpp"
#include "material_state.hpp"
#include "stiffness_system.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

using testing::Grid;

constexpr double width = 2.0;   // both bodies
constexpr double height = 0.5;  // each body
constexpr double E = 1000.0, nu = 0.3;
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

/// K of the model on a pattern that also couples each pair's nodes, and the rhs of any load state
/// with the same prescribed components.
class System {
 public:
  System(const Model& model, const ContactPairs& pairs) : dofs_(model) {
    Cliques couplings;
    for (const ContactPair& p : pairs.pairs) {
      std::vector<Index> eqs(2 * p.node.size());
      dofs_.equations(p.node, eqs);
      couplings.add(eqs);
    }
    const Assembler assembler(
        dofs_, model.elements.size(),
        [&model](std::size_t e) { return std::span<const int>(model.elements[e].nodes.data(), 4); }, couplings);
    pattern_ = assembler.pattern();
    StiffnessSystem system(model, dofs_);
    assemble(system, model);
    const CscPattern& plain = system.pattern();
    values_.assign(static_cast<std::size_t>(pattern_.nnz()), 0.0);
    for (Index j = 0; j < plain.n; ++j) {
      for (Index k = plain.colptr[j]; k < plain.colptr[j + 1]; ++k) {
        values_[pattern_.find(plain.rowind[k], j)] = system.values()[k];
      }
    }
    cholesky_ = std::make_unique<SparseCholesky>(pattern_);
  }

  /// f of a load state (its prescribed values lifted: K_fp u_p moved to the right).
  [[nodiscard]] std::vector<double> rhs(const Model& state) const {
    const DofMap dofs(state);
    EXPECT_EQ(dofs.size(), dofs_.size());
    StiffnessSystem system(state, dofs);
    assemble(system, state);
    return {system.rhs().begin(), system.rhs().end()};
  }

  /// (u_r, u_z) per node from the free displacements and the prescribed values of `state`.
  [[nodiscard]] std::vector<double> full(const Model& state, std::span<const double> u) const {
    const DofMap dofs(state);
    std::vector<double> x(2 * state.nodes.size());
    for (std::size_t node = 0; node < state.nodes.size(); ++node) {
      for (int c = 0; c < 2; ++c) {
        const Index eq = dofs.equation(static_cast<int>(node), c);
        x[2 * node + c] = eq >= 0 ? u[eq] : dofs.prescribed(static_cast<int>(node), c);
      }
    }
    return x;
  }

  /// max |K u - f - C^T lambda| over the free equations, C^T lambda given as a load vector.
  [[nodiscard]] double imbalance(std::span<const double> u, std::span<const double> f,
                                 std::span<const double> contact) const {
    std::vector<double> r(u.size(), 0.0);
    for (Index j = 0; j < pattern_.n; ++j) {
      for (Index k = pattern_.colptr[j]; k < pattern_.colptr[j + 1]; ++k) {
        const Index i = pattern_.rowind[k];
        r[i] += values_[k] * u[j];
        if (i != j) r[j] += values_[k] * u[i];
      }
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) worst = std::max(worst, std::abs(r[i] - f[i] - contact[i]));
    return worst;
  }

  const DofMap& dofs() const { return dofs_; }
  const CscPattern& pattern() const { return pattern_; }
  std::span<const double> values() const { return values_; }
  SparseCholesky& cholesky() { return *cholesky_; }

 private:
  static void assemble(StiffnessSystem& system, const Model& model) {
    const SolidMaterials materials(model);
    const MaterialState state = materials.initial();
    system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
  }

  DofMap dofs_;
  CscPattern pattern_;
  std::vector<double> values_;
  std::unique_ptr<SparseCholesky> cholesky_;
};

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

/// One increment per load state of `path` (all with the same prescribed components).
std::vector<Increment> run(const Model& model, const ContactPairs& pairs, double mu, const std::vector<Model>& path) {
  System system(path.front(), pairs);
  FrictionalContact contact(model, system.dofs(), system.pattern(), pairs, std::vector<double>(pairs.pairs.size(), mu));
  std::vector<Increment> out;
  FrictionState state;
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
  // The cost (docs/contact.md, "Friction"): one factorization per increment; 1 to 3 solves when
  // every point sticks or every point slips from the start, at most 25 (3 active sets) otherwise.
  for (const Increment& inc : run_) {
    EXPECT_EQ(inc.report.factorizations, 1) << "push " << inc.push;
    EXPECT_LE(inc.report.active_set_iterations, 3) << "push " << inc.push;
    const bool uniform = inc.report.active_set_iterations == 1 &&
                         (inc.report.sticking == static_cast<int>(points) || inc.report.slipping == static_cast<int>(points));
    EXPECT_LE(inc.report.multiplier_iterations, uniform ? 3 : 25) << "push " << inc.push;
  }

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

/// Cattaneo-Mindlin in plane strain: two bodies of one material (so that normal and tangential
/// responses uncouple) touching along z = 0 with the initial gap x^2 / (2 R) of two cylinders (the
/// node pairs' g0), pressed by a rigid platen on the upper body's top (z prescribed), then sheared by
/// a force Q on that top below mu P. Half-spaces give the Hertz half-width a^2 = 4 P R / (pi E*),
/// 1 / E* = 2 (1 - nu^2) / E, and a central stick zone of half-width c = a sqrt(1 - Q / (mu P)).
/// Interface nodes every h = a / 10 over |x| < 1.3 a, growing by 1.25 out to 8 a; depth 8 a.
struct Cylinders {
  Model model;
  ContactPairs pairs;
  std::vector<double> x;  ///< the interface nodes' r, in the pairs' order
  std::vector<int> top;
};

constexpr double radius = 10.0;
constexpr double spacing = 0.1;  // h, for a near 1

std::vector<double> graded(double uniform_to, double to) {
  std::vector<double> x{0.0};
  while (x.back() < uniform_to - 1e-12) x.push_back(x.back() + spacing);
  double step = spacing;
  while (x.back() < to) x.push_back(x.back() + (step *= 1.25));
  return x;
}

Cylinders cylinders(double sink) {
  Cylinders c;
  Model& m = c.model;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, E, nu)};
  const std::vector<double> half = graded(1.3, 8.0);
  std::vector<double> across(half.rbegin(), half.rend() - 1);
  for (double& v : across) v = -v;
  across.insert(across.end(), half.begin(), half.end());
  const std::vector<double> depth = graded(0.5, 8.0);
  const int ni = static_cast<int>(across.size()) - 1;
  const int nj = static_cast<int>(depth.size()) - 1;
  const auto at = [](const std::vector<double>& v, double s) {
    return v[static_cast<std::size_t>(std::lround(s * (static_cast<double>(v.size()) - 1)))];
  };
  const Grid lower = testing::add_grid(m, ni, nj, [&](double s, double t) {
    return Vec2(at(across, s), -at(depth, 1.0 - t));
  }, 0);
  const Grid upper = testing::add_grid(m, ni, nj, [&](double s, double t) { return Vec2(at(across, s), at(depth, t)); }, 0);
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= ni; ++i) {
    testing::constrain(m, lower.at(i, 0), 0.0, 0.0);
    testing::constrain(m, upper.at(i, nj), std::nullopt, -sink);
    c.top.push_back(upper.at(i, nj));
    ContactPair p;
    p.node = {lower.at(i, nj), upper.at(i, 0)};
    p.weight = {-1.0, 1.0};
    p.normal = Vec2(0.0, 1.0);
    p.g0 = across[i] * across[i] / (2 * radius);
    c.pairs.pairs.push_back(p);
    c.x.push_back(across[i]);
  }
  return c;
}

/// The model with a shear force Q on the upper body's top (consistent loads of a uniform traction).
Model sheared(const Cylinders& c, double Q) {
  Model m = c.model;
  const double span = m.nodes[c.top.back()].r - m.nodes[c.top.front()].r;
  for (std::size_t i = 0; i < c.top.size(); ++i) {
    const double left = i == 0 ? 0.0 : m.nodes[c.top[i]].r - m.nodes[c.top[i - 1]].r;
    const double right = i + 1 == c.top.size() ? 0.0 : m.nodes[c.top[i + 1]].r - m.nodes[c.top[i]].r;
    m.loads.nodal_forces.push_back({c.top[i], Q * (left + right) / (2 * span), 0.0});
  }
  return m;
}

TEST(FrictionalContact, CattaneoMindlinStickZoneHalfWidthWithinOneElementPlusFivePercent) {
  const Cylinders c = cylinders(0.18);
  const double P = run(c.model, c.pairs, mu, {sheared(c, 0.0)}).front().normal;
  const std::vector<double> ratios{0.25, 0.5, 0.75};
  std::vector<Model> path{sheared(c, 0.0)};
  for (const double r : ratios) path.push_back(sheared(c, r * mu * P));
  const std::vector<Increment> run_ = run(c.model, c.pairs, mu, path);
  const double E_star = E / (2 * (1 - nu * nu));
  for (std::size_t k = 0; k < run_.size(); ++k) {
    const Increment& inc = run_[k];
    const double Pk = inc.normal;
    const double Q = std::abs(inc.shear);
    const double a = std::sqrt(4 * Pk * radius / (std::numbers::pi * E_star));
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
    // The cost (docs/contact.md, "Friction"): one factorization per increment, a few active sets.
    EXPECT_EQ(inc.report.factorizations, 1) << "increment " << k;
    EXPECT_LE(inc.report.active_set_iterations, 5) << "increment " << k;
    EXPECT_LE(inc.report.multiplier_iterations, 13) << "increment " << k;
  }
}

}  // namespace
}  // namespace saasgaps
