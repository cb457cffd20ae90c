#pragma once
/// The routes remote workers use (service/worker_protocol.hpp): fetch a run's work, commit its
/// iterations, finish it, or take a queued job by hand. Every write checks the run's lease in the
/// same transaction that commits it (JobStore), so a stale run gets 409 and changes nothing.

#include <httplib.h>

#include "service/event_hub.hpp"
#include "service/job_store.hpp"

namespace saasgaps::service {

/// Registers the worker routes on `server` (authentication is the server's, as for every route).
void install_worker_api(httplib::Server& server, JobStore& store, EventHub& hub);

}  // namespace saasgaps::service
