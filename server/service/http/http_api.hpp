#pragma once
/// The HTTP API of docs/http-api.md on cpp-httplib: jobs, their iterations, events (Server-Sent Events),
/// results, models, cancel, resume, delete, and the health check. Handlers only read and write the
/// store; solving happens on the JobRunner's threads.

#include <httplib.h>

#include <atomic>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

#include "service/http/request_guard.hpp"
#include "service/runs/model_handoff.hpp"
#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::service {

struct ApiOptions {
  std::optional<std::string> token;  ///< bearer token required on every route but /healthz, /readyz
  int max_streams = 4;               ///< concurrent event streams (each holds an HTTP thread)
  int workers = 1;                   ///< reported by /healthz
  std::string listen_host = "127.0.0.1";   ///< a Host name always accepted
  std::vector<std::string> allowed_hosts;  ///< more Host names accepted without a token
  ModelHandoff* handoff = nullptr;  ///< where submitted models wait for the worker pool (local executor)
  std::size_t max_body = std::numeric_limits<std::size_t>::max();  ///< --max-body: the guard's 413
  bool remote_workers = false;      ///< the worker routes answer (executor slurm); 404 otherwise
};

class HttpApi {
 public:
  HttpApi(JobStore& store, EventHub& hub, ApiOptions options);
  /// Registers the routes, the authentication check and the error handlers on `server`.
  void install(httplib::Server& server);

 private:
  void submit(const httplib::Request& req, httplib::Response& res);
  /// Queues a validated model document (its text and its model) as a new job: 202 with Location.
  /// `parsed` (optional): the model read with its digest, handed to the worker that runs the job.
  void enqueue(const std::string& body, const Model& model, const httplib::Request& req, httplib::Response& res,
               std::shared_ptr<const ParsedModel> parsed = nullptr);
  /// POST /v1/imports: the model document of an uploaded assembly; with ?submit=true, queued as a job.
  void import_assembly(const httplib::Request& req, httplib::Response& res);
  void list(const httplib::Request& req, httplib::Response& res);
  void resume(const httplib::Request& req, httplib::Response& res);
  void events(const httplib::Request& req, httplib::Response& res);
  /// Operations routes: /healthz, /readyz, /metrics.
  void install_probes(httplib::Server& server);
  /// The pre-routing guard, request ids, the access log and the 405 answers.
  void install_guards(httplib::Server& server);
  [[nodiscard]] bool ready(std::string& why);

  JobStore& store_;
  EventHub& hub_;
  ApiOptions options_;
  RequestGuard guard_;
  std::atomic<int> open_streams_{0};
};

}  // namespace saasgaps::service
