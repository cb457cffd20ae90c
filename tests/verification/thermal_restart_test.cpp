// A transient heat conduction run stopped between two output times (inside a load step of its
// stress analysis) and resumed from its restart state, through the JSON, CBOR and stored codecs,
// ends with every number equal to the uninterrupted run's: stresses, gap and plastic state, the
// temperatures at every output time, and the thermal history rows, which the resumed run reports
// again unchanged.
#include <gtest/gtest.h>

#include <cmath>

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

struct Case {
  const char* example;
  testing::TransientHeating heating;
};

class TransientRestart : public ::testing::TestWithParam<Case> {};

TEST_P(TransientRestart, StoppedBetweenOutputTimesResumesToTheLastDigit) {
  const nlohmann::json document = testing::transient_heating(GetParam().example, GetParam().heating);
  const std::string digest = io::model_digest(document);
  const Model model = io::read_model(document);
  Recorder all;
  const Solution uninterrupted = solve_with_heat(model, &all);
  ASSERT_EQ(uninterrupted.status, RunStatus::converged) << uninterrupted.message;
  const std::vector<double>& times = GetParam().heating.output_times;
  ASSERT_EQ(uninterrupted.steps.size(), times.size());
  ASSERT_GT(uninterrupted.iterations, static_cast<int>(times.size()));  // some step takes more than one iteration
  // The state that must carry over is there: elastic, gaps closed by the heating; with a yield
  // stress, elements yielded by the thermal gradient (which keep the bore from growing as far).
  if (GetParam().heating.yield_stress == 0.0) {
    EXPECT_GT(all.rows.back().closed_gaps, 0);
  } else {
    EXPECT_GT(all.rows.back().yielded_elements, 0);
    EXPECT_EQ(all.states.back().version, RestartState::plastic_steps_version);
  }

  // One thermal row per output time, before the stress iterations: its time, the steps taken to
  // it (dt divides every interval here) and the temperature range, from the held bore down.
  ASSERT_EQ(all.thermal.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const ThermalRecord& row = all.thermal[k];
    EXPECT_EQ(row.kind, ThermalRowKind::transient);
    EXPECT_EQ(row.index, static_cast<int>(k) + 1);
    EXPECT_EQ(row.time, times[k]);
    EXPECT_EQ(row.time_steps, static_cast<int>(std::lround(times[k] / GetParam().heating.time_step)));
    EXPECT_EQ(row.max_T, GetParam().heating.hot);
    EXPECT_GE(row.min_T, 0.0);
    EXPECT_GT(row.max_change, 0.0);
    if (k > 0) {
      EXPECT_GE(row.min_T, all.thermal[k - 1].min_T);  // heat only flows in
    }
  }

  bool stopped_inside_a_later_step = false;
  for (int k : {1, uninterrupted.iterations / 2, uninterrupted.iterations - 1}) {
    SCOPED_TRACE("stopped after iteration " + std::to_string(k));
    Recorder first(k);
    const Solution stopped = solve_with_heat(model, &first);
    ASSERT_EQ(stopped.status, RunStatus::stopped);
    const RestartState& state = first.states.back();
    ASSERT_EQ(state.iteration, k);
    ASSERT_TRUE(state.position.has_value());
    EXPECT_EQ(state.version, restart_version(with_temperature_steps(model, *uninterrupted.thermal)));
    if (state.position->step > 1) stopped_inside_a_later_step = true;

    testing::expect_resumes_to_the_last_digit(model, state, digest, uninterrupted, all, k);
  }
  EXPECT_TRUE(stopped_inside_a_later_step);
}

// The shrink fit of two rings made by heating the inner one from its bore: its gaps close as the
// heat spreads; with a yield stress the thermal gradient yields it instead, so gap or plastic state
// carries from one output time to the next.
INSTANTIATE_TEST_SUITE_P(Examples, TransientRestart,
                         ::testing::Values(Case{"ring-shrink-fit-plane-strain.json", {.hot = 400.0}},
                                           Case{"ring-shrink-fit-plane-strain.json", {.hot = 400.0, .yield_stress = 40000.0}}),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return param.param.heating.yield_stress > 0.0 ? "ShrinkFitYielding" : "ShrinkFit";
                         });

}  // namespace
}  // namespace saasgaps
