#pragma once
/// Models read by the POST that validated them, kept for the worker that runs the job. Without it a
/// worker reads the stored document again: 0.3 s of a 3 s job at 150,000 unknowns, 10 % of the
/// service's time over the CLI's for the same model.
///
/// It holds only what a job about to start needs: at most `capacity` models (the oldest queued jobs,
/// which run first; a model submitted while it is full is not kept), each handed out once. Anything
/// missing is read from the database as before, so a restart, a resume or a remote worker loses
/// nothing but the time. An idle worker pool empties it (entries of jobs deleted or cancelled while
/// queued).

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

#include "service/runs/job_execution.hpp"

namespace saasgaps::service {

class ModelHandoff {
 public:
  explicit ModelHandoff(std::size_t capacity) : capacity_(capacity) {}

  /// Keeps the model of a job just queued, unless `capacity` models are kept already.
  void put(std::int64_t job, std::shared_ptr<const ParsedModel> model);
  /// The model kept for `job` (removed from here), or null.
  [[nodiscard]] std::shared_ptr<const ParsedModel> take(std::int64_t job);
  /// Drops every model kept (no job is waiting to start).
  void clear();
  [[nodiscard]] std::size_t size() const;

 private:
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, std::shared_ptr<const ParsedModel>> models_;
};

}  // namespace saasgaps::service
