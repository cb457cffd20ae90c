// The job state table (service/job_states.hpp) asked directly for every state and event, and the
// store (a real SQLite file) driven through the races its callers can produce: cancel against finish,
// resume against cancel, a finish after a cancel request, a stale lease's finish, a restart that
// finds an acknowledged cancel, the delete of a running job.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "service/store/job_states.hpp"
#include "service/store/job_store.hpp"
#include "support/temp_directory.hpp"

namespace saasgaps::service {
namespace {

namespace fs = std::filesystem;

constexpr std::array<JobAction, 8> actions_of_a_job = {JobAction::claim,     JobAction::iteration,      JobAction::finish,
                                                     JobAction::request_cancel, JobAction::revoke, JobAction::interrupt,
                                                     JobAction::resume,    JobAction::remove};

using S = JobState;
using E = JobAction;

/// The allowed transitions as the docs state them (docs/http-api.md, docs/operations.md), written
/// out here independently of the table: (from, event) -> to, with default facts (finish: the
/// outcome failed; interrupt: counted, no cancel requested, within the limit). Nothing: deleted.
const std::map<std::pair<S, E>, std::optional<S>>& expected() {
  static const std::map<std::pair<S, E>, std::optional<S>> allowed = {
      {{S::queued, E::claim}, S::running},
      {{S::interrupted, E::claim}, S::running},
      {{S::running, E::iteration}, S::running},
      {{S::running, E::finish}, S::failed},
      {{S::queued, E::request_cancel}, S::cancelled},
      {{S::running, E::request_cancel}, S::running},
      {{S::interrupted, E::request_cancel}, S::cancelled},
      {{S::running, E::revoke}, S::cancelled},
      {{S::running, E::interrupt}, S::interrupted},
      {{S::cancelled, E::resume}, S::queued},
      {{S::not_converged, E::resume}, S::queued},
      {{S::interrupted, E::resume}, S::queued},
      {{S::failed, E::resume}, S::queued},
      {{S::converged, E::remove}, std::nullopt},
      {{S::not_converged, E::remove}, std::nullopt},
      {{S::failed, E::remove}, std::nullopt},
      {{S::cancelled, E::remove}, std::nullopt},
  };
  return allowed;
}

TEST(JobStates, EveryStateAndEventIsAllowedOrRefusedAsDocumented) {
  int allowed = 0;
  for (S from : all_job_states) {
    for (E event : actions_of_a_job) {
      SCOPED_TRACE(std::string(to_string(from)) + " " + to_string(event));
      const auto found = expected().find({from, event});
      if (found == expected().end()) {
        EXPECT_FALSE(accepts(from, event));
        EXPECT_EQ(find_transition(from, event), nullptr);
        EXPECT_THROW((void)next_state(7, from, event), JobConflict);
      } else {
        ++allowed;
        EXPECT_TRUE(accepts(from, event));
        EXPECT_EQ(next_state(7, from, event), found->second);
      }
    }
  }
  EXPECT_EQ(allowed, static_cast<int>(expected().size()));
  // Only a new job is submitted; no job in any state is submitted again.
  ASSERT_NE(find_transition(std::nullopt, E::submit), nullptr);
  EXPECT_EQ(find_transition(std::nullopt, E::submit)->to, S::queued);
  for (S from : all_job_states) EXPECT_FALSE(accepts(from, E::submit)) << to_string(from);
}

TEST(JobStates, ARunEndsInItsOutcomeButNeverQueuedOrRunning) {
  for (S outcome : all_job_states) {
    SCOPED_TRACE(to_string(outcome));
    const JobFacts facts{.outcome = outcome};
    if (outcome == S::queued || outcome == S::running) {
      EXPECT_EQ(find_transition(S::running, E::finish, facts), nullptr);
      try {
        (void)next_state(4, S::running, E::finish, facts);
        ADD_FAILURE() << "a run ended " << to_string(outcome);
      } catch (const JobConflict& e) {
        EXPECT_EQ(std::string(e.what()), std::string("job 4 is running; a run cannot end ") + to_string(outcome));
      }
    } else {
      EXPECT_EQ(next_state(4, S::running, E::finish, facts), outcome);
    }
    // Only a running job finishes, whatever the outcome (a stale run's finish after a restart).
    for (S from : all_job_states) {
      if (from != S::running) {
        EXPECT_THROW((void)next_state(4, from, E::finish, facts), JobConflict);
      }
    }
  }
}

TEST(JobStates, AnInterruptionHonoursACancelThenTheLimit) {
  const auto after = [](JobFacts facts) { return next_state(1, S::running, E::interrupt, facts); };
  EXPECT_EQ(after({.interruptions = 3, .max_interruptions = 3}), S::interrupted);
  EXPECT_EQ(after({.interruptions = 4, .max_interruptions = 3}), S::failed);
  // Not counted (no space to write): never failed for it.
  EXPECT_EQ(after({.counted = false, .interruptions = 4, .max_interruptions = 3}), S::interrupted);
  // An acknowledged cancel wins over both (docs/operations.md, "Cancel and kill -9").
  EXPECT_EQ(after({.cancel_requested = true, .interruptions = 1, .max_interruptions = 3}), S::cancelled);
  EXPECT_EQ(after({.cancel_requested = true, .interruptions = 9, .max_interruptions = 3}), S::cancelled);
}

TEST(JobStates, RefusalsNameTheJobItsStateAndWhatTheEventNeeds) {
  const auto refusal = [](S from, E event) {
    try {
      (void)next_state(3, from, event);
    } catch (const JobConflict& e) {
      return std::string(e.what());
    }
    return std::string("allowed");
  };
  // The wording docs/http-api.md quotes.
  EXPECT_EQ(refusal(S::converged, E::resume),
            "job 3 is converged; only cancelled, not_converged, interrupted or failed jobs can be resumed");
  EXPECT_EQ(refusal(S::failed, E::request_cancel), "job 3 is failed; only queued, running or interrupted jobs can be cancelled");
  EXPECT_EQ(refusal(S::running, E::remove), "job 3 is running; cancel it before deleting");
  EXPECT_EQ(refusal(S::cancelled, E::claim), "job 3 is cancelled; only queued or interrupted jobs can be claimed");
}

TEST(JobStates, SqlListsFollowTheTable) {
  EXPECT_EQ(sql_states_accepting(E::claim), "'queued', 'interrupted'");
  EXPECT_EQ(sql_states_accepting(E::interrupt), "'running'");
  EXPECT_EQ(sql_states_accepting(E::remove), "'converged', 'not_converged', 'failed', 'cancelled'");
}

/// A store on a fresh file, removed with its WAL afterwards.
class StoreTransitions : public ::testing::Test {
 protected:
  void SetUp() override { open(); }
  /// (Re)opens the store, as a server start does.
  void open() {
    store_.reset();
    store_ = std::make_unique<JobStore>((dir_ / "jobs.db").string(), max_interruptions);
  }
  std::int64_t submit() { return store().submit("{}", "job", 10, std::nullopt, "").job.id; }
  ClaimedJob claim() {
    std::optional<ClaimedJob> claimed = store().claim("test");
    EXPECT_TRUE(claimed.has_value());
    return claimed ? *claimed : ClaimedJob{};
  }
  void iterate(const ClaimedJob& run, int iteration) {
    store().record_iteration(run.job.id, iteration, "{\"iteration\":" + std::to_string(iteration) + "}",
                             {1, 2, 3}, std::nullopt, &run.lease);
  }
  void finish(const ClaimedJob& run, JobState outcome, const std::string& digest = "d") {
    store().finish(run.job.id, outcome, "{}", "ended", std::nullopt, std::nullopt, &run.lease, digest);
  }
  JobState state(std::int64_t id) { return store().get(id).state; }
  JobStore& store() { return *store_; }

