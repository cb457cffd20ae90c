// The contact seam (contact_method.hpp): the factory's choice, each built-in method's evaluation and
// verdict on small cases, and a toy penalty method, written only here, solving the ring fit through
// the seam.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "solver/analysis/analysis.hpp"
#include "solver/analysis/contact_registry.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/base/errors.hpp"
#include "solver/contact/contact_method.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/gaps/gap_elements.hpp"
#include "solver/gaps/gap_modulus_method.hpp"
#include "solver/gaps/node_pair_method.hpp"
#include "support/mesh_builder.hpp"
#include "support/ring_fit.hpp"

namespace saasgaps {
namespace {

constexpr double g0 = 0.1;

/// `count` separate gap quads, plane stress, unit width: gap k joins wall nodes (k, 0), (k + 1, 0)
/// to face nodes (k + 1, g0), (k, g0), M at 90 degrees, floor modulus 1 (schedule 20, 5, 1).
Model separate_gaps(int count, GapMethod method) {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.gaps.emplace();
  m.gaps->method = method;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
  for (int k = 0; k < count; ++k) {
    const int first = static_cast<int>(m.nodes.size());
    const double x = 2.0 * k;
    m.nodes.push_back({first + 1, x, 0.0});
    m.nodes.push_back({first + 2, x + 1.0, 0.0});
    m.nodes.push_back({first + 3, x + 1.0, g0});
    m.nodes.push_back({first + 4, x, g0});
    m.gaps->elements.push_back({100 + k, {first, first + 1, first + 2, first + 3}, 4, 90.0});
  }
  testing::fill_temperatures(m, 0.0);
  return m;
}

/// Full displacement vector: gap k's face nodes moved by face_dz[k] along z, the wall held.
std::vector<double> faces_moved(const Model& m, const std::vector<double>& face_dz) {
  std::vector<double> u(2 * m.nodes.size(), 0.0);
  for (std::size_t k = 0; k < face_dz.size(); ++k) {
    u[2 * (4 * k + 2) + 1] = face_dz[k];
    u[2 * (4 * k + 3) + 1] = face_dz[k];
  }
  return u;
}

/// The system a method assembles into: the model's numbering and pattern, solids (none here) at zero.
struct System {
  explicit System(const Model& m) : dofs(m), system(m, dofs) {
    system.assemble_solids([](std::size_t) -> Constitutive { throw std::logic_error("no solids"); });
  }
  DofMap dofs;
  StiffnessSystem system;
};

RestartState fresh_state(const Model& m) {
  RestartState s;
  s.node_count = m.nodes.size();
  s.gap_count = m.gap_count();
  return s;
}

TEST(ContactMethodFactory, ChoosesByGapsMethodAndNoneWithoutGaps) {
  for (const GapMethod method : {GapMethod::classic, GapMethod::exact}) {
    const Model m = separate_gaps(1, method);
    System s(m);
    const auto made = make_contact_method({m, &*m.gaps, s.dofs, s.system.pattern()});
    if (method == GapMethod::classic) {
      EXPECT_NE(dynamic_cast<GapModulusMethod*>(made.get()), nullptr);
    } else {
      EXPECT_NE(dynamic_cast<NodePairMethod*>(made.get()), nullptr);
    }
  }
  Model without = separate_gaps(1, GapMethod::classic);
  without.gaps.reset();
  System s(without);
  const auto none = make_contact_method({without, nullptr, s.dofs, s.system.pattern()});
  ASSERT_NE(none, nullptr);
  EXPECT_EQ(dynamic_cast<GapModulusMethod*>(none.get()), nullptr);
  EXPECT_EQ(dynamic_cast<NodePairMethod*>(none.get()), nullptr);
  RestartState state = fresh_state(without);
  ContactOutcome outcome;
  outcome.nonconverged = 3;
  none->evaluate(state, outcome);
  EXPECT_TRUE(outcome.converged());
  EXPECT_TRUE(outcome.gaps.empty());
}

TEST(GapModulusMethod, ClassifiesEachGapByClosureAndVetoesUntilTheClosuresSettle) {
  const Model m = separate_gaps(4, GapMethod::classic);
  System s(m);
  GapModulusMethod method(m, *m.gaps);
  RestartState state = fresh_state(m);
  // Open (eps +0.5), partial (closure 50 %), closed (102 %, within the 5 % tolerance), overclosed (120 %).
  state.displacement = faces_moved(m, {0.5 * g0, -0.5 * g0, -1.02 * g0, -1.2 * g0});
  method.begin_iteration(state, s.system);
  state.iteration = 1;
  EXPECT_EQ(state.gaps.used.normal, std::vector<double>(4, 100.0));  // (a): E0 everywhere
  ContactOutcome outcome;
  method.evaluate(state, outcome);
  ASSERT_EQ(outcome.gaps.size(), 4U);
  const GapState expected[] = {GapState::open, GapState::partial, GapState::closed, GapState::overclosed};
  const double closure[] = {-50.0, 50.0, 102.0, 120.0};
  for (int g = 0; g < 4; ++g) {
    const GapResult& r = outcome.gaps[g];
    EXPECT_EQ(r.id, 100 + g);
    EXPECT_NEAR(r.closure, closure[g], 1e-9);
    EXPECT_NEAR(r.sigma_m, 100.0 * r.eps_m, 1e-9);  // plane stress, nu = 0: sigma_M = E_M eps_M
    EXPECT_EQ(r.modulus, 100.0);
    EXPECT_EQ(r.state, expected[g]) << "gap " << r.id;
    EXPECT_FALSE(r.converged);
  }
  EXPECT_EQ(outcome.gaps[3].failure, GapFailure::overclosed);
  EXPECT_EQ(outcome.gaps[0].failure, GapFailure::not_relaxed);  // open, still at E0 = 100 > floor 1
  EXPECT_EQ(outcome.gaps[2].failure, GapFailure::first_iteration);
  EXPECT_EQ(outcome.closed, 2);  // closure > 100 %
  EXPECT_NEAR(outcome.average_closure, 111.0, 1e-9);
  EXPECT_NEAR(outcome.max_closure, 120.0, 1e-9);
  EXPECT_EQ(outcome.nonconverged, 4);
  EXPECT_FALSE(outcome.converged());
  EXPECT_EQ(state.gaps.strain.size(), 4U);  // the history records the measured strains

  // A partial and a closed gap that do not move, at the second iteration: settled, no veto.
  const Model two = separate_gaps(2, GapMethod::classic);
  System s2(two);
  GapModulusMethod settled(two, *two.gaps);
  RestartState st = fresh_state(two);
  st.displacement = faces_moved(two, {-0.5 * g0, -1.02 * g0});
  for (int k = 0; k < 2; ++k) {
    settled.begin_iteration(st, s2.system);
    st.iteration += 1;
    settled.evaluate(st, outcome);
  }
  EXPECT_TRUE(outcome.converged());
  EXPECT_TRUE(outcome.gaps[0].converged && outcome.gaps[1].converged);
  // The partial gap was stiffened (b) and carries most of the pressure without touching: the note says so.
  EXPECT_GT(st.gaps.used.normal[0], 1.0);
  const std::string note = settled.converged_note(st, outcome);
  EXPECT_NE(note.find("warning: 1 gap is not closed (closure below 95 %) yet carries more than"), std::string::npos) << note;
  EXPECT_NE(note.find("accepts it, so its pressure and the stresses near it are approximate"), std::string::npos) << note;
  EXPECT_NE(note.find("gap 100"), std::string::npos) << note;
}

TEST(GapModulusMethod, AStateOfAnotherModelIsRefusedByItsStrains) {
  const Model m = separate_gaps(1, GapMethod::classic);
  System s(m);
  GapModulusMethod method(m, *m.gaps);
  RestartState state = fresh_state(m);
  state.displacement = faces_moved(m, {-0.5 * g0});
  method.begin_iteration(state, s.system);
  state.iteration = 1;
  state.gaps.strain = {-0.4};  // what a resume of another model would bring
  ContactOutcome outcome;
  EXPECT_THROW(method.evaluate(state, outcome), SolverError);
}

TEST(NodePairMethod, PressureFromThePairForcesAndNoVeto) {
  const Model m = separate_gaps(3, GapMethod::exact);
  System s(m);
  NodePairMethod method(m, *m.gaps, s.dofs, s.system.pattern());
  RestartState state = fresh_state(m);
  method.begin_iteration(state, s.system);
  state.iteration = 1;
  EXPECT_EQ(state.gaps.used.normal, std::vector<double>(3, 1.0));  // the floor modulus everywhere
  // Gap 0 touching (closed by exactly g0), its two pairs pressing with 3 each over a face area of 0.5
  // each: pressure 6. Gap 1 open by half its gap, gap 2 untouched.
  state.displacement = faces_moved(m, {-g0, -0.5 * g0, 0.0});
  const ContactPairs pairs = contact_pairs(m);
  ASSERT_EQ(pairs.pairs.size(), 6U);
  state.contact.force.assign(6, 0.0);
  state.contact.active.assign(6, 0);
  for (int k = 0; k < 2; ++k) {
    const int pair = pairs.of_gap[0][k].pair;
    EXPECT_NEAR(pairs.pairs[pair].area, 0.5, 1e-15);
    state.contact.force[pair] = 3.0;
    state.contact.active[pair] = 1;
  }
  ContactOutcome outcome;
  method.evaluate(state, outcome);
  ASSERT_EQ(outcome.gaps.size(), 3U);
  EXPECT_NEAR(outcome.gaps[0].closure, 100.0, 1e-9);
  EXPECT_NEAR(outcome.gaps[0].sigma_m, -1.0 - 6.0, 1e-9);  // floor spring at eps -1, then the contact
  EXPECT_EQ(outcome.gaps[0].state, GapState::closed);
  EXPECT_NEAR(outcome.gaps[1].closure, 50.0, 1e-9);
  EXPECT_NEAR(outcome.gaps[1].sigma_m, -0.5, 1e-9);
  EXPECT_EQ(outcome.gaps[1].state, GapState::open);
  EXPECT_EQ(outcome.closed, 1);
  EXPECT_NEAR(outcome.average_closure, 100.0, 1e-9);
  EXPECT_NEAR(outcome.max_closure, 100.0, 1e-9);
  EXPECT_TRUE(outcome.converged());
  for (const GapResult& r : outcome.gaps) EXPECT_TRUE(r.converged && r.failure == GapFailure::none);

  // The open gap's floor spring carries 0.5 of the 6 the contact carries: more than 1 %, so the
  // contact problem has no meaningful answer. Without it, nothing to say.
  try {
    method.check_solved(state, outcome);
    ADD_FAILURE() << "expected the floor-share check to throw";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("gap 101 at nodes 5 6 7 8"), std::string::npos) << e.what();
  }
  state.displacement = faces_moved(m, {-g0, 0.0, 0.0});
  state.gaps.strain.clear();  // a new solve: nothing saved to compare with
  method.evaluate(state, outcome);
  EXPECT_NO_THROW(method.check_solved(state, outcome));
}

// ---- A toy method through the seam: penalty springs on the exact method's node pairs.

/// Every gap at the floor modulus (as the exact method), and on each node pair that penetrates a
/// spring k_i = factor c_i^T diag(K) c_i on its gap function g_i = g0_i + c_i . u (energy k g^2 / 2:
/// K += k c c^T, f -= k g0 c); the set of springs iterated to a fixed point in each solve. The
/// contact force is lambda_i = -k_i g_i: the pair penetrates by lambda_i / k_i, which is the method's
/// error.
class PenaltyPairs final : public ContactMethod {
 public:
  PenaltyPairs(const ContactSetup& setup, double factor)
      : gaps_(setup.model, *setup.gaps), pairs_(contact_pairs(setup.model)), factor_(factor) {
    const CscPattern& pattern = setup.pattern;
    for (const ContactPair& p : pairs_.pairs) {
      Row row;
      row.g0 = p.g0;
      for (std::size_t k = 0; k < p.node.size(); ++k) {
        for (int dir = 0; dir < 2; ++dir) {
          const double c = p.weight[k] * p.normal[dir];
          const Index eq = setup.dofs.equation(p.node[k], dir);
          if (eq >= 0) row.entries.push_back({eq, c});
          else row.g0 += c * setup.dofs.prescribed(p.node[k], dir);
        }
      }
      for (const auto& [i, ci] : row.entries) {
        row.diagonal.push_back(pattern.find(i, i));
        for (const auto& [j, cj] : row.entries) {
          if (i <= j) row.products.push_back({pattern.find(i, j), ci * cj});
        }
      }
      rows_.push_back(std::move(row));
    }
  }

