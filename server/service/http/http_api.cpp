#include "service/http/http_api.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "io/json/json_limits.hpp"
#include "io/json/json_pointer.hpp"
#include "io/json/json_subset.hpp"
#include "io/json/json_text.hpp"
#include "io/model/model_reader.hpp"
#include "io/restart/read_card.hpp"
#include "io/results/result_arrays.hpp"
#include "io/results/vtu_writer.hpp"
#include "io/sections/restraint_issues.hpp"
#include "plot/draw/color_map.hpp"
#include "plot/pictures/plot_request.hpp"
#include "service/http/assembly_upload.hpp"
#include "service/http/guarded_server.hpp"
#include "service/http/job_path.hpp"
#include "service/http/problem.hpp"
#include "service/http/request_id.hpp"
#include "service/http/worker_api.hpp"
#include "service/ops/log.hpp"
#include "service/runs/metrics.hpp"
#include "solver/base/errors.hpp"
#include "web/web_assets.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {

/// FNV-1a, continued from `h`.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 1469598103934665603ULL) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

/// FNV-1a of a request body: tells an idempotent replay from a different request under the same key.
std::string body_digest(std::string_view body) { return std::to_string(fnv1a(body)); }

/// An optional integer query parameter within [low, high]; 400 naming it otherwise.
std::optional<std::int64_t> integer_parameter(const httplib::Request& req, const std::string& name,
                                              std::int64_t low, std::int64_t high) {
  if (!req.has_param(name)) return std::nullopt;
  const std::string text = req.get_param_value(name);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low || value > high) {
    throw HttpError(400, "Bad Request",
                    "query parameter " + name + " must be an integer from " + std::to_string(low) + " to " +
                        std::to_string(high) + ", got \"" + text + "\"");
  }
  return value;
}

/// A JSON text the store wrote, or null when it is missing or damaged (a damaged row must not make
/// the whole job unreadable).
json stored_json(const std::optional<std::string>& text) {
  if (!text) return nullptr;
  try {
    return io::parse_document(*text);
  } catch (const ModelError&) {
    return nullptr;
  }
}

/// The warnings of a run's message: each clause that follows "warning: " up to the next one (the
/// solver appends them to the message as "; warning: ..."). Empty for a clean run, so that clients
/// can tell "converged" from "converged with a warning" without reading prose.
json message_warnings(const std::optional<std::string>& message) {
  json warnings = json::array();
  if (!message) return warnings;
  static constexpr std::string_view marker = "warning: ";
  std::size_t at = message->find(marker);
  while (at != std::string::npos) {
    const std::size_t start = at + marker.size();
    const std::size_t next = message->find("; " + std::string(marker), start);
    warnings.push_back(message->substr(start, next == std::string::npos ? std::string::npos : next - start));
    at = next == std::string::npos ? next : message->find(marker, next);
  }
  return warnings;
}

json job_json(const JobRecord& j) {
  const std::string self = "/v1/jobs/" + std::to_string(j.id);
  return {{"id", j.id},
          {"state", to_string(j.state)},
          {"title", j.title},
          {"created_at", j.created_at},
          {"started_at", j.started_at ? json(*j.started_at) : json(nullptr)},
          {"finished_at", j.finished_at ? json(*j.finished_at) : json(nullptr)},
          {"iteration", j.iteration},
          {"max_iterations", j.max_iterations},
          {"last_row", stored_json(j.last_row)},
          {"attempts", j.attempts},
          {"interruptions", j.interruptions},
          {"cancel_requested", j.cancel_requested},
          {"message", j.message ? json(*j.message) : json(nullptr)},
          {"warnings", message_warnings(j.message)},
          {"error", j.error ? json(*j.error) : json(nullptr)},
          {"resume_settings", io::read_card_to_json(j.settings, io::ReadCardForm::in_force)},
          {"slurm", j.slurm_job_id ? json{{"job_id", *j.slurm_job_id}, {"state", j.slurm_state.value_or("")}} : json(nullptr)},
          {"links",
           {{"self", self},
            {"iterations", self + "/iterations"},
            {"thermal", self + "/thermal"},
            {"events", self + "/events"},
            {"result", self + "/result"},
            {"model", self + "/model"}}}};
}

