#include "service/http/http_api.hpp"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string_view>

#include "io/model/model_reader.hpp"
#include "io/restart/read_card.hpp"
#include "io/sections/restraint_issues.hpp"
#include "service/http/assembly_upload.hpp"
#include "service/http/entity_tags.hpp"
#include "service/http/job_path.hpp"
#include "service/http/job_views.hpp"
#include "service/http/probes.hpp"
#include "service/http/problem.hpp"
#include "service/http/query_parameters.hpp"
#include "service/http/request_hooks.hpp"
#include "service/http/worker_api.hpp"
#include "service/ops/log.hpp"
#include "service/store/result_cache.hpp"
#include "web/web_assets.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {

/// FNV-1a of a request body: tells an idempotent replay from a different request under the same key.
std::string body_digest(std::string_view body) { return std::to_string(fnv1a(body)); }

/// Reads a JSON request body as models are read (io::parse_document): 400 when it is not JSON
/// (io::NotJsonText), 422 naming the pointer of a repeated key, of a number beyond a double, or of
/// nesting beyond io::max_json_depth.
json json_body(const httplib::Request& req) { return io::parse_document(req.body); }

/// A route's handler: the method `serve` of `owner`, which outlives the server's routes.
template <class Owner>
httplib::Server::Handler handler(Owner& owner, void (Owner::*serve)(const httplib::Request&, httplib::Response&)) {
  return [&owner, serve](const httplib::Request& req, httplib::Response& res) { (owner.*serve)(req, res); };
}

}  // namespace

HttpApi::HttpApi(JobStore& store, EventHub& hub, ApiOptions options)
    : store_(store),
      hub_(hub),
      options_(std::move(options)),
      guard_({options_.token, options_.listen_host, options_.allowed_hosts, options_.max_body}),
      streams_(store, hub, options_.max_streams),
      results_(store),
      studies_(store, hub) {}

void HttpApi::install(httplib::Server& server) {
  install_request_hooks(server, guard_);
  install_probes(server, store_, streams_, options_.workers);

  server.Post("/v1/jobs", handler(*this, &HttpApi::submit));
  server.Post("/v1/imports", handler(*this, &HttpApi::import_assembly));
  server.Get("/v1/jobs", handler(*this, &HttpApi::list));
  server.Get(R"(/v1/jobs/(\d+))", handler(*this, &HttpApi::show));
  server.Get(R"(/v1/jobs/(\d+)/iterations)", handler(*this, &HttpApi::iterations));
  server.Get(R"(/v1/jobs/(\d+)/thermal)", handler(*this, &HttpApi::thermal));
  server.Get(R"(/v1/jobs/(\d+)/events)", handler(streams_, &EventStreams::serve));
  server.Get(R"(/v1/jobs/(\d+)/result)", handler(results_, &ResultRoutes::document));
  server.Get(R"(/v1/jobs/(\d+)/model)", handler(*this, &HttpApi::model));
  server.Get(R"(/v1/jobs/(\d+)/units)", handler(*this, &HttpApi::units));
  server.Get(R"(/v1/jobs/(\d+)/contact)", handler(results_, &ResultRoutes::contact));
  server.Post(R"(/v1/jobs/(\d+)/cancel)", handler(*this, &HttpApi::cancel));
  server.Post(R"(/v1/jobs/(\d+)/resume)", handler(*this, &HttpApi::resume));
  server.Delete(R"(/v1/jobs/(\d+))", handler(*this, &HttpApi::remove));
  server.Get(R"(/v1/jobs/(\d+)/result\.vtu)", handler(results_, &ResultRoutes::vtu));
  server.Get(R"(/v1/jobs/(\d+)/plots/(\w+)\.(png|svg|csv))", handler(results_, &ResultRoutes::picture));
  server.Get(R"(/v1/jobs/(\d+)/probe)", handler(results_, &ResultRoutes::probe));
  for (const web::Asset& asset : web::assets()) {
    server.Get(std::string(asset.path), [asset](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(asset.body), std::string(asset.content_type));
    });
  }
  studies_.install(server);
  install_worker_api(server, store_, hub_, options_.remote_workers);
}

void HttpApi::submit(const httplib::Request& req, httplib::Response& res) {
  // The reader repeats every check of `saasgaps validate`; a bad model never reaches the queue, and
  // a body that is not JSON at all is a 400 (io::NotJsonText) from the same single pass.
  std::shared_ptr<const ParsedModel> parsed = parse_run_model(req.body);
  enqueue(req.body, parsed->model, req, res, parsed);
}

