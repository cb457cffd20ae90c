#include "service/runs/job_runner.hpp"

#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>

#include "service/ops/log.hpp"
#include "service/runs/adaptive_execution.hpp"
#include "service/runs/job_execution.hpp"
#include "service/runs/metrics.hpp"

namespace saasgaps::service {

namespace {

/// The local executor's sink: commits straight into the store.
class StoreSink final : public RunSink {
 public:
  StoreSink(JobStore& store, EventHub& hub, std::int64_t job) : store_(store), hub_(hub), job_(job) {}

  /// Commits the row and state; the time that takes is recorded as the row's commit_seconds in
  /// the next commit (a row cannot contain the duration of its own commit).
  void iteration(int iteration, const std::string& row, const std::vector<std::uint8_t>& state) override {
    const auto started = std::chrono::steady_clock::now();
    store_.record_iteration(job_, iteration, row, state, last_commit_);
    last_commit_ = {iteration, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()};
    hub_.notify();
    note_iteration(job_, row);
  }

  void thermal(int index, const std::string& row) override {
    store_.record_thermal(job_, index, row);
    hub_.notify();
  }

  bool stop_requested() override { return store_.cancel_requested(job_); }

  void finish(JobState state, const std::optional<std::string>& result, const std::optional<std::string>& message,
              const std::optional<std::string>& error) override {
    store_.finish(job_, state, result, message, error, last_commit_);
    note_finished(store_, job_, state, message, error);
  }

 private:
  JobStore& store_;
  EventHub& hub_;
  std::int64_t job_;
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

}  // namespace

JobRunner::JobRunner(JobStore& store, EventHub& hub, int workers, const std::filesystem::path& ordering_cache,
                     ModelHandoff* handoff)
    : store_(store), hub_(hub), handoff_(handoff) {
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
      // After a write failed for want of space, no job starts until the store finds space again;
      // then the jobs handed on (interrupted) are claimed and resume on their own.
      if (!store_.writable() && store_.recover_writes()) continue;
      const std::uint64_t before = seen;
      seen = hub_.wait(seen, std::chrono::milliseconds(1000));
      // Idle for a second: give back what HTTP threads freed too (results sent, models parsed),
      // which the trim after a job cannot see, since they come after it.
      if (seen == before) {
        // Nothing to claim: a model still kept belongs to a job deleted or cancelled in the queue.
        if (handoff_ != nullptr) handoff_->clear();
        trim_when_idle();
      }
      continue;
    }
    hub_.notify();
    note_run_started(*claimed, name);
    run(*claimed);
    hub_.notify();
    // A large job leaves its factor's and assembly's memory in the allocator's arenas; hand the
    // free pages back so an idle server does not keep the peak of the last job (tests/bench
    // saasgaps_idle_memory measures it; SAASGAPS_MALLOC_TRIM=0 turns this off for its baseline).
    if (trim_after_jobs()) malloc_trim(0);
  }
}

void JobRunner::run(const ClaimedJob& claimed) {
  if (claimed.job.adaptive) {
    // An adaptive job: the assembly's loop (adaptive_execution.hpp), not the stored first model.
    if (handoff_ != nullptr) handoff_->take(claimed.job.id);
    try {
      const std::optional<AdaptiveInput> input = store_.adaptive_input(claimed.job.id);
      if (input) {
        execute_adaptive_run(store_, hub_, claimed, *input, stopping_, ordering_cache_ ? &*ordering_cache_ : nullptr);
        return;
      }
    } catch (const std::exception& e) {
      // The input cannot be read (the database failing): the job stays running and the next start resumes it.
      log_error("store_error", {{"operation", "adaptive_input"}, {"job", claimed.job.id}, {"error", e.what()}});
      return;
    }
  }
  StoreSink sink(store_, hub_, claimed.job.id);
  std::shared_ptr<const ParsedModel> parsed = handoff_ != nullptr ? handoff_->take(claimed.job.id) : nullptr;
  execute_run({claimed.model, std::move(parsed), claimed.state, claimed.job.settings, claimed.job.id}, sink, stopping_,
              ordering_cache_ ? &*ordering_cache_ : nullptr);
}

}  // namespace saasgaps::service