  void begin_iteration(RestartState& state, StiffnessSystem& system) override {
    GapElements::advance(state.gaps, gaps_.floor_moduli(), state.iteration);
    gaps_.assemble(system, state.gaps.used);
  }

  void solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
             RestartState& state, std::span<double> u) override {
    const std::size_t n = rows_.size();
    std::vector<double> k(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t e = 0; e < rows_[i].entries.size(); ++e) {
        const double c = rows_[i].entries[e].second;
        k[i] += factor_ * c * c * values[rows_[i].diagonal[e]];
      }
    }
    ContactState& contact = state.contact;
    if (contact.active.size() != n) contact.active.assign(n, 0);
    contact.force.assign(n, 0.0);
    std::vector<double> K, f;
    for (int round = 0; round < 50; ++round) {
      K.assign(values.begin(), values.end());
      f.assign(rhs.begin(), rhs.end());
      for (std::size_t i = 0; i < n; ++i) {
        if (!contact.active[i]) continue;
        for (const auto& [position, product] : rows_[i].products) K[position] += k[i] * product;
        for (const auto& [eq, c] : rows_[i].entries) f[eq] -= k[i] * rows_[i].g0 * c;
      }
      cholesky.factorize(K);
      cholesky.solve(f, u);
      bool changed = false;
      for (std::size_t i = 0; i < n; ++i) {
        double g = rows_[i].g0;
        for (const auto& [eq, c] : rows_[i].entries) g += c * u[eq];
        const std::uint8_t now = g < 0.0;
        changed = changed || now != contact.active[i];
        contact.active[i] = now;
        contact.force[i] = now ? -k[i] * g : 0.0;
      }
      if (!changed) return;
    }
    throw SolverError("the penalty active set did not settle");
  }

  void evaluate(RestartState& state, ContactOutcome& outcome) const override {
    gaps_.measure(state.gaps, state.displacement, outcome);
    measure_pair_contact(pairs_, state.contact, state.displacement, outcome);
    gaps_.keep_strains(outcome, state.gaps);
    touching_verdict(outcome);
  }

 private:
  struct Row {
    std::vector<std::pair<Index, double>> entries;   // (equation, c)
    std::vector<Index> diagonal;                     // K_jj of each entry
    std::vector<std::pair<Index, double>> products;  // (position of K_ij, c_i c_j), i <= j
    double g0 = 0.0;
  };
  GapElements gaps_;
  ContactPairs pairs_;
  std::vector<Row> rows_;
  double factor_;
};