  static constexpr int max_interruptions = 2;
  testing::TempDirectory temp_{"job-states"};
  fs::path dir_ = temp_.path();
  std::unique_ptr<JobStore> store_;  // after the directory: closed before it is removed
};

TEST_F(StoreTransitions, ARunGoesFromQueuedThroughRunningToItsOutcome) {
  const std::int64_t id = submit();
  EXPECT_EQ(state(id), S::queued);
  const ClaimedJob run = claim();
  EXPECT_EQ(run.job.id, id);
  EXPECT_EQ(state(id), S::running);
  iterate(run, 1);
  finish(run, S::not_converged);
  EXPECT_EQ(state(id), S::not_converged);
  // Finished: neither claimed again nor cancelled; resumed, it is queued and claimed again.
  EXPECT_FALSE(store().claim("test").has_value());
  EXPECT_THROW(store().cancel(id), JobConflict);
  EXPECT_EQ(store().resume(id, {}).state, S::queued);
  EXPECT_EQ(claim().job.attempts, 2);
}

TEST_F(StoreTransitions, CancelRequestedThenTheRunConvergesFirst) {
  const std::int64_t id = submit();
  const ClaimedJob run = claim();
  const JobRecord asked = store().cancel(id);
  EXPECT_EQ(asked.state, S::running);
  EXPECT_TRUE(asked.cancel_requested);
  // A second request changes nothing.
  EXPECT_EQ(store().cancel(id).state, S::running);
  // The run converged before its next boundary: converged, the request spent.
  finish(run, S::converged);
  const JobRecord job = store().get(id);
  EXPECT_EQ(job.state, S::converged);
  EXPECT_FALSE(job.cancel_requested);
  // The cancel that comes after the finish is refused.
  EXPECT_THROW(store().cancel(id), JobConflict);
}

TEST_F(StoreTransitions, CancelRequestedTakesEffectAtTheRunsBoundary) {
  const std::int64_t id = submit();
  const ClaimedJob run = claim();
  iterate(run, 1);
  store().cancel(id);
  EXPECT_TRUE(store().cancel_requested(id));
  finish(run, S::cancelled);
  EXPECT_EQ(state(id), S::cancelled);
  // A finish repeated by the same lease (a retry) is ignored; another finish is refused.
  finish(run, S::cancelled);
  EXPECT_THROW(finish(run, S::converged, "another"), LeaseConflict);
  EXPECT_EQ(state(id), S::cancelled);
}

TEST_F(StoreTransitions, ResumeAgainstCancel) {
  const std::int64_t id = submit();
  // Queued: cancelled at once, never resumed while queued or running.
  EXPECT_THROW(store().resume(id, {}), JobConflict);
  EXPECT_EQ(store().cancel(id).state, S::cancelled);
  EXPECT_EQ(store().resume(id, {}).state, S::queued);
  EXPECT_EQ(store().cancel(id).state, S::cancelled);
  EXPECT_EQ(store().resume(id, {}).state, S::queued);
  const ClaimedJob run = claim();
  EXPECT_THROW(store().resume(id, {}), JobConflict);
  finish(run, S::converged);
  EXPECT_THROW(store().resume(id, {}), JobConflict);
}

TEST_F(StoreTransitions, AStaleLeaseCannotWriteOrFinish) {
  const std::int64_t id = submit();
  const ClaimedJob first = claim();
  iterate(first, 1);
  // The server dies: the job is interrupted, then claimed again by a new run.
  open();
  EXPECT_EQ(store().recover_interrupted(), 1);
  EXPECT_EQ(state(id), S::interrupted);
  const ClaimedJob second = claim();
  EXPECT_EQ(second.job.attempts, 2);
  EXPECT_THROW(iterate(first, 2), LeaseConflict);
  EXPECT_THROW(finish(first, S::converged), LeaseConflict);
  EXPECT_EQ(state(id), S::running);
  iterate(second, 2);
  finish(second, S::converged);
  EXPECT_EQ(state(id), S::converged);
  // The first run's finish after the second's: still refused.
  EXPECT_THROW(finish(first, S::failed), LeaseConflict);
  EXPECT_EQ(state(id), S::converged);
}

TEST_F(StoreTransitions, ARunFinishesOnlyARunningJob) {
  // Without a lease (the service's own runs) the table still decides: a job no run holds is not
  // finished by one. Before the table, such a finish was written unchecked.
  const std::int64_t id = submit();
  EXPECT_THROW(store().finish(id, S::converged, "{}", "ended", std::nullopt), JobConflict);
  EXPECT_EQ(state(id), S::queued);
  const ClaimedJob run = claim();
  EXPECT_THROW(store().finish(id, S::queued, "{}", "ended", std::nullopt), JobConflict);
  store().finish(id, S::converged, "{}", "ended", std::nullopt);
  EXPECT_EQ(state(id), S::converged);
  EXPECT_THROW(store().finish(id, S::failed, "{}", "again", std::nullopt), JobConflict);
  EXPECT_EQ(state(id), S::converged);
  (void)run;
}

TEST_F(StoreTransitions, RecoveryCancelsAJobWhoseCancelWasAcknowledged) {
  const std::int64_t id = submit();
  const ClaimedJob run = claim();
  iterate(run, 1);
  store().cancel(id);
  open();  // the server died before the run reached its boundary
  EXPECT_EQ(store().recover_interrupted(), 1);
  const JobRecord job = store().get(id);
  EXPECT_EQ(job.state, S::cancelled);
  EXPECT_FALSE(job.cancel_requested);
  EXPECT_EQ(job.iteration, 1);
  // Its restart state is kept: resumed by hand, the next run starts from it.
  store().resume(id, {});
  const ClaimedJob again = claim();
  EXPECT_TRUE(again.state.has_value());
  EXPECT_THROW(iterate(run, 2), LeaseConflict);
}

TEST_F(StoreTransitions, RecoveryFailsAJobInterruptedTooOften) {
  const std::int64_t id = submit();
  for (int k = 1; k <= max_interruptions + 1; ++k) {
    claim();
    open();
    EXPECT_EQ(store().recover_interrupted(), 1);
    EXPECT_EQ(state(id), k <= max_interruptions ? S::interrupted : S::failed) << k;
  }
  // Resumed by hand, the count starts again.
  EXPECT_EQ(store().resume(id, {}).interruptions, 0);
  EXPECT_EQ(store().recover_interrupted(), 0);  // nothing running
}

TEST_F(StoreTransitions, DeleteOnlyAFinishedJob) {
  const std::int64_t id = submit();
  EXPECT_THROW(store().remove(id), JobConflict);  // queued
  const ClaimedJob run = claim();
  try {
    store().remove(id);
    ADD_FAILURE() << "a running job was deleted";
  } catch (const JobConflict& e) {
    EXPECT_EQ(std::string(e.what()), "job " + std::to_string(id) + " is running; cancel it before deleting");
  }
  finish(run, S::failed);
  store().remove(id);
  EXPECT_THROW(store().get(id), JobNotFound);
}

TEST_F(StoreTransitions, ASecondResumeKeepsTheFirstsChangesAndStartsANewScheduleAfresh) {
  const std::int64_t id = submit();
  const ClaimedJob run = claim();
  iterate(run, 1);
  finish(run, S::not_converged);
  ResumeOptions first;
  first.tensile_schedule = std::vector<double>{10.0, 1.0};
  first.extrapolation_factor = 0.5;
  EXPECT_TRUE(store().resume(id, first).settings.restart_schedule);
  const ClaimedJob second = claim();
  iterate(second, 2);  // the new schedule is in use: a restart continues it
  EXPECT_FALSE(store().get(id).settings.restart_schedule);
  finish(second, S::not_converged);
  ResumeOptions more;
  more.max_iterations = 40;
  const JobRecord job = store().resume(id, more);
  EXPECT_EQ(job.settings.tensile_schedule, first.tensile_schedule);
  EXPECT_EQ(job.settings.extrapolation_factor, 0.5);
  EXPECT_EQ(job.settings.max_iterations, 40);
  EXPECT_EQ(job.max_iterations, 40);
  EXPECT_FALSE(job.settings.restart_schedule);
}

}  // namespace
}  // namespace saasgaps::service
