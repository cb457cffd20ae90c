#pragma once
/// Wakes whoever waits for news (event streams, idle workers) when the store changes: a version
/// counter under a condition variable. The news itself is read from the database.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace saasgaps::service {

class EventHub {
 public:
  /// Something was committed.
  void notify() {
    {
      std::lock_guard lock(mutex_);
      ++version_;
    }
    changed_.notify_all();
  }

  [[nodiscard]] std::uint64_t version() {
    std::lock_guard lock(mutex_);
    return version_;
  }

  /// Waits until the version differs from `seen` or the timeout passes; returns the version.
  std::uint64_t wait(std::uint64_t seen, std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return version_ != seen; });
    return version_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::uint64_t version_ = 0;
};

}  // namespace saasgaps::service
