#include "service/http/worker_api.hpp"

#include <charconv>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/model/model_reader.hpp"
#include "service/http/job_path.hpp"
#include "service/http/problem.hpp"
#include "service/workers/worker_protocol.hpp"

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

void install_worker_api(httplib::Server& server, JobStore& store, EventHub& hub, bool remote_workers) {
  if (!remote_workers) {
    // No worker of this service can exist: the in-process pool runs every job. Answered as the
    // unknown resources they are here, saying why, so no lease can keep a job from the pool and no
    // result can be posted for one.
    const auto absent = [](const httplib::Request& req, httplib::Response&) {
      throw HttpError(404, "Not Found",
                      req.method + " " + req.path + ": no such resource; the remote-worker routes exist only on a "
                      "service started with --executor slurm, for the workers it submits to Slurm");
    };
    for (const char* route : {R"(/v1/jobs/(\d+)/lease)", R"(/v1/jobs/(\d+)/work/iterations)",
                              R"(/v1/jobs/(\d+)/work/thermal)", R"(/v1/jobs/(\d+)/work/finish)"}) {
      server.Post(route, absent);
    }
    server.Get(R"(/v1/jobs/(\d+)/work)", absent);
    return;
  }
  server.Post(R"(/v1/jobs/(\d+)/lease)", [&store](const httplib::Request& req, httplib::Response& res) {
    const std::optional<Lease> ticket = protocol::parse_lease(req.get_header_value(protocol::ticket_header));
    if (!ticket) {
      throw HttpError(400, "Bad Request",
                      std::string("a lease is granted only for the run's ticket, which the service passed to the "
                                  "worker it submitted to Slurm: ") + protocol::ticket_header + ": ATTEMPT:TICKET");
    }
    const std::string who = req.get_header_value("User-Agent");
    const std::string worker = "worker " + req.remote_addr + (who.empty() ? "" : " " + who);
    const Lease lease = store.redeem_ticket(job_in_path(req), *ticket, worker);
    res.status = 201;
    res.set_content(nlohmann::json{{"attempt", lease.attempt}, {"secret", lease.secret}}.dump(), "application/json");
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
  server.Post(R"(/v1/jobs/(\d+)/work/thermal)", [&store, &hub](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const Lease lease = request_lease(req);
    const protocol::ThermalRow t = decoded(req, protocol::decode_thermal);
    store.record_thermal(id, t.index, t.row, &lease);
    hub.notify();
    res.status = 204;
  });
  server.Post(R"(/v1/jobs/(\d+)/work/finish)", [&store, &hub](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const Lease lease = request_lease(req);
    const protocol::Finish f = decoded(req, protocol::decode_finish);
    const std::string digest = protocol::body_digest(req.body);
    res.status = 204;
    // The lease first (cheap), then the model: reading it is for the lease holder only.
    if (!store.finish_allowed(id, lease, digest)) return;  // a retry of the recorded finish
    // Only the digest is wanted: the model was read when it was submitted.
    const std::string expected = io::model_text_digest(store.model(id));
    if (f.model_digest != expected) {
      throw HttpError(422, "Unprocessable Content",
                      "job " + std::to_string(id) + ": the finish is for a model with digest \"" + f.model_digest +
                          "\", not the job's (\"" + expected + "\"); nothing was stored");
    }
    store.finish(id, f.state, f.result, f.message, f.error, {}, &lease, digest);
    hub.notify();
    note_finished(store, id, f.state, f.message, f.error);
  });
}

}  // namespace saasgaps::service
