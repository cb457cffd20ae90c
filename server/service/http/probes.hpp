#pragma once
/// The operations routes: /healthz (the service's state), /readyz (whether it can take jobs now:
/// 503 with the reason while the store cannot write) and /metrics (Prometheus text).

#include <httplib.h>

#include "service/http/event_stream.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// Registers the three routes; `workers` is the size of the worker pool they report.
void install_probes(httplib::Server& server, JobStore& store, const EventStreams& streams, int workers);

}  // namespace saasgaps::service
