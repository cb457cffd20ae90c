#pragma once
/// The HTTP API of docs/http-api.md on cpp-httplib: the route table, and the handlers of the job
/// routes (submit, import, list, show, iterations, thermal rows, model, units, cancel, resume,
/// delete). Results (result_routes), events (event_stream), the probes (probes) and what runs around
/// every route (request_hooks) have files of their own. Handlers only read and write the store;
/// solving happens on the JobRunner's threads.

#include <httplib.h>

#include <cstddef>
#include <limits>
#include <map>
#include <mutex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "service/http/assembly_upload.hpp"
#include "service/http/event_stream.hpp"
#include "io/results/load_progress.hpp"
#include "service/http/request_guard.hpp"
#include "service/http/result_routes.hpp"
#include "service/studies/study_routes.hpp"
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
  /// POST /v1/jobs: a model document, validated and queued.
  void submit(const httplib::Request& req, httplib::Response& res);
  /// Queues a validated model document (its text and its model) as a new job: 202 with Location.
  /// `parsed` (optional): the model read with its digest, handed to the worker that runs the job.
  void enqueue(const std::string& body, const Model& model, const httplib::Request& req, httplib::Response& res,
               std::shared_ptr<const ParsedModel> parsed = nullptr);
  /// POST /v1/imports: the model document of an uploaded assembly; with ?submit=true, queued as a job
  /// (with `adapt`, an adaptive job: enqueue_adaptive).
  void import_assembly(const httplib::Request& req, httplib::Response& res);
  /// Queues an uploaded assembly with `adapt` as one adaptive job (runs/adaptive_execution.hpp):
  /// `body` the first mesh's model document. 202 with Location.
  void enqueue_adaptive(const std::string& body, const AssemblyUpload& upload, const httplib::Request& req,
                        httplib::Response& res);
  /// GET /v1/jobs: a page of jobs, newest first (?state=, ?page_size=, ?page_token=).
  void list(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}: the job resource.
  void show(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/iterations: its history rows after ?after=.
  void iterations(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/thermal: its thermal history rows after ?after=.
  void thermal(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/model: the submitted model document.
  void model(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/units: the names of the model's units.
  void units(const httplib::Request& req, httplib::Response& res);
  /// POST /v1/jobs/{id}/cancel.
  void cancel(const httplib::Request& req, httplib::Response& res);
  /// POST /v1/jobs/{id}/resume, with the READ card's changes as its body.
  void resume(const httplib::Request& req, httplib::Response& res);
  /// DELETE /v1/jobs/{id}.
  void remove(const httplib::Request& req, httplib::Response& res);

  JobStore& store_;
  EventHub& hub_;
  ApiOptions options_;
  RequestGuard guard_;
  EventStreams streams_;
  ResultRoutes results_;
  StudyRoutes studies_;
  /// Each job's load path, read once from its model for the progress line (io/results/load_progress.hpp).
  std::mutex plans_mutex_;
  std::map<std::int64_t, io::LoadPlan> plans_;
};

}  // namespace saasgaps::service