void HttpApi::enqueue(const std::string& body, const Model& model, const httplib::Request& req,
                      httplib::Response& res, std::shared_ptr<const ParsedModel> parsed) {
  io::require_restrained(model);
  // The result cache (docs/studies.md): a model solved before is answered at once by the job that
  // solved it (200, `cached: true`); ?cache=off solves it afresh (and its result answers from then on).
  // A request with an Idempotency-Key keeps its own meaning (a replay answers the job it made).
  const std::string cache = req.has_param("cache") ? req.get_param_value("cache") : "on";
  if (cache != "on" && cache != "off") {
    throw HttpError(400, "Bad Request", "query parameter cache must be on or off; got \"" + cache + "\"");
  }
  const std::optional<ModelKey> cache_key = model_key(std::string_view(body));
  if (cache_key && cache == "on" && !req.has_header("Idempotency-Key")) {
    if (const std::optional<std::int64_t> solved = find_cached(store_, *cache_key)) {
      json view = job_json(store_.get(*solved));
      view["cached"] = true;
      log_info("job_cached", {{"job", *solved}, {"request_id", res.get_header_value("X-Request-Id")}});
      res.set_header("Location", "/v1/jobs/" + std::to_string(*solved));
      send_json(res, 200, view);
      return;
    }
  }
  std::optional<std::string> key;
  if (req.has_header("Idempotency-Key")) key = req.get_header_value("Idempotency-Key");
  const JobStore::Submitted submitted =
      store_.submit(body, model.title, model.solver.max_iterations, key, body_digest(body),
                    cache_key ? std::optional<std::string>(cache_key->key) : std::nullopt);
  if (submitted.replayed) res.set_header("Idempotent-Replayed", "true");
  if (!submitted.replayed) {
    // Before the workers are woken: the job's worker takes the model rather than read it again.
    if (options_.handoff != nullptr && parsed != nullptr) options_.handoff->put(submitted.job.id, std::move(parsed));
    log_info("job_queued", {{"job", submitted.job.id}, {"request_id", res.get_header_value("X-Request-Id")},
                            {"title", model.title}, {"nodes", model.nodes.size()}});
  }
  res.set_header("Location", "/v1/jobs/" + std::to_string(submitted.job.id));
  send_json(res, 202, job_json(submitted.job));
  hub_.notify();
}

void HttpApi::import_assembly(const httplib::Request& req, httplib::Response& res) {
  const AssemblyUpload upload = import_upload(req);
  const std::string submit = req.get_param_value("submit");
  if (submit == "true" || submit == "1") {
    const std::string body = upload.model.dump(1);
    if (upload.assembly.contains("adapt")) {
      enqueue_adaptive(body, upload, req, res);
      return;
    }
    enqueue(body, io::read_model(upload.model), req, res);
    return;
  }
  send_json(res, 200, upload.model);
}

void HttpApi::enqueue_adaptive(const std::string& body, const AssemblyUpload& upload, const httplib::Request& req,
                               httplib::Response& res) {
  if (options_.remote_workers) {
    throw HttpError(501, "Not Implemented",
                    "adaptive jobs (an assembly with adapt) run in the service's own workers; this server hands its "
                    "jobs to remote workers (--executor slurm): run saasgaps solve ASSEMBLY.json instead");
  }
  const Model model = io::read_model(upload.model);
  io::require_restrained(model);
  // What the request asks for: the assembly and every file, so a replay under the same key matches.
  std::string request = upload.input.assembly;
  for (const auto& [name, content] : upload.input.files) request += '\0' + name + '\0' + content;
  std::optional<std::string> key;
  if (req.has_header("Idempotency-Key")) key = req.get_header_value("Idempotency-Key");
  const JobStore::Submitted submitted = store_.submit_adaptive(body, model.title, model.solver.max_iterations,
                                                               upload.input, key, body_digest(request));
  if (submitted.replayed) res.set_header("Idempotent-Replayed", "true");
  if (!submitted.replayed) {
    log_info("job_queued", {{"job", submitted.job.id}, {"request_id", res.get_header_value("X-Request-Id")},
                            {"title", model.title}, {"nodes", model.nodes.size()}, {"adaptive", true}});
  }
  res.set_header("Location", "/v1/jobs/" + std::to_string(submitted.job.id));
  send_json(res, 202, job_json(submitted.job));
  hub_.notify();
}

