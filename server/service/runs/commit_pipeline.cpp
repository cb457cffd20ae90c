#include "service/runs/commit_pipeline.hpp"

#include <utility>

namespace saasgaps::service {

CommitPipeline::CommitPipeline() : thread_([this] { run(); }) {}

CommitPipeline::~CommitPipeline() {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !busy_; });
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void CommitPipeline::post(std::function<void()> commit) {
  std::unique_lock lock(mutex_);
  wait_locked(lock);
  task_ = std::move(commit);
  busy_ = true;
  lock.unlock();
  changed_.notify_all();
}

void CommitPipeline::wait() {
  std::unique_lock lock(mutex_);
  wait_locked(lock);
}

bool CommitPipeline::failed() const {
  std::lock_guard lock(mutex_);
  return error_ != nullptr;
}

void CommitPipeline::wait_locked(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [this] { return !busy_; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

void CommitPipeline::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stopping_ || busy_; });
    if (stopping_) return;
    std::function<void()> task = std::move(task_);
    task_ = nullptr;
    lock.unlock();
    std::exception_ptr error;
    try {
      task();
    } catch (...) {
      // Whatever the commit threw (a store error, RunAbandoned) goes to the solver's thread.
      error = std::current_exception();
    }
    lock.lock();
    error_ = error;
    busy_ = false;
    changed_.notify_all();
  }
}

}  // namespace saasgaps::service
