#pragma once
/// The worker pool: solves queued jobs on its own threads, never on HTTP threads. Each finished
/// iteration is committed (history row and restart state together) before the next starts; a cancel
/// or a shutdown stops a job at its next iteration boundary.

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "service/event_hub.hpp"
#include "service/job_store.hpp"

namespace saasgaps::service {

class JobRunner {
 public:
  JobRunner(JobStore& store, EventHub& hub, int workers);
  /// Stops: running jobs halt at their next iteration boundary and become interrupted, to be
  /// resumed by the next server; then the threads are joined.
  ~JobRunner();
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  [[nodiscard]] int workers() const { return static_cast<int>(threads_.size()); }

 private:
  void work(const std::string& name);
  void run(const ClaimedJob& claimed);

  JobStore& store_;
  EventHub& hub_;
  std::atomic<bool> stopping_{false};
  std::vector<std::thread> threads_;
};

}  // namespace saasgaps::service
