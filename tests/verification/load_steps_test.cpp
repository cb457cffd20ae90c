// Load steps (model.steps): the analysis runs increment by increment (solver/model/load_schedule.hpp).
//  - a frictionless exact-contact ring fit split into 4 proportional increments ends where the
//    one-increment run ends (1e-8 of the largest displacement), and a step of one increment is the
//    model without steps to the last digit;
//  - a prescribed non-zero displacement is reached linearly, increment by increment;
//  - a plastic bar under a load-unload-reload path shows the path in its history;
//  - a run stopped mid-step and resumed from its saved state (JSON, CBOR, stored) equals the
//    uninterrupted run to the last digit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/restart/state_codec.hpp"
#include "io/results/history_json.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/base/errors.hpp"
#include "support/identical_solutions.hpp"
#include "support/mesh_builder.hpp"
#include "support/ring_fit.hpp"
#include "support/state_recorder.hpp"
#include "support/state_round_trip.hpp"

namespace saasgaps {
namespace {

using Recorder = testing::StateRecorder;

Model exact_ring_fit() {
  Model m = testing::quarter_ring_fit(AnalysisType::plane_stress, 3, 8);
  testing::use_exact_contact(m);
  return m;
}

Step step(std::string name, int increments) {
  Step s;
  s.name = std::move(name);
  s.increments = increments;
  return s;
}

double largest_displacement(const Solution& s) {
  double largest = 0.0;
  for (const NodeResult& n : s.nodes) largest = std::max({largest, std::abs(n.u_r), std::abs(n.u_z)});
  return largest;
}

TEST(LoadSteps, FourProportionalIncrementsOfExactContactEndWhereOneIncrementEnds) {
  const Model plain = exact_ring_fit();
  Model stepped = plain;
  stepped.steps = {step("heat", 4)};  // no loads: step 1 takes the model's (the inner ring's dT)

  const Solution one = solve(plain);
  Recorder rows;
  const Solution four = solve(stepped, &rows);
  ASSERT_EQ(one.status, RunStatus::converged) << one.message;
  ASSERT_EQ(four.status, RunStatus::converged) << four.message;
  ASSERT_EQ(four.steps.size(), 1u);
  EXPECT_EQ(four.steps[0].name, "heat");
  EXPECT_EQ(four.steps[0].increments, 4);
  EXPECT_EQ(four.steps[0].status, StepStatus::converged);
  EXPECT_TRUE(one.steps.empty());

  // Every row carries its step and increment; increments come in order; iterations count globally.
  ASSERT_EQ(rows.rows.size(), four.history.size());
  int last_increment = 0;
  for (std::size_t k = 0; k < rows.rows.size(); ++k) {
    EXPECT_EQ(rows.rows[k].iteration, static_cast<int>(k) + 1);
    EXPECT_EQ(rows.rows[k].step, 1);
    EXPECT_GE(rows.rows[k].increment, last_increment);
    last_increment = rows.rows[k].increment;
  }
  EXPECT_EQ(last_increment, 4);
  for (const IterationRecord& row : one.history) EXPECT_EQ(row.step, 0);

  const double scale = largest_displacement(one);
  ASSERT_GT(scale, 0.0);
  ASSERT_EQ(one.nodes.size(), four.nodes.size());
  for (std::size_t n = 0; n < one.nodes.size(); ++n) {
    EXPECT_NEAR(four.nodes[n].u_r, one.nodes[n].u_r, 1e-8 * scale) << "node " << one.nodes[n].id;
    EXPECT_NEAR(four.nodes[n].u_z, one.nodes[n].u_z, 1e-8 * scale) << "node " << one.nodes[n].id;
  }
  for (std::size_t g = 0; g < one.gaps.size(); ++g) {
    EXPECT_EQ(four.gaps[g].state, one.gaps[g].state);
    EXPECT_NEAR(four.gaps[g].sigma_m, one.gaps[g].sigma_m, 1e-8 * std::abs(one.gaps[g].sigma_m) + 1e-9);
  }
}

TEST(LoadSteps, OneStepOfOneIncrementIsTheModelWithoutStepsToTheLastDigit) {
  const Model plain = exact_ring_fit();
  Model stepped = plain;
  stepped.steps = {step("all", 1)};
  const Solution a = solve(plain);
  const Solution b = solve(stepped);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t n = 0; n < a.nodes.size(); ++n) {
    EXPECT_EQ(a.nodes[n].u_r, b.nodes[n].u_r);
    EXPECT_EQ(a.nodes[n].u_z, b.nodes[n].u_z);
  }
  for (std::size_t e = 0; e < a.elements.size(); ++e) EXPECT_EQ(a.elements[e].stress, b.elements[e].stress);
}

/// A bar W x H of 2 x 4 quads in plane stress, held at z = 0 (and r = 0 at one corner); its top
/// nodes are the grid's last row.
struct Bar {
  Model model;
  testing::Grid grid;
  static constexpr double W = 1.0, H = 4.0, E = 30.0e6, nu = 0.3, yield = 30.0e3;
  [[nodiscard]] std::vector<int> top() const {
    std::vector<int> nodes;
    for (int i = 0; i <= grid.ni; ++i) nodes.push_back(grid.at(i, grid.nj));
    return nodes;
  }
};

Bar bar(bool plastic) {
  Bar b;
  Model& m = b.model;
  m.analysis = AnalysisType::plane_stress;
  Material steel = testing::isotropic_material(1, Bar::E, Bar::nu);
  if (plastic) steel.plasticity = {{0.0, Bar::yield, 0.1}};
  m.materials.push_back(steel);
  b.grid = testing::add_grid(m, 2, 4, [](double s, double t) { return Vec2(Bar::W * s, Bar::H * t); }, 0);
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= b.grid.ni; ++i) testing::constrain(m, b.grid.at(i, 0), i == 0 ? std::optional(0.0) : std::nullopt, 0.0);
  return b;
}