void HttpApi::list(const httplib::Request& req, httplib::Response& res) {
  std::optional<JobState> state;
  if (req.has_param("state")) {
    state = parse_job_state(req.get_param_value("state"));
    if (!state) {
      throw HttpError(400, "Bad Request", "query parameter state must be one of queued, running, converged, "
                                          "not_converged, failed, cancelled, interrupted; got \"" +
                                              req.get_param_value("state") + "\"");
    }
  }
  const auto page_size = integer_parameter(req, "page_size", 1, 100).value_or(20);
  const auto before = integer_parameter(req, "page_token", 1, INT64_MAX);
  const JobStore::Page page = store_.list(state, static_cast<int>(page_size), before);
  json jobs = json::array();
  for (const JobRecord& j : page.jobs) jobs.push_back(job_list_item(j));
  send_json(res, 200, {{"jobs", jobs},
                       {"next_page_token", page.next_before ? json(std::to_string(*page.next_before)) : json(nullptr)}});
}

void HttpApi::show(const httplib::Request& req, httplib::Response& res) {
  const JobRecord job = store_.get(job_in_path(req));
  json body = job_json(job);
  io::LoadPlan plan;
  {
    std::lock_guard lock(plans_mutex_);
    const auto known = plans_.find(job.id);
    plan = known != plans_.end() ? known->second : plans_.emplace(job.id, io::load_plan(store_.model(job.id))).first->second;
  }
  if (job.adaptive) {
    // The cycles stored so far (docs/http-api.md): the `adaptation` rows of the result, as they come.
    json rows = json::array();
    for (const StoredAdaptCycle& c : store_.adapt_cycles(job.id)) rows.push_back(json::parse(c.row));
    body["adaptation"] = std::move(rows);
    body["links"]["adaptation_plot"] = "/v1/jobs/" + std::to_string(job.id) + "/plots/adaptation.svg";
  }
  const json row = body["last_row"];
  const double elapsed = job.started_at ? io::seconds_since(*job.started_at, std::chrono::system_clock::now()) : 0.0;
  body["progress"] = io::job_progress(plan, row, job.state == JobState::running, job.state == JobState::converged,
                                  job.max_iterations, elapsed);
  body["error_estimate"] = results_.error_estimate(job);
  send_json(res, 200, body);
}

void HttpApi::iterations(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_in_path(req);
  const auto after = integer_parameter(req, "after", 0, 1'000'000'000).value_or(0);
  res.set_content(rows_page(id, "iterations", store_.iterations(id, static_cast<int>(after))), "application/json");
}

void HttpApi::thermal(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_in_path(req);
  const auto after = integer_parameter(req, "after", 0, 1'000'000'000).value_or(0);
  res.set_content(rows_page(id, "thermal", store_.thermal_rows(id, static_cast<int>(after))), "application/json");
}

void HttpApi::model(const httplib::Request& req, httplib::Response& res) {
  std::string model = store_.model(job_in_path(req));
  if (not_modified(req, res, entity_tag(model))) return;
  res.set_content(std::move(model), "application/json");
}

void HttpApi::units(const httplib::Request& req, httplib::Response& res) {
  send_json(res, 200, model_units(store_.model(job_in_path(req))));
}

void HttpApi::cancel(const httplib::Request& req, httplib::Response& res) {
  const JobRecord job = store_.cancel(job_in_path(req));
  log_info("job_cancel_requested", {{"job", job.id}, {"request_id", res.get_header_value("X-Request-Id")},
                                    {"state", to_string(job.state)}});
  send_json(res, 202, job_json(job));
  hub_.notify();
}

void HttpApi::resume(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_in_path(req);
  // The body {tensile_schedule?, max_iterations?, extrapolation_factor?}: every problem is reported
  // with its pointer, like a model's.
  ResumeOptions changes;
  if (!req.body.empty()) {
    changes = io::read_card_from_json(json_body(req), io::ReadCardForm::changes,
                                      io::parse_model(store_.model(id)).gaps.has_value());
  }
  const JobRecord job = store_.resume(id, changes);
  log_info("job_resume_requested", {{"job", id}, {"request_id", res.get_header_value("X-Request-Id")},
                                    {"from_iteration", job.iteration}});
  send_json(res, 202, job_json(job));
  hub_.notify();
}

void HttpApi::remove(const httplib::Request& req, httplib::Response& res) {
  store_.remove(job_in_path(req));
  res.status = 204;
}

}  // namespace saasgaps::service
