#include "service/http_api.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <memory>
#include <nlohmann/json.hpp>

#include "errors.hpp"
#include "io/json_pointer.hpp"
#include "io/model_reader.hpp"
#include "io/vtu_writer.hpp"
#include "plot/plot_request.hpp"
#include "service/assembly_upload.hpp"
#include "service/problem.hpp"
#include "web/web_assets.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {

/// FNV-1a of a request body: tells an idempotent replay from a different request under the same key.
std::string body_digest(std::string_view body) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : body) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return std::to_string(h);
}

std::int64_t job_id(const httplib::Request& req) {
  std::int64_t id = 0;
  const std::string text = req.matches[1];
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (error != std::errc() || end != text.data() + text.size()) throw JobNotFound(0);
  return id;
}

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

json job_json(const JobRecord& j) {
  const std::string self = "/v1/jobs/" + std::to_string(j.id);
  json settings = json::object();
  if (j.settings.tensile_schedule) settings["tensile_schedule"] = *j.settings.tensile_schedule;
  if (j.settings.extrapolation_factor) settings["extrapolation_factor"] = *j.settings.extrapolation_factor;
  return {{"id", j.id},
          {"state", to_string(j.state)},
          {"title", j.title},
          {"created_at", j.created_at},
          {"started_at", j.started_at ? json(*j.started_at) : json(nullptr)},
          {"finished_at", j.finished_at ? json(*j.finished_at) : json(nullptr)},
          {"iteration", j.iteration},
          {"max_iterations", j.max_iterations},
          {"last_row", j.last_row ? json::parse(*j.last_row) : json(nullptr)},
          {"attempts", j.attempts},
          {"interruptions", j.interruptions},
          {"cancel_requested", j.cancel_requested},
          {"message", j.message ? json(*j.message) : json(nullptr)},
          {"error", j.error ? json(*j.error) : json(nullptr)},
          {"resume_settings", settings},
          {"links",
           {{"self", self},
            {"iterations", self + "/iterations"},
            {"events", self + "/events"},
            {"result", self + "/result"},
            {"model", self + "/model"}}}};
}

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

/// Reads a JSON request body; 400 when it is not JSON.
json json_body(const httplib::Request& req) {
  json body = json::parse(req.body, nullptr, false);
  if (body.is_discarded()) {
    throw HttpError(400, "Bad Request", "the request body is not JSON");
  }
  return body;
}

/// The resume body {tensile_schedule?, max_iterations?, extrapolation_factor?}: every problem is
/// reported with its pointer, like a model.
RunSettings resume_changes(const json& body, bool model_has_gaps) {
  std::vector<InputIssue> issues;
  RunSettings changes;
  if (!body.is_object()) {
    throw ModelError(std::vector<InputIssue>{{"", "the resume body must be an object, like {\"max_iterations\": 40}"}});
  }
  for (const auto& [key, value] : body.items()) {
    const std::string pointer = io::pointer_append("", key);
    if (key == "tensile_schedule") {
      if (!model_has_gaps) issues.push_back({pointer, "the model has no gaps, so it has no tensile schedule"});
      if (!value.is_array() || value.empty()) {
        issues.push_back({pointer, "must be a non-empty array of positive moduli, got " + value.dump()});
        continue;
      }
      std::vector<double> schedule;
      for (std::size_t i = 0; i < value.size(); ++i) {
        if (!value[i].is_number() || !(value[i].get<double>() > 0.0)) {
          issues.push_back({io::pointer_append(pointer, i), "a tensile modulus must be a number > 0, got " + value[i].dump()});
        } else {
          schedule.push_back(value[i].get<double>());
        }
      }
      changes.tensile_schedule = schedule;
    } else if (key == "max_iterations") {
      if (!value.is_number_integer() || value.get<std::int64_t>() < 1 || value.get<std::int64_t>() > 100000) {
        issues.push_back({pointer, "must be an integer from 1 to 100000, got " + value.dump()});
      } else {
        changes.max_iterations = value.get<int>();
      }
    } else if (key == "extrapolation_factor") {
      if (!model_has_gaps) issues.push_back({pointer, "the model has no gaps, so nothing to extrapolate"});
      if (!value.is_number() || !(value.get<double>() >= 0.0 && value.get<double>() < 1.0)) {
        issues.push_back({pointer, "must be a number with 0 <= f < 1, got " + value.dump()});
      } else {
        changes.extrapolation_factor = value.get<double>();
      }
    } else {
      issues.push_back({pointer, "unknown key \"" + key + "\" (known: tensile_schedule, max_iterations, "
                                 "extrapolation_factor)"});
    }
  }
  if (!issues.empty()) throw ModelError(std::move(issues));
  return changes;
}

