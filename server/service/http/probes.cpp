#include "service/http/probes.hpp"

#include <string>

#include "service/http/job_views.hpp"
#include "service/runs/metrics.hpp"

namespace saasgaps::service {

namespace {

/// Whether the service can take jobs now; when it cannot, `why` says what stops it.
bool ready(JobStore& store, std::string& why) {
  if (!store.writable()) {
    why = store.why_not_writable();
    return false;
  }
  const std::string failing = Metrics::global().store_failing();
  if (!failing.empty()) {
    why = "database writes are failing: " + failing;
    return false;
  }
  return true;
}

}  // namespace

void install_probes(httplib::Server& server, JobStore& store, const EventStreams& streams, int workers) {
  server.Get("/healthz", [&store, &streams, workers](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200, {{"status", "ok"},
                         {"version", SAASGAPS_VERSION},
                         {"queue_length", store.queue_length()},
                         {"running", store.running_count()},
                         {"workers", workers},
                         {"writable", store.writable()},
                         {"event_streams", streams.open()},
                         {"max_event_streams", streams.max_streams()}});
  });
  server.Get("/readyz", [&store](const httplib::Request&, httplib::Response& res) {
    std::string why;
    if (ready(store, why)) {
      send_json(res, 200, {{"status", "ready"}});
    } else {
      res.set_header("Retry-After", "30");
      send_json(res, 503, {{"status", "not ready"}, {"reason", why}});
    }
  });
  server.Get("/metrics", [&store, &streams, workers](const httplib::Request&, httplib::Response& res) {
    std::string why;
    const bool is_ready = ready(store, why);
    res.set_content(Metrics::global().render(store, {streams.open(), workers, is_ready}),
                    "text/plain; version=0.0.4; charset=utf-8");
  });
}

}  // namespace saasgaps::service
