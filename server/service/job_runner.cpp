#include "service/job_runner.hpp"

#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>

#include "analysis.hpp"
#include "io/history_json.hpp"
#include "io/json_text.hpp"
#include "io/model_reader.hpp"
#include "io/result_writer.hpp"
#include "io/state_codec.hpp"
#include "service/log.hpp"
#include "service/metrics.hpp"
#include "io/stored_state.hpp"

namespace saasgaps::service {

namespace {

/// Commits every iteration of one job and tells the solver when to stop.
class CommittingObserver final : public IterationObserver {
 public:
  CommittingObserver(JobStore& store, EventHub& hub, std::int64_t job, std::string digest,
                     const std::atomic<bool>& stopping)
      : store_(store), hub_(hub), job_(job), digest_(std::move(digest)), stopping_(stopping) {}

  /// Encodes and commits the row and state; the time that takes is recorded as the row's
  /// commit_seconds in the next commit (a row cannot contain the duration of its own commit).
  void on_iteration(const IterationRecord& row, const RestartState& state) override {
    const auto started = std::chrono::steady_clock::now();
    store_.record_iteration(job_, row.iteration, io::history_row_text(row), io::encode_stored_state(state, digest_),
                            last_commit_);
    last_commit_ = {row.iteration, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()};
    hub_.notify();
    Metrics::global().count_iteration(row.seconds);
    log_info("job_iteration", {{"job", job_}, {"iteration", row.iteration}, {"attempt", row.attempt},
                               {"seconds", row.seconds}});
  }

  /// The last committed iteration's commit time, for finish().
  [[nodiscard]] const std::optional<CommitTime>& last_commit() const { return last_commit_; }

  bool stop_requested() override { return stopping_ || store_.cancel_requested(job_); }

 private:
  JobStore& store_;
  EventHub& hub_;
  std::int64_t job_;
  std::string digest_;
  const std::atomic<bool>& stopping_;
  std::optional<CommitTime> last_commit_;
};

bool trim_after_jobs() {
  static const bool trim = [] {
    const char* setting = std::getenv("SAASGAPS_MALLOC_TRIM");
    return setting == nullptr || std::string(setting) != "0";
  }();
  return trim;
}

/// malloc_trim at most every 10 s, from whichever worker is idle.
void trim_when_idle() {
  static std::atomic<std::int64_t> last{0};
  const std::int64_t now =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  std::int64_t previous = last.load();
  if (!trim_after_jobs() || now - previous < 10 || !last.compare_exchange_strong(previous, now)) return;
  malloc_trim(0);
}

ResumeOptions resume_options(const RunSettings& settings) {
  ResumeOptions options;
  options.tensile_schedule = settings.tensile_schedule;
  options.max_iterations = settings.max_iterations;
  options.extrapolation_factor = settings.extrapolation_factor;
  options.restart_schedule = settings.restart_schedule;
  return options;
}

}  // namespace

JobRunner::JobRunner(JobStore& store, EventHub& hub, int workers, const std::filesystem::path& ordering_cache)
    : store_(store), hub_(hub) {
  if (!ordering_cache.empty()) ordering_cache_.emplace(ordering_cache);
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
  std::string failing;  // the last claim's error, logged once
  while (!stopping_) {
    std::optional<ClaimedJob> claimed;
    try {
      claimed = store_.claim(name);
      if (!failing.empty()) log_info("store_recovered", {{"worker", name}});
      failing.clear();
      Metrics::global().set_store_failing("");
    } catch (const std::exception& e) {
      // The database is busy or failing (a full disk): say so once, keep the job queued, and try
      // again after a pause rather than spin or die. /readyz reports it meanwhile.
      claimed.reset();
      if (failing != e.what()) {
        log_error("store_error", {{"operation", "claim"}, {"worker", name}, {"error", e.what()}});
        Metrics::global().count_store_error();
      }
      failing = e.what();
      Metrics::global().set_store_failing(failing);
    }
    if (!claimed) {
      const std::uint64_t before = seen;
      seen = hub_.wait(seen, std::chrono::milliseconds(1000));
      // Idle for a second: give back what HTTP threads freed too (results sent, models parsed),
      // which the trim after a job cannot see, since they come after it.
      if (seen == before) trim_when_idle();
      continue;
    }
    hub_.notify();
    if (claimed->state) {
      log_info("job_resumed", {{"job", claimed->job.id}, {"from_iteration", claimed->job.iteration},
                               {"attempt", claimed->job.attempts}, {"worker", name}});
    } else {
      log_info("job_started", {{"job", claimed->job.id}, {"attempt", claimed->job.attempts}, {"worker", name}});
    }
    run(*claimed);
    hub_.notify();
    // A large job leaves its factor's and assembly's memory in the allocator's arenas; hand the
    // free pages back so an idle server does not keep the peak of the last job (tests/bench
    // saasgaps_idle_memory measures it; SAASGAPS_MALLOC_TRIM=0 turns this off for its baseline).
    if (trim_after_jobs()) malloc_trim(0);
  }
}

void JobRunner::run(const ClaimedJob& claimed) {
  const std::int64_t id = claimed.job.id;
  try {
    std::string digest;
    const Model model = io::parse_model(claimed.model, &digest);
    std::optional<RestartState> state;
    if (claimed.state) state = io::decode_stored_state(*claimed.state, digest);

    CommittingObserver observer(store_, hub_, id, digest, stopping_);
    const Solution solution = solve(model, &observer, state ? &*state : nullptr, resume_options(claimed.job.settings),
                                    ordering_cache_ ? &*ordering_cache_ : nullptr);

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
    store_.finish(id, final_state, io::result_text(model, solution), message, std::nullopt,
                  observer.last_commit());
    Metrics::global().count_finished(final_state);
    log_info("job_finished", {{"job", id}, {"state", to_string(final_state)}, {"iterations", solution.iterations},
                              {"message", message}});
  } catch (const std::exception& e) {
    try {
      store_.finish(id, JobState::failed, io::failed_result_text(e.what()), std::nullopt, e.what());
      Metrics::global().count_finished(JobState::failed);
      log_error("job_finished", {{"job", id}, {"state", "failed"}, {"error", e.what()}});
    } catch (const std::exception& again) {
      // Even the failure cannot be recorded (a full disk, the database gone): the job stays running
      // in the file and the next server start marks it interrupted and resumes it.
      Metrics::global().count_store_error();
      log_error("job_not_recorded", {{"job", id}, {"error", e.what()}, {"store_error", again.what()},
                                     {"note", "the job stays in the database as running; the next start resumes it"}});
    }
  }
}

}  // namespace saasgaps::service
