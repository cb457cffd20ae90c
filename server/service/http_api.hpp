#pragma once
/// The HTTP API of service.md on cpp-httplib: jobs, their iterations, events (Server-Sent Events),
/// results, models, cancel, resume, delete, and the health check. Handlers only read and write the
/// store; solving happens on the JobRunner's threads.

#include <httplib.h>

#include <atomic>
#include <cstddef>
#include <optional>
#include <string>

#include "model.hpp"
#include "service/event_hub.hpp"
#include "service/job_store.hpp"

namespace saasgaps::service {

struct ApiOptions {
  std::optional<std::string> token;  ///< bearer token required on every route but /healthz
  int max_streams = 4;               ///< concurrent event streams (each holds an HTTP thread)
  int workers = 1;                   ///< reported by /healthz
};

class HttpApi {
 public:
  HttpApi(JobStore& store, EventHub& hub, ApiOptions options);
  /// Registers the routes, the authentication check and the error handlers on `server`.
  void install(httplib::Server& server);

 private:
  void submit(const httplib::Request& req, httplib::Response& res);
  /// Queues a validated model document (its text and its model) as a new job: 202 with Location.
  void enqueue(const std::string& body, const Model& model, const httplib::Request& req, httplib::Response& res);
  /// POST /v1/imports: the model document of an uploaded assembly; with ?submit=true, queued as a job.
  void import_assembly(const httplib::Request& req, httplib::Response& res);
  void list(const httplib::Request& req, httplib::Response& res);
  void resume(const httplib::Request& req, httplib::Response& res);
  void events(const httplib::Request& req, httplib::Response& res);
  [[nodiscard]] bool authorized(const httplib::Request& req) const;

  JobStore& store_;
  EventHub& hub_;
  ApiOptions options_;
  std::atomic<int> open_streams_{0};
};

}  // namespace saasgaps::service