/// {"job": id, "<member>": [rows]}: the rows are stored as JSON text, spliced rather than parsed and
/// printed again.
std::string rows_page(std::int64_t id, const char* member, const std::vector<std::string>& rows) {
  std::string page = "{\"job\":" + std::to_string(id) + ",\"" + member + "\":[";
  for (std::size_t i = 0; i < rows.size(); ++i) page += (i ? "," : "") + rows[i];
  return page + "]}";
}

/// A job as GET /v1/jobs lists it: the job resource without per-gap arrays (the last row's
/// gap_closures), which grow with the model and belong on the job and its iterations.
json job_list_item(const JobRecord& j) {
  json item = job_json(j);
  if (item["last_row"].is_object()) item["last_row"].erase("gap_closures");
  return item;
}

/// The names of the model's units (its top-level "units" object; {} when it names none), read
/// from the stored model text without building the rest of it.
json model_units(const std::string& model_text) {
  const json model =
      io::parse_json_subset(model_text, [](int depth, std::string_view, std::string_view key) { return depth > 1 || key == "units"; });
  const auto units = model.find("units");
  return units != model.end() && units->is_object() ? *units : json::object();
}

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(io::json_text(body), "application/json");
}

/// Reads a JSON request body as models are read (io::parse_document): 400 when it is not JSON
/// (io::NotJsonText), 422 naming the pointer of a repeated key, of a number beyond a double, or of
/// nesting beyond io::max_json_depth.
json json_body(const httplib::Request& req) { return io::parse_document(req.body); }

/// Releases an event-stream slot when the stream ends, however it ends.
struct StreamSlot {
  std::atomic<int>& open;
  ~StreamSlot() { --open; }
};

}  // namespace

HttpApi::HttpApi(JobStore& store, EventHub& hub, ApiOptions options)
    : store_(store),
      hub_(hub),
      options_(std::move(options)),
      guard_({options_.token, options_.listen_host, options_.allowed_hosts, options_.max_body}) {}

