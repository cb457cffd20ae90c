// The computational restart: a run stopped after iteration k (or ended not converged) and resumed
// from its saved state, through the JSON, CBOR and stored (compressed) codecs, ends with every output
// number equal to the uninterrupted run's.
#include <gtest/gtest.h>

#include "io/restart/state_codec.hpp"
#include "io/restart/stored_state.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/base/errors.hpp"
#include "support/examples.hpp"
#include "support/identical_solutions.hpp"
#include "support/state_recorder.hpp"
#include "support/state_round_trip.hpp"

namespace saasgaps {
namespace {

using Recorder = testing::StateRecorder;

class ExactRestart : public ::testing::TestWithParam<const char*> {};

TEST_P(ExactRestart, StopAfterKResumeFromTheSavedStateGivesTheSameNumbers) {
  const nlohmann::json document = testing::example_document(GetParam());
  const Model model = testing::example_model(GetParam());
  const std::string digest = io::model_digest(document);
  Recorder all;
  const Solution uninterrupted = solve(model, &all);
  ASSERT_GE(uninterrupted.iterations, 3);

  for (int k : {1, 2, uninterrupted.iterations - 1}) {
    SCOPED_TRACE("stopped after iteration " + std::to_string(k));
    Recorder first(k);
    const Solution stopped = solve(model, &first);
    ASSERT_EQ(stopped.status, RunStatus::stopped);
    ASSERT_EQ(stopped.iterations, k);
    // The state the stopped run saved equals the uninterrupted run's after k iterations (wall times
    // in the history rows aside).
    nlohmann::json saved = io::state_to_json(first.states.back(), digest);
    nlohmann::json reference = io::state_to_json(all.states[k - 1], digest);
    saved.erase("history");
    reference.erase("history");
    EXPECT_EQ(saved, reference);

    for (const std::string_view codec : testing::state_codecs) {
      SCOPED_TRACE(codec);
      const RestartState from = testing::through_codec(codec, first.states.back(), digest);
      testing::expect_identical(solve(model, nullptr, &from), uninterrupted);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ReportProblems, ExactRestart,
                         ::testing::Values("report-problem2.json", "report-problem3-case1.json",
                                           "report-problem3-case3.json", "report-problem3-case3-exact.json"));

TEST(Restart, ANotConvergedRunResumesWithMoreIterations) {
  const Model model = testing::example_model("report-problem3-case3.json");
  const Solution uninterrupted = solve(model);
  EXPECT_EQ(uninterrupted.iterations, 15);  // the README's restart example: "converges at 15"
  ResumeOptions short_run;
  short_run.max_iterations = 6;
  Recorder saved;
  const Solution partial = solve(model, &saved, nullptr, short_run);
  ASSERT_EQ(partial.status, RunStatus::not_converged);
  EXPECT_NE(partial.message.find("max_iterations 6"), std::string::npos) << partial.message;
  ResumeOptions more;
  more.max_iterations = model.solver.max_iterations;
  testing::expect_identical(solve(model, nullptr, &saved.states.back(), more), uninterrupted);
}

TEST(Restart, ANewScheduleStartsAfreshFromItsFirstValue) {
  const Model model = testing::example_model("report-problem3-case1.json");
  Recorder saved(3);
  solve(model, &saved);
  ResumeOptions changes;
  changes.tensile_schedule = std::vector<double>{0.5, 0.25};
  const Solution resumed = solve(model, nullptr, &saved.states.back(), changes);
  ASSERT_GE(resumed.history.size(), 5U);
  EXPECT_EQ(resumed.history[3].tensile_modulus, 0.5);
  EXPECT_EQ(resumed.history[4].tensile_modulus, 0.25);
  EXPECT_EQ(resumed.history[3].attempt, 2);
  EXPECT_EQ(resumed.history[2].attempt, 1);
}

TEST(Restart, AStateOfAnotherModelIsRefused) {
  const nlohmann::json document = testing::example_document("report-problem3-case1.json");
  Recorder saved(2);
  solve(testing::example_model("report-problem3-case1.json"), &saved);
  const nlohmann::json state = io::state_to_json(saved.states.back(), io::model_digest(document));
  const nlohmann::json other = testing::example_document("report-problem3-case3.json");
  EXPECT_THROW(io::state_from_json(state, io::model_digest(other)), SolverError);
  // Past the digest, the solver itself refuses a state whose numbers do not fit the model.
  const RestartState loaded = io::state_from_json(state, "");
  EXPECT_THROW(solve(testing::example_model("report-problem1.json"), nullptr, &loaded), SolverError);
}

TEST(StoredState, RoundTripsExactlyAndIsSmallerThanTheCbor) {
  const nlohmann::json document = testing::example_document("ring-shrink-fit-plane-strain.json");
  const std::string digest = io::model_digest(document);
  Recorder saved(3);
  solve(testing::example_model("ring-shrink-fit-plane-strain.json"), &saved);
  const RestartState& state = saved.states.back();
  const std::vector<std::uint8_t> stored = io::encode_stored_state(state, digest);
  EXPECT_LT(stored.size(), io::state_to_cbor(state, digest).size());
  // Every field, the history's wall times included, to the last bit.
  EXPECT_EQ(io::state_to_json(io::decode_stored_state(stored, digest), digest), io::state_to_json(state, digest));
}

TEST(StoredState, OldUncompressedStatesStillLoad) {
  const nlohmann::json document = testing::example_document("report-problem3-case1.json");
  const std::string digest = io::model_digest(document);
  Recorder saved(2);
  solve(testing::example_model("report-problem3-case1.json"), &saved);
  // Version 1 of the stored encoding was the plain CBOR of state_to_cbor.
  const RestartState loaded = io::decode_stored_state(io::state_to_cbor(saved.states.back(), digest), digest);
  EXPECT_EQ(io::state_to_json(loaded, digest), io::state_to_json(saved.states.back(), digest));
}

TEST(StoredState, DamagedOrForeignStatesAreRefusedNotCrashed) {
  const nlohmann::json document = testing::example_document("report-problem3-case1.json");
  const std::string digest = io::model_digest(document);
  Recorder saved(2);
  solve(testing::example_model("report-problem3-case1.json"), &saved);
  const std::vector<std::uint8_t> stored = io::encode_stored_state(saved.states.back(), digest);
  std::vector<std::uint8_t> truncated(stored.begin(), stored.begin() + static_cast<long>(stored.size() / 2));
  EXPECT_THROW(io::decode_stored_state(truncated, digest), SolverError);
  std::vector<std::uint8_t> flipped = stored;
  for (std::size_t i = 8; i < flipped.size(); i += 7) flipped[i] ^= 0x5a;
  EXPECT_THROW(io::decode_stored_state(flipped, digest), SolverError);
  EXPECT_THROW(io::decode_stored_state(std::vector<std::uint8_t>{'S', 'G', 'Z', '1'}, digest), SolverError);
  EXPECT_THROW(io::decode_stored_state(stored, "0123456789abcdef"), SolverError);
}

}  // namespace
}  // namespace saasgaps
