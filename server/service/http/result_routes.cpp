#include "service/http/result_routes.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/json/json_limits.hpp"
#include "io/model/model_reader.hpp"
#include "io/results/result_arrays.hpp"
#include "io/results/vtu_writer.hpp"
#include "plot/pictures/path_plot.hpp"
#include "plot/pictures/plot_request.hpp"
#include "plot/result/point_probe.hpp"
#include "service/http/entity_tags.hpp"
#include "service/http/job_path.hpp"
#include "service/http/job_views.hpp"
#include "service/http/problem.hpp"
#include "service/http/query_parameters.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {

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

/// What the adaptation plot reads of an adaptive job, running or finished: its stored cycles and
/// the target of its assembly's `adapt`. 409 for a job that is not adaptive, or before its first cycle.
json adaptation_so_far(JobStore& store, const JobRecord& job) {
  json rows = json::array();
  for (const StoredAdaptCycle& c : store.adapt_cycles(job.id)) rows.push_back(io::parse_document(c.row));
  if (rows.empty()) {
    throw HttpError(409, "Conflict", "job " + std::to_string(job.id) +
                                         (job.adaptive ? std::string(" has no adaptive cycle yet (") + to_string(job.state) + ")"
                                                       : " is not an adaptive job (an assembly with adapt)"));
  }
  double target = 0.0;
  if (const std::optional<AdaptiveInput> input = store.adaptive_input(job.id)) {
    const json assembly = io::parse_document(input->assembly);
    target = assembly.value("/adapt/target_error"_json_pointer, 0.0);
  }
  return {{"title", job.title}, {"status", to_string(job.state)}, {"adaptation", std::move(rows)},
          {"target_error", target}};
}

}  // namespace

void ResultRoutes::document(const httplib::Request& req, httplib::Response& res) {
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
}

void ResultRoutes::contact(const httplib::Request& req, httplib::Response& res) {
  // The dashboard's contact tables: the result's contact member alone, however large the rest is.
  const std::int64_t id = job_in_path(req);
  if (not_modified(req, res, result_tag(store_, id, 0, "contact"))) return;
  const io::ResultArrays result = stored_result_arrays(store_, id, {.mesh = false, .element_keys = {}});
  send_json(res, 200, {{"contact", result.document.value("contact", json::array())}});
}

void ResultRoutes::vtu(const httplib::Request& req, httplib::Response& res) {
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
}

void ResultRoutes::picture(const httplib::Request& req, httplib::Response& res) {
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
  if (request.name == "adaptation") {
    // Drawn from the stored cycles (live while the job runs), never from the result: small enough
    // to draw every time.
    const json document = adaptation_so_far(store_, job);
    const plot::PlotResult cycles(document);  // views the document
    const bool csv = req.matches[3] == "csv";
    try {
      res.set_content(csv ? plot::render_table(cycles, request) : plot::render_plot(cycles, request),
                      csv ? "text/csv; charset=utf-8" : plot::media_type(request.format));
    } catch (const std::invalid_argument& e) {
      throw HttpError(409, "Conflict", "job " + std::to_string(id) + ": " + e.what());
    }
    return;
  }
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
}

json ResultRoutes::error_estimate(const JobRecord& job) {
  // A finished run that wrote a result: converged, not converged, or cancelled at an iteration. A
  // queued job keeps the finished_at of the run before its resume: that run's estimate no longer holds.
  const bool finished = job.state == JobState::converged || job.state == JobState::not_converged ||
                        job.state == JobState::cancelled;
  if (!job.finished_at || !finished) return nullptr;
  const std::string finish = *job.finished_at + "/" + std::to_string(job.attempts);
  {
    std::lock_guard lock(estimates_mutex_);
    if (const auto known = estimates_.find(job.id); known != estimates_.end() && known->second.first == finish) {
      return known->second.second;
    }
  }
  json estimate = nullptr;
  try {
    const io::ResultArrays result = stored_result_arrays(store_, job.id, {.mesh = false, .element_keys = {}});
    if (const auto found = result.document.find("error_estimate"); found != result.document.end() && found->is_object()) {
      estimate = *found;
    }
  } catch (const HttpError&) {
    return nullptr;  // no result (deleted meanwhile) or a damaged one: the job resource still answers
  } catch (const JobConflict&) {
    return nullptr;  // resumed and claimed again since `job` was read: running, no estimate
  }
  std::lock_guard lock(estimates_mutex_);
  estimates_[job.id] = {finish, estimate};
  return estimate;
}

void ResultRoutes::probe(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = job_in_path(req);
  if (!req.has_param("at")) throw HttpError(400, "Bad Request", "query parameter at is required: the point r,z");
  plot::PlanePoint at{};
  std::vector<std::string> fields;
  try {
    at = plot::parse_point(req.get_param_value("at"));
  } catch (const std::invalid_argument& e) {
    throw HttpError(400, "Bad Request", std::string("query parameter at: ") + e.what());
  }
  if (req.has_param("field")) {
    const std::string list = req.get_param_value("field");
    for (std::size_t begin = 0; begin <= list.size();) {
      const std::size_t end = std::min(list.find(',', begin), list.size());
      if (end > begin) fields.push_back(list.substr(begin, end - begin));
      begin = end + 1;
    }
  }
  io::ResultSelection selection;
  try {
    for (const std::string& key : plot::probe_element_keys(fields)) selection.element_keys.push_back(key);
  } catch (const std::invalid_argument& e) {
    throw HttpError(400, "Bad Request", std::string("query parameter field: ") + e.what());
  }
  if (not_modified(req, res, result_tag(store_, id, 0, req.target))) return;
  const plot::PlotResult result(stored_result_arrays(store_, id, selection));
  try {
    const plot::Probe probe = plot::probe_point(result, at, fields);
    send_json(res, 200, plot::probe_json(probe, result.mesh()));
  } catch (const plot::PointOutsideMesh& e) {
    throw HttpError(422, "Unprocessable Content", "job " + std::to_string(id) + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    // A gap field, or a result without a mesh (a failed run).
    throw HttpError(409, "Conflict", "job " + std::to_string(id) + ": " + e.what());
  }
}

}  // namespace saasgaps::service