namespace {

/// A validator of a representation: FNV-1a of its bytes (and of what else selects it).
std::string entity_tag(std::string_view bytes, std::string_view variant = {}) {
  return "\"" + std::to_string(fnv1a(variant, fnv1a(std::string_view("\0", 1), fnv1a(bytes)))) + "\"";
}

/// A validator of a job's stored result without reading it: the result is written only by finish(),
/// which stamps finished_at (milliseconds) and counts the run in attempts.
std::string result_tag(JobStore& store, std::int64_t id, std::size_t size, std::string_view variant = {}) {
  const JobRecord job = store.get(id);
  return entity_tag(std::to_string(id) + '/' + job.finished_at.value_or("") + '/' + std::to_string(job.attempts) + '/' +
                        std::to_string(size),
                    variant);
}

/// Sets a weak ETag and answers 304 when If-None-Match names it (RFC 9110 section 13.1.2: weak comparison,
/// "*" matches any).
bool not_modified(const httplib::Request& req, httplib::Response& res, const std::string& tag) {
  // Weak: the same bytes may be sent gzip-compressed or not (a strong tag would have to differ).
  res.set_header("ETag", "W/" + tag);
  const std::string header = req.get_header_value("If-None-Match");
  if (header.empty()) return false;
  std::size_t start = 0;
  while (start < header.size()) {
    auto end = header.find(',', start);
    if (end == std::string::npos) end = header.size();
    std::string candidate = header.substr(start, end - start);
    candidate.erase(0, candidate.find_first_not_of(" \t"));
    candidate.erase(candidate.find_last_not_of(" \t") + 1);
    if (candidate.rfind("W/", 0) == 0) candidate.erase(0, 2);
    if (candidate == "*" || candidate == tag) {
      res.status = 304;
      return true;
    }
    start = end + 1;
  }
  return false;
}

/// The job's stored result, to be read in pieces; 404 when it has none yet.
std::unique_ptr<JobStore::StoredResult> open_stored_result(JobStore& store, std::int64_t id) {
  std::unique_ptr<JobStore::StoredResult> result = store.open_result(id);
  if (!result) {
    throw HttpError(404, "Not Found", "job " + std::to_string(id) + " has no result yet (" + to_string(store.get(id).state) + ")");
  }
  return result;
}

HttpError damaged_result(std::int64_t id, const std::string& what) {
  return HttpError(500, "Internal Server Error", "the stored result of job " + std::to_string(id) + " is damaged (" +
                                                     what + "); resume the job to compute it again");
}

/// What a plot or the VTU export reads of the job's stored result, as typed arrays
/// (io/result_arrays.hpp): no tree of the nodes and elements, and the text never held whole: it is
/// read from the database's blob handle in 64 KiB pieces straight into the SAX reader.
io::ResultArrays stored_result_arrays(JobStore& store, std::int64_t id, const io::ResultSelection& selection) {
  const std::unique_ptr<JobStore::StoredResult> result = open_stored_result(store, id);
  std::size_t offset = 0;
  const io::TextPieces pieces = [&](char* out, std::size_t capacity) {
    const std::size_t count = std::min(capacity, result->size() - offset);
    result->read(offset, out, count);
    offset += count;
    return count;
  };
  try {
    return io::read_result_arrays_pieces(pieces, selection);
  } catch (const io::ResultTextError& e) {
    throw damaged_result(id, std::string("not JSON: ") + e.what());
  } catch (const io::NestingTooDeep& e) {
    throw damaged_result(id, e.issues().front().pointer + ": " + e.issues().front().detail);
  }
}

/// What the convergence plot reads of a result (title, status, iterations, history, gaps), for a
/// job that has none yet: its stored history rows. 409 before its first iteration.
json history_so_far(JobStore& store, const JobRecord& job) {
  json history = json::array();
  for (const std::string& row : store.iterations(job.id, 0)) history.push_back(io::parse_document(row));
  if (history.empty()) {
    throw HttpError(409, "Conflict", "job " + std::to_string(job.id) + " has no iterations yet (" + to_string(job.state) + ")");
  }
  // Only the number of gaps is read (the height of the count axis): one per closure of the last row.
  const std::size_t gaps = history.back().value("gap_closures", json::array()).size();
  return {{"title", job.title},
          {"status", to_string(job.state)},
          {"iterations", job.iteration},
          {"history", std::move(history)},
          {"gaps", json(std::vector<json>(gaps, json::object()))}};
}

/// The plot a request asks for: the name and format from the path, options from the query.
plot::PlotRequest plot_request(const httplib::Request& req) {
  plot::PlotRequest request;
  request.name = req.matches[2];
  request.format = req.matches[3] == "svg" ? plot::ImageFormat::svg : plot::ImageFormat::png;
  constexpr int least = plot::Canvas::min_side, most = plot::Canvas::max_side;
  request.width = static_cast<int>(integer_parameter(req, "width", least, most).value_or(request.width));
  request.height = static_cast<int>(integer_parameter(req, "height", least, most).value_or(request.height));
  request.contour.max_bands = static_cast<int>(integer_parameter(req, "bands", 2, 40).value_or(request.contour.max_bands));
  request.contour.mesh = req.get_param_value("mesh") == "1" || req.get_param_value("mesh") == "true";
  const int samples = static_cast<int>(integer_parameter(req, "samples", 2, 100000).value_or(201));
  try {
    plot::set_deformation(req.get_param_value("deformed"), request.contour);
    if (req.has_param("colormap")) {
      request.contour.color_map = req.get_param_value("colormap");
      plot::ColorMap::require_name(request.contour.color_map);
    }
    if (req.has_param("levels")) request.contour.levels = plot::level_rule(req.get_param_value("levels"));
    plot::set_centre(req.get_param_value("centre"), request.centre);
    plot::set_gap_row(req.get_param_value("gaps"), req.get_param_value("along"), request.row);
    if (req.has_param("path")) request.path = plot::PathOptions{plot::parse_path(req.get_param_value("path")), samples};
  } catch (const std::invalid_argument& e) {
    throw HttpError(400, "Bad Request",
                    std::string("query parameters deformed, colormap, levels, centre, gaps, along, path: ") + e.what());
  }
  return request;
}

}  // namespace

