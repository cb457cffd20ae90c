#pragma once
/// `saasgaps worker`: runs one job for a service that may be on another machine. It fetches the
/// job's model and latest restart state, solves with execute_run (the local executor's own code),
/// and sends every iteration's row and state, then the end, back over HTTP. The service commits
/// them; the worker keeps nothing.
///
/// Network failures are retried with exponential backoff for a bounded time; then the worker gives
/// up (exit 4) so its Slurm job ends and the service resubmits the job. A 409 means the run's lease
/// was revoked (cancelled, or presumed dead and replaced): the worker stops at once (exit 5).

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "service/runs/job_execution.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// The service refused this run's lease or ticket (409): another run holds the job, it was
/// cancelled, or the ticket was spent.
class LeaseLost : public RunAbandoned {
 public:
  using RunAbandoned::RunAbandoned;
};

/// The service could not be reached (or kept failing) for longer than the retry budget.
class ServiceUnreachable : public RunAbandoned {
 public:
  using RunAbandoned::RunAbandoned;
};

struct WorkerOptions {
  std::string server;  ///< http://host:port
  std::int64_t job = 0;
  std::optional<Lease> lease;         ///< the run's lease, when already redeemed
  std::optional<Lease> ticket;        ///< otherwise: the run's ticket, redeemed for the lease
  std::optional<std::string> token;   ///< bearer token
  std::chrono::milliseconds retry_for{std::chrono::minutes(2)};  ///< per request, before giving up
  std::chrono::milliseconds first_backoff{250};
  std::function<void(const std::string&)> log;  ///< progress lines (may be empty)
};

/// Exit codes of `saasgaps worker` beyond main()'s 0/1/2.
inline constexpr int worker_exit_unreachable = 4;
inline constexpr int worker_exit_lease_lost = 5;

/// Runs the job to its end; returns 0 when the service recorded the end, worker_exit_unreachable or
/// worker_exit_lease_lost when the run was abandoned. Other failures throw.
int run_worker(const WorkerOptions& options);

}  // namespace saasgaps::service
