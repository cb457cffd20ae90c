#include "service/job_runner.hpp"

#include <unistd.h>

#include "service/job_execution.hpp"

namespace saasgaps::service {

namespace {

/// The local executor's sink: commits straight into the store.
class StoreSink final : public RunSink {
 public:
  StoreSink(JobStore& store, EventHub& hub, std::int64_t job) : store_(store), hub_(hub), job_(job) {}

  void iteration(int iteration, const std::string& row, const std::vector<std::uint8_t>& state) override {
    store_.record_iteration(job_, iteration, row, state);
    hub_.notify();
  }

  bool stop_requested() override { return store_.cancel_requested(job_); }

  void finish(JobState state, const std::optional<std::string>& result, const std::optional<std::string>& message,
              const std::optional<std::string>& error) override {
    store_.finish(job_, state, result, message, error);
  }

 private:
  JobStore& store_;
  EventHub& hub_;
  std::int64_t job_;
};

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
  StoreSink sink(store_, hub_, claimed.job.id);
  execute_run({claimed.model, claimed.state, claimed.job.settings}, sink, stopping_);
}

}  // namespace saasgaps::service