void HttpApi::install_guards(httplib::Server& server) {
  server.set_exception_handler(respond_to_exception);
  server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
    // A path that exists, asked with a method it does not have: 405 naming the ones it has.
    const std::string allow = allowed_methods(req.path);
    if (res.status == 404 && res.body.empty() && !allow.empty()) {
      res.set_header("Allow", allow);
      write_problem(res, 405, "Method Not Allowed", req.method + " " + req.path + ": allowed methods are " + allow);
    }
    fill_error_body(req, res);
    return httplib::Server::HandlerResponse::Handled;
  }));
  server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    res.set_header("X-Request-Id", request_id(req));
    if (!guard_.admit(req, res)) return httplib::Server::HandlerResponse::Handled;
    // No route here takes PUT, PATCH and the like: answer before cpp-httplib waits for their body.
    // (GET, POST and DELETE on a path without them reach the error handler above as a 404.)
    const bool served_method = req.method == "GET" || req.method == "HEAD" || req.method == "POST" ||
                               req.method == "DELETE" || req.method == "OPTIONS";
    const std::string allow = allowed_methods(req.path);
    if (!served_method && !allow.empty()) {
      res.set_header("Allow", allow);
      res.set_header("Connection", "close");
      GuardedServer::close_after_response();
      write_problem(res, 405, "Method Not Allowed", req.method + " " + req.path + ": allowed methods are " + allow);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    std::string id = res.get_header_value("X-Request-Id");
    if (id.empty()) id = request_id(req);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                 GuardedServer::request_started())
                          .count();
    const std::string route = route_label(req.path);
    Metrics::global().count_request(route, res.status);
    log_info("http_request", {{"request_id", id},
                              {"method", req.method},
                              {"path", req.path},
                              {"route", route},
                              {"status", res.status},
                              {"ms", std::round(ms * 1000.0) / 1000.0},
                              {"bytes", res.body.size()},
                              {"remote", req.remote_addr}});
  });
}

bool HttpApi::ready(std::string& why) {
  if (!store_.writable()) {
    why = store_.why_not_writable();
    return false;
  }
  const std::string failing = Metrics::global().store_failing();
  if (!failing.empty()) {
    why = "database writes are failing: " + failing;
    return false;
  }
  return true;
}

void HttpApi::install_probes(httplib::Server& server) {
  server.Get("/healthz", [this](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200, {{"status", "ok"},
                         {"version", SAASGAPS_VERSION},
                         {"queue_length", store_.queue_length()},
                         {"running", store_.running_count()},
                         {"workers", options_.workers},
                         {"writable", store_.writable()},
                         {"event_streams", open_streams_.load()},
                         {"max_event_streams", options_.max_streams}});
  });
  server.Get("/readyz", [this](const httplib::Request&, httplib::Response& res) {
    std::string why;
    if (ready(why)) {
      send_json(res, 200, {{"status", "ready"}});
    } else {
      res.set_header("Retry-After", "30");
      send_json(res, 503, {{"status", "not ready"}, {"reason", why}});
    }
  });
  server.Get("/metrics", [this](const httplib::Request&, httplib::Response& res) {
    std::string why;
    const bool is_ready = ready(why);
    res.set_content(Metrics::global().render(store_, {open_streams_.load(), options_.workers, is_ready}),
                    "text/plain; version=0.0.4; charset=utf-8");
  });
}

