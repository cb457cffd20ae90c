#include "service/worker_api.hpp"

#include <charconv>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "service/job_path.hpp"
#include "service/problem.hpp"
#include "service/worker_protocol.hpp"

namespace saasgaps::service {

namespace {

namespace protocol = worker_protocol;

Lease request_lease(const httplib::Request& req) {
  const std::optional<Lease> lease = protocol::parse_lease(req.get_header_value(protocol::lease_header));
  if (!lease) {
    throw HttpError(400, "Bad Request",
                    std::string("worker requests carry the run's lease: ") + protocol::lease_header + ": ATTEMPT:SECRET");
  }
  return *lease;
}

/// Decodes a worker's body; 400 naming what is wrong.
template <class Decode>
auto decoded(const httplib::Request& req, Decode decode) {
  try {
    return decode(req.body);
  } catch (const std::invalid_argument& e) {
    throw HttpError(400, "Bad Request", req.path + ": " + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw HttpError(400, "Bad Request", req.path + ": the body is not CBOR (" + e.what() + ")");
  }
}

}  // namespace

void install_worker_api(httplib::Server& server, JobStore& store, EventHub& hub) {
  server.Post(R"(/v1/jobs/(\d+)/lease)", [&store, &hub](const httplib::Request& req, httplib::Response& res) {
    const std::string who = req.get_header_value("User-Agent");
    const std::string worker = "worker " + req.remote_addr + (who.empty() ? "" : " " + who);
    const ClaimedJob claimed = store.claim_job(job_in_path(req), worker);
    note_run_started(claimed, worker);
    res.status = 201;
    res.set_content(nlohmann::json{{"attempt", claimed.lease.attempt}, {"secret", claimed.lease.secret}}.dump(),
                    "application/json");
    hub.notify();
  });
  server.Get(R"(/v1/jobs/(\d+)/work)", [&store](const httplib::Request& req, httplib::Response& res) {
    res.set_content(protocol::encode_work(store.work(job_in_path(req), request_lease(req))), protocol::cbor_type);
  });
  server.Post(R"(/v1/jobs/(\d+)/work/iterations)", [&store, &hub](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const Lease lease = request_lease(req);
    const protocol::Iteration it = decoded(req, protocol::decode_iteration);
    store.record_iteration(id, it.iteration, it.row, it.state, {}, &lease);
    hub.notify();
    note_iteration(id, it.row);
    res.set_content(nlohmann::json{{"committed", it.iteration}, {"stop", store.cancel_requested(id)}}.dump(),
                    "application/json");
  });
  server.Post(R"(/v1/jobs/(\d+)/work/finish)", [&store, &hub](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const Lease lease = request_lease(req);
    const protocol::Finish f = decoded(req, protocol::decode_finish);
    store.finish(id, f.state, f.result, f.message, f.error, {}, &lease);
    hub.notify();
    note_finished(store, id, f.state, f.message, f.error);
    res.status = 204;
  });
}

}  // namespace saasgaps::service
