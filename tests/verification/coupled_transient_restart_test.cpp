// A transient heat conduction run whose gaps conduct (so the conductances of each interval come
// from the stress solve at the output time before it, transient_coupling.hpp), stopped at several
// points and resumed from its restart state through the JSON, CBOR and stored codecs, ends with
// every number equal to the uninterrupted run's: stresses, gap state, the temperatures at every
// output time and the thermal rows; the resumed run reports only the iterations after the stop.
#include <gtest/gtest.h>

#include <set>

#include "io/model/model_reader.hpp"
#include "solver/state/restart_state.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/identical_solutions.hpp"
#include "support/state_recorder.hpp"
#include "support/transient_heating.hpp"
#include "support/transient_resume.hpp"

namespace saasgaps {
namespace {

using Recorder = testing::StateRecorder;

TEST(CoupledTransientRestart, StoppedAnywhereResumesToTheLastDigit) {
  nlohmann::json document = testing::transient_heating("ring-shrink-fit-plane-strain.json", {.hot = 400.0});
  // Gaps conduct through their gas across the opening each stress step leaves, better still when touching.
  document["gaps"]["conductance"] = {{"closed", 20.0}, {"gas_conductivity", 0.0005}};
  const std::string digest = io::model_digest(document);
  const Model model = io::read_model(document);
  Recorder all;
  const Solution uninterrupted = solve_with_heat(model, &all);
  ASSERT_EQ(uninterrupted.status, RunStatus::converged) << uninterrupted.message;
  ASSERT_TRUE(uninterrupted.thermal.has_value());
  const std::size_t output_times = model.thermal->output_times.size();
  ASSERT_EQ(uninterrupted.steps.size(), output_times);
  ASSERT_EQ(all.thermal.size(), output_times);
  // The heated inner ring narrows the gaps (their gas conductance k_gas / (w (1 + eps_M)) grows),
  // and so some output time changed the conductances: the conduction depends on the stress solves.
  for (const GapResult& g : uninterrupted.gaps) EXPECT_LT(g.eps_m, -0.1);
  EXPECT_GT(uninterrupted.thermal->factorizations, 1);

  // Stops: the first iteration, the last of each load step but the final one (a step boundary),
  // the first of each later step, and the one before the end.
  std::set<int> stops{1, uninterrupted.iterations - 1};
  for (std::size_t i = 0; i + 1 < all.states.size(); ++i) {
    if (all.states[i].position->step != all.states[i + 1].position->step) {
      stops.insert(static_cast<int>(i) + 1);
      stops.insert(static_cast<int>(i) + 2);
    }
  }
  std::set<int> steps_stopped_in;
  for (int k : stops) {
    SCOPED_TRACE("stopped after iteration " + std::to_string(k));
    Recorder first(k);
    const Solution stopped = solve_with_heat(model, &first);
    ASSERT_EQ(stopped.status, RunStatus::stopped);
    const RestartState& state = first.states.back();
    ASSERT_EQ(state.iteration, k);
    ASSERT_TRUE(state.position.has_value());
    steps_stopped_in.insert(state.position->step);

    testing::expect_resumes_to_the_last_digit(model, state, digest, uninterrupted, all, k);
  }
  EXPECT_GE(steps_stopped_in.size(), 3u);  // resumed in several load steps, not only the first
}

TEST(CoupledTransientRestart, AStateOfAnotherRunIsRefused) {
  nlohmann::json document = testing::transient_heating("ring-shrink-fit-plane-strain.json", {.hot = 400.0});
  document["gaps"]["conductance"] = {{"closed", 20.0}, {"gas_conductivity", 0.0005}};
  const Model model = io::read_model(document);
  Recorder first(1);
  ASSERT_EQ(solve_with_heat(model, &first).status, RunStatus::stopped);
  RestartState state = first.states.back();
  state.position->step = static_cast<int>(model.thermal->output_times.size());  // past the last output time
  EXPECT_THROW(solve_with_heat(model, nullptr, &state), SolverError);
}

}  // namespace
}  // namespace saasgaps