void HttpApi::install(httplib::Server& server) {
  install_guards(server);
  install_probes(server);

  server.Post("/v1/jobs", [this](const httplib::Request& req, httplib::Response& res) { submit(req, res); });
  server.Post("/v1/imports", [this](const httplib::Request& req, httplib::Response& res) { import_assembly(req, res); });
  server.Get("/v1/jobs", [this](const httplib::Request& req, httplib::Response& res) { list(req, res); });
  server.Get(R"(/v1/jobs/(\d+))", [this](const httplib::Request& req, httplib::Response& res) {
    send_json(res, 200, job_json(store_.get(job_in_path(req))));
  });
  server.Get(R"(/v1/jobs/(\d+)/iterations)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const auto after = integer_parameter(req, "after", 0, 1'000'000'000).value_or(0);
    res.set_content(rows_page(id, "iterations", store_.iterations(id, static_cast<int>(after))), "application/json");
  });
  server.Get(R"(/v1/jobs/(\d+)/thermal)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const auto after = integer_parameter(req, "after", 0, 1'000'000'000).value_or(0);
    res.set_content(rows_page(id, "thermal", store_.thermal_rows(id, static_cast<int>(after))), "application/json");
  });
  server.Get(R"(/v1/jobs/(\d+)/events)", [this](const httplib::Request& req, httplib::Response& res) { events(req, res); });
  server.Get(R"(/v1/jobs/(\d+)/result)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    std::shared_ptr<JobStore::StoredResult> result = open_stored_result(store_, id);
    if (not_modified(req, res, result_tag(store_, id, result->size()))) return;
    // Streamed from the database in 64 KiB pieces: a result of hundreds of megabytes is never
    // copied whole, let alone parsed. A job deleted meanwhile ends the response early.
    const std::size_t size = result->size();
    res.set_content_provider(
        size, "application/json",
        [result](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
          std::array<char, 1 << 16> piece;
          const std::size_t count = std::min(length, piece.size());
          try {
            result->read(offset, piece.data(), count);
          } catch (const StoreError&) {
            return false;
          }
          return sink.write(piece.data(), count);
        });
  });
  server.Get(R"(/v1/jobs/(\d+)/model)", [this](const httplib::Request& req, httplib::Response& res) {
    std::string model = store_.model(job_in_path(req));
    if (not_modified(req, res, entity_tag(model))) return;
    res.set_content(std::move(model), "application/json");
  });
  server.Get(R"(/v1/jobs/(\d+)/units)", [this](const httplib::Request& req, httplib::Response& res) {
    send_json(res, 200, model_units(store_.model(job_in_path(req))));
  });
  server.Get(R"(/v1/jobs/(\d+)/contact)", [this](const httplib::Request& req, httplib::Response& res) {
    // The dashboard's contact tables: the result's contact member alone, however large the rest is.
    const std::int64_t id = job_in_path(req);
    if (not_modified(req, res, result_tag(store_, id, 0, "contact"))) return;
    const io::ResultArrays result = stored_result_arrays(store_, id, {.mesh = false, .element_keys = {}});
    send_json(res, 200, {{"contact", result.document.value("contact", json::array())}});
  });
  server.Post(R"(/v1/jobs/(\d+)/cancel)", [this](const httplib::Request& req, httplib::Response& res) {
    const JobRecord job = store_.cancel(job_in_path(req));
    log_info("job_cancel_requested", {{"job", job.id}, {"request_id", res.get_header_value("X-Request-Id")},
                                      {"state", to_string(job.state)}});
    send_json(res, 202, job_json(job));
    hub_.notify();
  });
  server.Post(R"(/v1/jobs/(\d+)/resume)", [this](const httplib::Request& req, httplib::Response& res) { resume(req, res); });
  server.Delete(R"(/v1/jobs/(\d+))", [this](const httplib::Request& req, httplib::Response& res) {
    store_.remove(job_in_path(req));
    res.status = 204;
  });
  server.Get(R"(/v1/jobs/(\d+)/result\.vtu)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    if (not_modified(req, res, result_tag(store_, id, 0, "vtu"))) return;
    const io::ResultArrays result = stored_result_arrays(store_, id, io::vtu_result_selection());
    if (result.document.value("status", "") == "failed") {
      throw HttpError(409, "Conflict", "job " + std::to_string(id) + " failed; there is no solution to export");
    }
    res.set_header("Content-Disposition", "attachment; filename=\"job-" + std::to_string(id) + ".vtu\"");
    io::VtuFormat format = io::VtuFormat::binary;
    try {
      if (req.has_param("format")) format = io::vtu_format(req.get_param_value("format"));
    } catch (const std::invalid_argument& e) {
      throw HttpError(400, "Bad Request", std::string("query parameter format: ") + e.what());
    }
    res.set_content(io::result_to_vtu(result, format), "application/xml");
  });
  server.Get(R"(/v1/jobs/(\d+)/plots/(\w+)\.(png|svg|csv))", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_in_path(req);
    const plot::PlotRequest request = plot_request(req);
    try {
      plot::require_plot_name(request.name);
    } catch (const std::invalid_argument& e) {
      throw HttpError(404, "Not Found", e.what());
    }
    // The image follows from the stored result and the query: tag it by both, and skip the drawing
    // when the client already has it.
    // A job still running has no result: its convergence plot is drawn from the rows stored so far
    // (the dashboard follows it live), tagged by its last iteration as well.
    const JobRecord job = store_.get(id);
    const bool live = request.name == "convergence" &&
                      (job.state == JobState::queued || job.state == JobState::running || job.state == JobState::interrupted);
    const std::string variant = live ? req.target + "@" + std::to_string(job.iteration) : req.target;
    if (not_modified(req, res, result_tag(store_, id, 0, variant))) return;
    // The live history is a small tree; a stored result is read as typed arrays.
    const std::optional<json> history = live ? std::optional<json>(history_so_far(store_, job)) : std::nullopt;
    const plot::PlotResult result = history ? plot::PlotResult(*history)
                                            : plot::PlotResult(stored_result_arrays(store_, id, plot::result_selection_for(request)));
    const bool table = req.matches[3] == "csv";
    std::string body;
    try {
      body = table ? plot::render_table(result, request) : plot::render_plot(result, request);
    } catch (const std::invalid_argument& e) {
      // The name is fine but this result cannot show it: a failed run, a closure plot without gaps.
      throw HttpError(409, "Conflict", "job " + std::to_string(id) + ": " + e.what());
    }
    res.set_content(body, table ? "text/csv; charset=utf-8" : plot::media_type(request.format));
  });
  for (const web::Asset& asset : web::assets()) {
    server.Get(std::string(asset.path), [asset](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(asset.body), std::string(asset.content_type));
    });
  }
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
  std::optional<std::string> key;
  if (req.has_header("Idempotency-Key")) key = req.get_header_value("Idempotency-Key");
  const JobStore::Submitted submitted =
      store_.submit(body, model.title, model.solver.max_iterations, key, body_digest(body));
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
  const json model = import_upload(req);
  const std::string submit = req.get_param_value("submit");
  if (submit == "true" || submit == "1") {
    const std::string body = model.dump(1);
    enqueue(body, io::read_model(model), req, res);
    return;
  }
  send_json(res, 200, model);
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