/// A step that pulls the bar's top to z = d.
Step pull(Bar& b, std::string name, int increments, double d) {
  Step s = step(std::move(name), increments);
  for (int node : b.top()) s.constraints.push_back({node, std::nullopt, d});
  return s;
}

/// The displacement of node `index` at the end of each increment (the state of the last row with
/// that increment).
std::vector<double> uz_per_increment(const Recorder& r, int index) {
  std::vector<double> uz;
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    const bool last_of_increment = k + 1 == r.rows.size() || r.rows[k + 1].increment != r.rows[k].increment ||
                                   r.rows[k + 1].step != r.rows[k].step;
    if (last_of_increment) uz.push_back(r.states[k].displacement[2 * static_cast<std::size_t>(index) + 1]);
  }
  return uz;
}

TEST(LoadSteps, PrescribedNonZeroDisplacementIsReachedLinearly) {
  Bar b = bar(false);
  constexpr double d = 0.004;
  b.model.steps = {pull(b, "pull", 4, d)};
  Recorder r;
  const Solution s = solve(b.model, &r);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  // The top reaches d/4, d/2, 3d/4, d; the node at mid height, free, half of that (uniform strain).
  const int top = b.grid.at(1, b.grid.nj);
  const int middle = b.grid.at(1, b.grid.nj / 2);
  const std::vector<double> at_top = uz_per_increment(r, top);
  const std::vector<double> at_middle = uz_per_increment(r, middle);
  ASSERT_EQ(at_top.size(), 4u);
  for (int i = 1; i <= 4; ++i) {
    EXPECT_DOUBLE_EQ(at_top[static_cast<std::size_t>(i - 1)], d * i / 4.0);
    EXPECT_NEAR(at_middle[static_cast<std::size_t>(i - 1)], 0.5 * d * i / 4.0, 1e-12);
  }
  EXPECT_EQ(at_top.back(), d);  // the step's own value at its end, to the last digit
  // The uniaxial stress E d / H everywhere.
  for (const ElementResult& e : s.elements) EXPECT_NEAR(e.stress[zz], Bar::E * d / Bar::H, 1e-6 * Bar::E * d / Bar::H);
}