/// The ring fit, plane strain, quarter annulus, gaps at the floor modulus of the exact method.
Model ring_fit() {
  Model m = testing::quarter_ring_fit(AnalysisType::plane_strain, 4, 24);
  m.gaps->method = GapMethod::exact;
  m.gaps->initial_modulus = 100.0;
  m.gaps->tensile_schedule = {20.0, 5.0, 1.0};
  return m;
}

/// Mean contact pressure and mean penetration (closure beyond 100 %, as a fraction of the gap) over
/// the gaps.
struct Fit {
  double pressure = 0.0;
  double penetration = 0.0;
};

Fit fit_of(const Solution& s) {
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  Fit fit;
  for (const GapResult& g : s.gaps) {
    EXPECT_EQ(g.state, GapState::closed) << "gap " << g.id;
    fit.pressure += -g.sigma_m / static_cast<double>(s.gaps.size());
    fit.penetration += (g.closure - 100.0) / 100.0 / static_cast<double>(s.gaps.size());
  }
  return fit;
}

TEST(ContactMethodSeam, AToyPenaltyMethodSolvesTheRingFitWithinItsPenetrationError) {
  using F = testing::RingFit;
  const Model m = ring_fit();
  const Fit exact = fit_of(solve(m));
  EXPECT_LT(exact.penetration, 1e-9);
  // The fit's free interference: the inner ring's thermal growth at b1 (plane strain) less the gap.
  const double interference = (1.0 + F::nu) * F::alpha * F::dT * F::b1 - F::delta;
  double previous_error = 0.0;
  for (const double factor : {1.0e4, 1.0e2}) {
    const ContactMethodFactory penalty = [factor](const ContactSetup& setup) {
      return std::make_unique<PenaltyPairs>(setup, factor);
    };
    const Solution s = solve(m, nullptr, nullptr, {}, nullptr, penalty);
    const Fit fit = fit_of(s);
    // Linear elasticity: the pressure is proportional to the interference the rings take up, and the
    // penalty lets the pairs overlap by d (their mean), so p_penalty = p_exact (1 - d / interference)
    // (observed: to 2e-4 of the error).
    const double error = (exact.pressure - fit.pressure) / exact.pressure;
    const double expected = fit.penetration * F::delta / interference;
    std::printf("penalty factor %.0e: pressure %.6g (exact %.6g), error %.6e, expected %.6e\n", factor,
                fit.pressure, exact.pressure, error, expected);
    EXPECT_GT(fit.penetration, 0.0);
    EXPECT_NEAR(error, expected, 0.01 * expected);
    // The error falls with the penalty: a factor 100 stiffer, about 100 times smaller.
    if (previous_error > 0.0) {
      EXPECT_NEAR(error / previous_error, 100.0, 10.0);
    }
    previous_error = error;
  }
}

}  // namespace
}  // namespace saasgaps