void HttpApi::events(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_in_path(req);
  (void)store_.get(id);  // 404 before a stream is opened
  if (++open_streams_ > options_.max_streams) {
    --open_streams_;
    res.set_header("Retry-After", "5");
    throw HttpError(503, "Service Unavailable",
                    "too many open event streams (" + std::to_string(options_.max_streams) + "); poll " +
                        "/v1/jobs/" + std::to_string(id) + "/iterations?after=N instead, or retry later");
  }
  auto slot = std::make_shared<StreamSlot>(open_streams_);
  std::int64_t last = 0;
  const std::string last_header = req.get_header_value("Last-Event-ID");
  if (!last_header.empty()) std::from_chars(last_header.data(), last_header.data() + last_header.size(), last);
  auto cursor = std::make_shared<std::int64_t>(last);
  res.set_header("Cache-Control", "no-cache");
  res.set_header("X-Accel-Buffering", "no");
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, id, cursor](std::size_t, httplib::DataSink& sink) {
        const std::uint64_t seen = hub_.version();
        const std::vector<JobEvent> events = store_.events(id, *cursor, 100);
        if (!events.empty()) {
          std::string text;
          for (const JobEvent& e : events) {
            text += "id: " + std::to_string(e.id) + "\nevent: " + e.kind + "\ndata: " + e.data + "\n\n";
            *cursor = e.id;
          }
          return sink.write(text.data(), text.size());
        }
        // Nothing new. A job that will not change again ends its stream; a live one waits for news,
        // with a comment line now and then so proxies and clients know the stream is alive.
        const JobState state = store_.get(id).state;
        if (is_finished(state)) {
          sink.done();
          return true;
        }
        if (hub_.wait(seen, std::chrono::seconds(15)) == seen) {
          static const std::string keep_alive = ": keep-alive\n\n";
          return sink.write(keep_alive.data(), keep_alive.size());
        }
        return true;
      },
      [slot](bool) {});
}

}  // namespace saasgaps::service
