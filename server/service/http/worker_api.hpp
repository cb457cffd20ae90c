#pragma once
/// The routes remote workers use (service/worker_protocol.hpp): redeem a run's ticket for its lease,
/// fetch the run's work, commit its iterations, finish it. Only a job the service handed to Slurm
/// has a ticket, so only such a job can be leased. Every write checks the run's lease in the same
/// transaction that commits it (JobStore), so a stale run gets 409 and changes nothing; a finish
/// spends the lease, and must name the job's model by its digest.

#include <httplib.h>

#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// Registers the worker routes on `server` (authentication is the server's, as for every route).
/// remote_workers false (the local executor): the routes answer 404, saying they exist only with
/// --executor slurm.
void install_worker_api(httplib::Server& server, JobStore& store, EventHub& hub, bool remote_workers);

}  // namespace saasgaps::service
