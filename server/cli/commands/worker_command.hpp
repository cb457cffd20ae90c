#pragma once
/// `saasgaps worker --server URL --job ID [--token-file F] [--ticket ATTEMPT:TICKET | --lease
/// ATTEMPT:SECRET]`: runs one job for a service, reporting every iteration over HTTP
/// (service/worker_client.hpp). The lease comes from --lease or $SAASGAPS_LEASE, else the worker
/// redeems the run's ticket (--ticket, else $SAASGAPS_TICKET, how the Slurm executor passes it).
/// Without either it cannot run: only a job the service handed to Slurm can be worked on.

#include <cstdint>
#include <string>

namespace saasgaps::cli {

struct WorkerCommandOptions {
  std::string server;
  std::int64_t job = 0;
  std::string lease;
  std::string ticket;
  std::string token_file;
  double retry_for = 120.0;  ///< seconds of failed requests before giving up
};

/// Exit code: 0 the service recorded the run's end, 4 the service stayed unreachable, 5 the service
/// refused the lease. Throws for other failures (main() maps them).
int run_worker_command(const WorkerCommandOptions& options);

}  // namespace saasgaps::cli