TEST(LoadSteps, PlasticBarShowsLoadUnloadReloadInItsHistory) {
  Bar b = bar(true);
  const double d = 1.5 * Bar::yield / Bar::E * Bar::H;  // 1.5 times the yield strain
  b.model.steps = {pull(b, "load", 2, d), pull(b, "unload", 2, 0.0), pull(b, "reload", 2, d)};
  Recorder r;
  const Solution s = solve(b.model, &r);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_EQ(s.steps.size(), 3u);
  for (const StepResult& st : s.steps) EXPECT_EQ(st.status, StepStatus::converged) << st.name;

  // Yielded elements at the end of each increment: none at half the load (the yield strain),
  // all at full load, none once unloaded, all again after reloading.
  std::vector<int> yielded;
  std::vector<double> uz;
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    const bool last = k + 1 == r.rows.size() || r.rows[k + 1].increment != r.rows[k].increment ||
                      r.rows[k + 1].step != r.rows[k].step;
    if (last) yielded.push_back(r.rows[k].yielded_elements);
  }
  const int all = static_cast<int>(b.model.elements.size());
  EXPECT_EQ(yielded, (std::vector<int>{0, all, 0, 0, 0, all})) << "(load 1/2, 1; unload 1/2, 0; reload 1/2, 1)";
  // The plastic increments needed the material iteration; the elastic ones converge at once.
  int load_iterations = 0, unload_last_iterations = 0;
  for (const IterationRecord& row : r.rows) {
    if (row.step == 1 && row.increment == 2) ++load_iterations;
    if (row.step == 2 && row.increment == 2) ++unload_last_iterations;
  }
  EXPECT_GT(load_iterations, 1);
  EXPECT_EQ(unload_last_iterations, 1);
  // The reloaded bar ends where the first loading ended: reloading retraces the elastic unloading
  // line up to the peak (solver/materials/plastic_history.hpp).
  const Solution once = [&] {
    Bar c = bar(true);
    c.model.steps = {pull(c, "load", 2, d)};
    return solve(c.model);
  }();
  for (std::size_t e = 0; e < s.elements.size(); ++e) {
    EXPECT_NEAR(s.elements[e].stress[zz], once.elements[e].stress[zz], 1e-9 * Bar::yield);
    EXPECT_TRUE(s.elements[e].yielded);
  }
}

/// Stops the run after every iteration k in turn, resumes from the saved state through the JSON,
/// CBOR and stored (compressed CBOR) codecs, and expects the uninterrupted run's numbers to the last digit.
void expect_exact_resumes(const Model& model, int minimum_iterations) {
  const std::string digest = "steps-test";
  Recorder all;
  const Solution uninterrupted = solve(model, &all);
  ASSERT_EQ(uninterrupted.status, RunStatus::converged) << uninterrupted.message;
  ASSERT_GE(uninterrupted.iterations, minimum_iterations);
  for (int k = 1; k < uninterrupted.iterations; ++k) {
    SCOPED_TRACE("stopped after iteration " + std::to_string(k));
    Recorder first(k);
    const Solution stopped = solve(model, &first);
    ASSERT_EQ(stopped.status, RunStatus::stopped);
    EXPECT_EQ(stopped.steps.back().status, StepStatus::not_converged);
    const RestartState& saved = first.states.back();
    ASSERT_TRUE(saved.position.has_value());
    EXPECT_EQ(saved.version, restart_version(model));
    EXPECT_EQ(*saved.position, *all.states[static_cast<std::size_t>(k - 1)].position);

    for (const std::string_view codec : testing::state_codecs) {
      SCOPED_TRACE(codec);
      const RestartState from = testing::through_codec(codec, saved, digest);
      testing::expect_identical(solve(model, nullptr, &from), uninterrupted);
    }
  }
}

TEST(LoadSteps, RunStoppedBetweenIncrementsAndStepsResumesToTheLastDigit) {
  // Exact contact converges in one iteration per increment: every stop is at an increment's end,
  // two of them at the end of a step.
  Model model = exact_ring_fit();
  model.steps = {step("heat", 3), step("hold", 2)};
  expect_exact_resumes(model, 5);
}

TEST(LoadSteps, RunStoppedInsideAnIncrementResumesToTheLastDigit) {
  // The plastic increments take several iterations each: most stops fall inside an increment.
  Bar b = bar(true);
  const double d = 1.5 * Bar::yield / Bar::E * Bar::H;
  b.model.steps = {pull(b, "load", 2, d), pull(b, "unload", 2, 0.0)};
  expect_exact_resumes(b.model, 6);
}

TEST(LoadSteps, StatesDoNotCrossBetweenStepsAndNoSteps) {
  const Model plain = exact_ring_fit();
  Model stepped = plain;
  stepped.steps = {step("heat", 2)};
  Recorder a(1), b(1);
  solve(plain, &a);
  solve(stepped, &b);
  EXPECT_EQ(a.states.back().version, RestartState::plain_version);
  EXPECT_FALSE(a.states.back().position.has_value());
  EXPECT_THROW(solve(stepped, nullptr, &a.states.back()), SolverError);
  EXPECT_THROW(solve(plain, nullptr, &b.states.back()), SolverError);
  // A version-1 document (a model without steps) is written exactly as before: no position.
  const nlohmann::json document = io::state_to_json(a.states.back(), "d");
  EXPECT_EQ(document.at("version"), 1);
  EXPECT_FALSE(document.contains("position"));
  EXPECT_FALSE(io::history_row_json(a.rows.back()).contains("step"));
  EXPECT_EQ(io::history_row_json(b.rows.back()).at("step"), 1);
  EXPECT_EQ(io::history_row_json(b.rows.back()).at("increment"), 1);
}

}  // namespace
}  // namespace saasgaps
