#pragma once
/// The worker pool: solves queued jobs on its own threads, never on HTTP threads. Each finished
/// iteration is committed (history row and restart state together) while the next one computes,
/// and before the one after it starts; a cancel or a shutdown stops a job at its next iteration
/// boundary.

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "service/runs/model_handoff.hpp"
#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"
#include "solver/lac/ordering_cache.hpp"

namespace saasgaps::service {

class JobRunner {
 public:
  /// ordering_cache (optional): a directory where the fill-reducing orderings of the meshes solved
  /// are kept, so resumes and later jobs on the same mesh skip computing them.
  /// handoff (optional): models the HTTP side read already, taken by the job's worker.
  JobRunner(JobStore& store, EventHub& hub, int workers, const std::filesystem::path& ordering_cache = {},
            ModelHandoff* handoff = nullptr);
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
  std::optional<OrderingCache> ordering_cache_;
  ModelHandoff* handoff_;
  std::atomic<bool> stopping_{false};
  std::vector<std::thread> threads_;
};

}  // namespace saasgaps::service
