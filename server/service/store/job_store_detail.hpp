#pragma once
/// Inside the job store: the connection pool every store file leases from, and the helpers of
/// run_leases.cpp (runs, leases, remote workers, Slurm) that the other store files call. Not for use
/// outside the store's files.

#include <condition_variable>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// Connections handed out one per caller at a time: SQLite connections are not shared across threads,
/// and separate connections let WAL readers run beside the writer. An exclusive-mode pool holds one
/// connection, and callers wait their turn for it.
class JobStore::Pool {
 public:
  Pool(std::string path, OpenMode mode) : path_(std::move(path)), mode_(mode) {}
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] OpenMode mode() const {
    std::lock_guard lock(mutex_);
    return mode_;
  }

  class Lease {
   public:
    Lease(Pool& pool, std::unique_ptr<Connection> c) : pool_(pool), connection_(std::move(c)) {}
    ~Lease() { pool_.give_back(std::move(connection_)); }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Connection& operator*() { return *connection_; }
    Connection* operator->() { return connection_.get(); }

   private:
    Pool& pool_;
    std::unique_ptr<Connection> connection_;
  };

  /// Closes every connection (waiting until all are given back) and opens new ones in `mode` from
  /// now on: a store opened read-only becomes writable once space returns.
  void reopen(OpenMode mode) {
    std::unique_lock lock(mutex_);
    returned_.wait(lock, [&] { return static_cast<int>(idle_.size()) == open_; });
    idle_.clear();
    open_ = 0;
    mode_ = mode;
  }

  Lease lease() {
    std::unique_lock lock(mutex_);
    if (mode_ == OpenMode::exclusive) returned_.wait(lock, [&] { return !idle_.empty() || open_ == 0; });
    if (!idle_.empty()) {
      std::unique_ptr<Connection> c = std::move(idle_.back());
      idle_.pop_back();
      return Lease(*this, std::move(c));
    }
    ++open_;
    lock.unlock();
    try {
      return Lease(*this, std::make_unique<Connection>(path_, mode_));
    } catch (...) {
      lock.lock();
      --open_;
      returned_.notify_one();
      throw;
    }
  }

 private:
  void give_back(std::unique_ptr<Connection> c) {
    {
      std::lock_guard lock(mutex_);
      if (idle_.size() < 16) {
        idle_.push_back(std::move(c));
      } else {
        --open_;
      }
    }
    returned_.notify_one();
  }

  std::string path_;
  OpenMode mode_;
  mutable std::mutex mutex_;
  std::condition_variable returned_;
  std::vector<std::unique_ptr<Connection>> idle_;
  int open_ = 0;  ///< connections alive (leased or idle)
};

namespace detail {

/// Starts a run of a queued or interrupted job: running, attempts + 1, a new lease (with_ticket: a
/// new ticket instead, the lease to be drawn when the worker redeems it); returns what the run needs
/// (model, latest restart state, settings, lease or ticket).
ClaimedJob start_run(Connection& db, std::int64_t id, const std::string& worker, bool with_ticket = false);
/// A run ended without finishing (the server died, its Slurm job ended): the job becomes interrupted,
/// to be resumed from its last committed iteration, or failed beyond max_interruptions; a job whose
/// cancel was acknowledged (cancel_requested committed) becomes cancelled instead, never resumed, its
/// restart state kept. The lease (and ticket) is revoked either way. counted = false: an
/// interruption that is no fault of the run (the database could not be written), not counted
/// against max_interruptions.
void interrupt(Connection& db, std::int64_t id, const std::string& what, int max_interruptions, bool counted = true);
/// A write by a lease holder may go ahead (true), was already made by the same lease (false: a
/// retried request), or is refused (LeaseConflict). `iteration` and `row` for an iteration; without
/// an iteration, a finish, and `row` is the finish's digest (a finished job's spent lease only
/// recognizes the retry of the same finish).
bool check_lease(Connection& db, std::int64_t id, const Lease& lease, std::optional<int> iteration,
                 const std::string& row);
/// Fingerprint of a lease secret and a finish's digest: what a finished job keeps of its spent lease.
std::string spent_lease(const std::string& secret, const std::string& finish_digest);
/// Compares secrets in time independent of where they differ.
bool same_secret(const std::string& a, const std::string& b);

}  // namespace detail
}  // namespace saasgaps::service