/// Releases an event-stream slot when the stream ends, however it ends.
struct StreamSlot {
  std::atomic<int>& open;
  ~StreamSlot() { --open; }
};

}  // namespace

HttpApi::HttpApi(JobStore& store, EventHub& hub, ApiOptions options)
    : store_(store), hub_(hub), options_(std::move(options)) {}

namespace {

/// Compares every byte whatever the first difference, so timing does not reveal the token.
bool same_secret(const std::string& given, const std::string& expected) {
  unsigned char difference = given.size() == expected.size() ? 0 : 1;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    difference |= static_cast<unsigned char>(expected[i] ^ (i < given.size() ? given[i] : 0));
  }
  return difference == 0;
}

bool is_public(const std::string& path) {
  if (path == "/healthz") return true;
  for (const web::Asset& asset : web::assets()) {
    if (path == asset.path) return true;
  }
  return false;
}

/// The job's stored result as a document, for plots and exports.
json stored_result(JobStore& store, std::int64_t id) {
  const std::optional<std::string> result = store.result(id);
  if (!result) {
    throw HttpError(404, "Not Found", "job " + std::to_string(id) + " has no result yet (" + to_string(store.get(id).state) + ")");
  }
  return json::parse(*result);
}

/// The plot a request asks for: the name and format from the path, options from the query.
plot::PlotRequest plot_request(const httplib::Request& req) {
  plot::PlotRequest request;
  request.name = req.matches[2];
  request.format = req.matches[3] == "svg" ? plot::ImageFormat::svg : plot::ImageFormat::png;
  request.width = static_cast<int>(integer_parameter(req, "width", 16, 4000).value_or(request.width));
  request.height = static_cast<int>(integer_parameter(req, "height", 16, 4000).value_or(request.height));
  request.contour.max_bands = static_cast<int>(integer_parameter(req, "bands", 2, 40).value_or(request.contour.max_bands));
  request.contour.mesh = req.get_param_value("mesh") == "1" || req.get_param_value("mesh") == "true";
  try {
    plot::set_deformation(req.get_param_value("deformed"), request.contour);
    if (req.has_param("colormap")) request.contour.color_map = req.get_param_value("colormap");
    if (req.has_param("along")) request.closure.along = plot::closure_axis(req.get_param_value("along"));
  } catch (const std::invalid_argument& e) {
    throw HttpError(400, "Bad Request", std::string("query parameters deformed, colormap, along: ") + e.what());
  }
  return request;
}

}  // namespace

bool HttpApi::authorized(const httplib::Request& req) const {
  if (!options_.token || is_public(req.path)) return true;
  // EventSource and <img> cannot send headers: the page passes the token as access_token.
  if (req.has_param("access_token")) return same_secret(req.get_param_value("access_token"), *options_.token);
  return same_secret(req.get_header_value("Authorization"), "Bearer " + *options_.token);
}

