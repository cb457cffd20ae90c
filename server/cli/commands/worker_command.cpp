#include "cli/commands/worker_command.hpp"

#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "cli/common/file_io.hpp"
#include "service/ops/private_directory.hpp"
#include "service/workers/worker_client.hpp"
#include "service/workers/worker_protocol.hpp"

namespace saasgaps::cli {

int run_worker_command(const WorkerCommandOptions& options) {
  service::WorkerOptions worker;
  worker.server = options.server;
  worker.job = options.job;
  std::string lease = options.lease;
  if (lease.empty()) {
    if (const char* from_env = std::getenv("SAASGAPS_LEASE")) lease = from_env;
  }
  std::string ticket = options.ticket;
  if (ticket.empty()) {
    if (const char* from_env = std::getenv("SAASGAPS_TICKET")) ticket = from_env;
  }
  if (!lease.empty()) {
    worker.lease = service::worker_protocol::parse_lease(lease);
    if (!worker.lease) throw std::runtime_error("the lease must look like ATTEMPT:SECRET (attempt >= 1)");
  } else if (!ticket.empty()) {
    worker.ticket = service::worker_protocol::parse_lease(ticket);
    if (!worker.ticket) throw std::runtime_error("the ticket must look like ATTEMPT:TICKET (attempt >= 1)");
  } else {
    throw std::runtime_error("no ticket (--ticket or $SAASGAPS_TICKET) and no lease (--lease or $SAASGAPS_LEASE): "
                             "a worker runs only a job the service handed to Slurm, with the ticket it passed");
  }
  if (!options.token_file.empty()) worker.token = read_token_file(options.token_file);
  worker.retry_for = std::chrono::milliseconds(static_cast<long long>(options.retry_for * 1000.0));
  const std::string prefix = "saasgaps worker (job " + std::to_string(options.job) + ", pid " + std::to_string(::getpid()) + "): ";
  worker.log = [prefix](const std::string& line) { std::cerr << prefix << line << std::endl; };
  // Upload directories of workers on this node killed before they could remove them.
  if (const int removed = service::remove_abandoned_uploads(); removed > 0) {
    worker.log("removed " + std::to_string(removed) + " upload directories of processes that no longer run");
  }
  return service::run_worker(worker);
}

}  // namespace saasgaps::cli
