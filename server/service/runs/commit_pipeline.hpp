#pragma once
/// Commits one iteration while the solver computes the next. Encoding a restart state and committing
/// it (an fsync, or a round trip to the service for a remote worker) took 20-25 ms per iteration on
/// a 150,000-unknown job, 10 % of an iteration, all of it on the solver's path; on a second thread
/// it overlaps the next factorization.
///
/// Depth one: `post` first waits for the commit in flight, so at most one finished iteration is not
/// yet committed (and a crash loses at most that one, which nobody was told about: the job resumes
/// from the one before). A commit's failure is kept and rethrown by the next `post` or `wait`, once.

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace saasgaps::service {

class CommitPipeline {
 public:
  CommitPipeline();
  /// Waits for the commit in flight and stops the thread; a failure not yet rethrown is dropped
  /// (call `wait` first to see it).
  ~CommitPipeline();
  CommitPipeline(const CommitPipeline&) = delete;
  CommitPipeline& operator=(const CommitPipeline&) = delete;

  /// Waits for the commit in flight (rethrowing its failure), then starts `commit` on the thread.
  void post(std::function<void()> commit);
  /// Waits for the commit in flight; rethrows its failure if it failed.
  void wait();
  /// True when a commit failed and its exception has not been rethrown yet.
  [[nodiscard]] bool failed() const;

 private:
  void run();
  void wait_locked(std::unique_lock<std::mutex>& lock);

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::function<void()> task_;  // the commit to run; empty when none is waiting
  bool busy_ = false;           // a commit is waiting or running
  bool stopping_ = false;
  std::exception_ptr error_;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace saasgaps::service