void HttpApi::install(httplib::Server& server) {
  server.set_exception_handler(respond_to_exception);
  server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
    fill_error_body(req, res);
    return httplib::Server::HandlerResponse::Handled;
  }));
  server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (authorized(req)) return httplib::Server::HandlerResponse::Unhandled;
    res.set_header("WWW-Authenticate", "Bearer");
    write_problem(res, 401, "Unauthorized", "this server requires an Authorization: Bearer token");
    return httplib::Server::HandlerResponse::Handled;
  });

  server.Post("/v1/jobs", [this](const httplib::Request& req, httplib::Response& res) { submit(req, res); });
  server.Post("/v1/imports", [this](const httplib::Request& req, httplib::Response& res) { import_assembly(req, res); });
  server.Get("/v1/jobs", [this](const httplib::Request& req, httplib::Response& res) { list(req, res); });
  server.Get(R"(/v1/jobs/(\d+))", [this](const httplib::Request& req, httplib::Response& res) {
    send_json(res, 200, job_json(store_.get(job_id(req))));
  });
  server.Get(R"(/v1/jobs/(\d+)/iterations)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_id(req);
    const auto after = integer_parameter(req, "after", 0, 1'000'000'000).value_or(0);
    std::string rows;
    for (const std::string& row : store_.iterations(id, static_cast<int>(after))) {
      rows += (rows.empty() ? "" : ",") + row;
    }
    // The rows are stored as JSON text: splice them rather than parse and print them again.
    res.set_content("{\"job\":" + std::to_string(id) + ",\"iterations\":[" + rows + "]}", "application/json");
  });
  server.Get(R"(/v1/jobs/(\d+)/events)", [this](const httplib::Request& req, httplib::Response& res) { events(req, res); });
  server.Get(R"(/v1/jobs/(\d+)/result)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_id(req);
    std::shared_ptr<JobStore::StoredResult> result = store_.open_result(id);
    if (!result) {
      throw HttpError(404, "Not Found", "job " + std::to_string(id) + " has no result yet (" +
                                            to_string(store_.get(id).state) + ")");
    }
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
    res.set_content(store_.model(job_id(req)), "application/json");
  });
  server.Post(R"(/v1/jobs/(\d+)/cancel)", [this](const httplib::Request& req, httplib::Response& res) {
    send_json(res, 202, job_json(store_.cancel(job_id(req))));
    hub_.notify();
  });
  server.Post(R"(/v1/jobs/(\d+)/resume)", [this](const httplib::Request& req, httplib::Response& res) { resume(req, res); });
  server.Delete(R"(/v1/jobs/(\d+))", [this](const httplib::Request& req, httplib::Response& res) {
    store_.remove(job_id(req));
    res.status = 204;
  });
  server.Get(R"(/v1/jobs/(\d+)/result\.vtu)", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_id(req);
    const json result = stored_result(store_, id);
    if (result.value("status", "") == "failed") {
      throw HttpError(409, "Conflict", "job " + std::to_string(id) + " failed; there is no solution to export");
    }
    res.set_header("Content-Disposition", "attachment; filename=\"job-" + std::to_string(id) + ".vtu\"");
    res.set_content(io::result_to_vtu(result), "application/xml");
  });
  server.Get(R"(/v1/jobs/(\d+)/plots/(\w+)\.(png|svg))", [this](const httplib::Request& req, httplib::Response& res) {
    const std::int64_t id = job_id(req);
    const plot::PlotRequest request = plot_request(req);
    try {
      plot::require_plot_name(request.name);
    } catch (const std::invalid_argument& e) {
      throw HttpError(404, "Not Found", e.what());
    }
    const json result = stored_result(store_, id);
    std::string image;
    try {
      image = plot::render_plot(result, request);
    } catch (const std::invalid_argument& e) {
      // The name is fine but this result cannot show it: a failed run, a closure plot without gaps.
      throw HttpError(409, "Conflict", "job " + std::to_string(id) + ": " + e.what());
    }
    res.set_content(image, request.format == plot::ImageFormat::svg ? "image/svg+xml" : "image/png");
  });
  for (const web::Asset& asset : web::assets()) {
    server.Get(std::string(asset.path), [asset](const httplib::Request&, httplib::Response& res) {
      res.set_content(std::string(asset.body), std::string(asset.content_type));
    });
  }
  server.Get("/healthz", [this](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200, {{"status", "ok"},
                         {"queue_length", store_.queue_length()},
                         {"running", store_.running_count()},
                         {"workers", options_.workers},
                         {"event_streams", open_streams_.load()},
                         {"max_event_streams", options_.max_streams}});
  });
}

void HttpApi::submit(const httplib::Request& req, httplib::Response& res) {
  if (!json::accept(req.body)) throw HttpError(400, "Bad Request", "the request body is not JSON");
  // The reader repeats every check of `saasgaps validate`; a bad model never reaches the queue.
  enqueue(req.body, io::parse_model(req.body), req, res);
}

void HttpApi::enqueue(const std::string& body, const Model& model, const httplib::Request& req,
                      httplib::Response& res) {
  std::optional<std::string> key;
  if (req.has_header("Idempotency-Key")) key = req.get_header_value("Idempotency-Key");
  const JobStore::Submitted submitted =
      store_.submit(body, model.title, model.solver.max_iterations, key, body_digest(body));
  if (submitted.replayed) res.set_header("Idempotent-Replayed", "true");
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
  for (const JobRecord& j : page.jobs) jobs.push_back(job_json(j));
  send_json(res, 200, {{"jobs", jobs},
                       {"next_page_token", page.next_before ? json(std::to_string(*page.next_before)) : json(nullptr)}});
}

void HttpApi::resume(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_id(req);
  RunSettings changes;
  if (!req.body.empty()) {
    changes = resume_changes(json_body(req), io::parse_model(store_.model(id)).gaps.has_value());
  }
  send_json(res, 202, job_json(store_.resume(id, changes)));
  hub_.notify();
}

void HttpApi::events(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_id(req);
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
