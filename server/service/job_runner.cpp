#include "service/job_runner.hpp"

#include <unistd.h>

#include "analysis.hpp"
#include "io/history_json.hpp"
#include "io/model_reader.hpp"
#include "io/result_writer.hpp"
#include "io/state_codec.hpp"

namespace saasgaps::service {

namespace {

/// Commits every iteration of one job and tells the solver when to stop.
class CommittingObserver final : public IterationObserver {
 public:
  CommittingObserver(JobStore& store, EventHub& hub, std::int64_t job, std::string digest,
                     const std::atomic<bool>& stopping)
      : store_(store), hub_(hub), job_(job), digest_(std::move(digest)), stopping_(stopping) {}

  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    store_.record_iteration(job_, row.iteration, io::history_row_text(row), io::state_to_cbor(state, digest_));
    hub_.notify();
  }

  bool stop_requested() override { return stopping_ || store_.cancel_requested(job_); }

 private:
  JobStore& store_;
  EventHub& hub_;
  std::int64_t job_;
  std::string digest_;
  const std::atomic<bool>& stopping_;
};

ResumeOptions resume_options(const RunSettings& settings) {
  ResumeOptions options;
  options.tensile_schedule = settings.tensile_schedule;
  options.max_iterations = settings.max_iterations;
  options.extrapolation_factor = settings.extrapolation_factor;
  options.restart_schedule = settings.restart_schedule;
  return options;
}

}  // namespace

JobRunner::JobRunner(JobStore& store, EventHub& hub, int workers) : store_(store), hub_(hub) {
  const std::string host = "pid " + std::to_string(::getpid());
  for (int w = 0; w < workers; ++w) {
    threads_.emplace_back([this, name = host + " worker " + std::to_string(w + 1)] { work(name); });
  }
}

JobRunner::~JobRunner() {
  stopping_ = true;
  hub_.notify();
  for (std::thread& t : threads_) t.join();
}

void JobRunner::work(const std::string& name) {
  std::uint64_t seen = hub_.version();
  while (!stopping_) {
    std::optional<ClaimedJob> claimed;
    try {
      claimed = store_.claim(name);
    } catch (const std::exception&) {
      // The database is busy or failing: try again after a pause rather than spin or die.
      claimed.reset();
    }
    if (!claimed) {
      seen = hub_.wait(seen, std::chrono::milliseconds(1000));
      continue;
    }
    hub_.notify();
    run(*claimed);
    hub_.notify();
  }
}

void JobRunner::run(const ClaimedJob& claimed) {
  const std::int64_t id = claimed.job.id;
  try {
    std::string digest;
    const Model model = io::parse_model(claimed.model, &digest);
    std::optional<RestartState> state;
    if (claimed.state) state = io::state_from_cbor(*claimed.state, digest);

    CommittingObserver observer(store_, hub_, id, digest, stopping_);
    const Solution solution = solve(model, &observer, state ? &*state : nullptr, resume_options(claimed.job.settings));

    JobState final_state = JobState::converged;
    std::string message = solution.message;
    if (solution.status == RunStatus::not_converged) final_state = JobState::not_converged;
    if (solution.status == RunStatus::stopped) {
      // A shutdown hands the job to the next server; a user's cancel keeps it cancelled.
      final_state = stopping_ ? JobState::interrupted : JobState::cancelled;
      message = stopping_ ? "the server shut down after iteration " + std::to_string(solution.iterations) +
                                "; resumes from there"
                          : "cancelled after iteration " + std::to_string(solution.iterations);
    }
    store_.finish(id, final_state, io::result_text(model, solution), message, std::nullopt);
  } catch (const std::exception& e) {
    try {
      store_.finish(id, JobState::failed, io::failed_result_text(e.what()), std::nullopt, e.what());
    } catch (const std::exception&) {
      // Even the failure cannot be recorded (database gone): the job stays running in the file and
      // the next server start marks it interrupted.
    }
  }
}

}  // namespace saasgaps::service
