#include "service/studies/study_routes.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "io/import/assembly_reader.hpp"
#include "io/json/json_text.hpp"
#include "io/model/model_reader.hpp"
#include "io/sections/restraint_issues.hpp"
#include "io/study/study_result.hpp"
#include "service/http/assembly_upload.hpp"
#include "service/http/event_stream.hpp"
#include "service/http/job_views.hpp"
#include "service/http/problem.hpp"
#include "service/ops/log.hpp"
#include "service/store/result_cache.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {

std::int64_t study_in_path(const httplib::Request& req) {
  const std::string text = req.matches[1];
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (text.starts_with('0') || error != std::errc() || end != text.data() + text.size()) {
    throw HttpError(404, "Not Found", "no study " + text);
  }
  return id;
}

/// What the point's job state means for the point while it follows the job.
const char* following(JobState state) {
  switch (state) {
    case JobState::queued:
      return "queued";
    case JobState::cancelled:
      return "cancelled";
    default:
      return "running";  // running, or interrupted: the service resumes it
  }
}

template <class Serve>
httplib::Server::Handler handler(StudyRoutes& owner, Serve serve) {
  return [&owner, serve](const httplib::Request& req, httplib::Response& res) { (owner.*serve)(req, res); };
}

}  // namespace

void StudyRoutes::install(httplib::Server& server) {
  server.Post("/v1/studies", handler(*this, &StudyRoutes::submit));
  server.Get("/v1/studies", handler(*this, &StudyRoutes::list));
  server.Get(R"(/v1/studies/(\d+))", handler(*this, &StudyRoutes::show));
  server.Get(R"(/v1/studies/(\d+)/events)", handler(*this, &StudyRoutes::events));
  server.Post(R"(/v1/studies/(\d+)/cancel)", handler(*this, &StudyRoutes::cancel));
  server.Post(R"(/v1/studies/(\d+)/resume)", handler(*this, &StudyRoutes::resume));
}

void StudyRoutes::submit(const httplib::Request& req, httplib::Response& res) {
  // A study of an assembly comes with the files its assembly names (multipart/form-data, a part
  // "study"); each point is imported here, in the upload's private directory, then runs as a model.
  std::optional<UploadedFiles> files;
  if (req.is_multipart_form_data()) files.emplace(req, "study", "POST /v1/studies");
  const std::string& text = files ? files->document() : req.body;
  const json document = io::parse_document(text);
  const bool of_assembly = document.is_object() && document.contains("assembly");
  const io::Study study = io::read_study(document, of_assembly ? std::min(max_points_, max_assembly_points) : max_points_);
  if (study.assembly && !files) {
    throw ModelError({{"/assembly", "a study of an assembly is uploaded with the files its assembly names: "
                                    "multipart/form-data with a part \"study\" (this document) and one part per file, "
                                    "e.g. curl -F study=@s.json -F mesh=@fit.geo"}},
                     "study");
  }
  std::vector<StudyPointInput> points(study.point_count());
  std::size_t cached = 0, refused = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    StudyPointInput& p = points[i];
    json model_document;
    std::optional<Model> model;
    try {
      model_document = study.assembly ? io::import_assembly(study.point_document(i), files->directory(),
                                                            io::FileAccess::base_only)
                                      : study.point_document(i);
      model = io::read_model(model_document);
      io::require_restrained(*model);
    } catch (const ModelError& e) {
      p.status = "failed";
      p.message = io::point_issues(study, i, e);
      ++refused;
      continue;
    } catch (const std::exception& e) {
      p.status = "failed";
      p.message = e.what();
      ++refused;
      continue;
    }
  const ModelKey key = model_key(model_document);
    if (const std::optional<std::int64_t> job = find_cached(store_, key)) {
      if (const std::optional<std::string> result = store_.result(*job)) {
        io::PointOutcome outcome;
        outcome.index = i;
        io::take_result(json::parse(*result), study, outcome);
        p.status = outcome.status;
        p.message = outcome.message;
        p.outputs = io::json_text(outcome.outputs);
        p.cached_job = job;
        ++cached;
        continue;
      }
    }
    p.model = io::json_text(model_document);
    p.title = model->title;
    p.max_iterations = model->solver.max_iterations;
    p.cache_key = key.key;
  }
  const std::int64_t id = store_.create_study(text, study.title, points);
  log_info("study_queued", {{"study", id}, {"request_id", res.get_header_value("X-Request-Id")},
                            {"points", points.size()}, {"cached", cached}, {"refused", refused}});
  hub_.notify();
  res.set_header("Location", "/v1/studies/" + std::to_string(id));
  send_json(res, 202, view(id));
}

json StudyRoutes::view(std::int64_t id) {
  StudyRecord record;
  try {
    record = store_.study(id);
  } catch (const JobNotFound&) {
    throw HttpError(404, "Not Found", "no study " + std::to_string(id));
  }
  const io::Study study = io::read_study(io::parse_document(record.document), std::numeric_limits<std::size_t>::max());
  std::vector<io::PointOutcome> points;
  std::size_t solved = 0;
  for (const StudyPointRow& row : record.points) {
    io::PointOutcome p;
    p.index = row.index;
    p.job = row.job;
    p.cached = row.cached;
    if (row.job && !row.cached) ++solved;
    if (!row.status.empty()) {
      p.status = row.status;
      p.outputs = json::parse(row.outputs);
      p.message = row.message;
    } else if (!row.job_state) {
      p.status = "failed";
      p.message = "its job was deleted before the point's outputs were read";
    } else if (*row.job_state == JobState::converged || *row.job_state == JobState::not_converged) {
      std::optional<std::string> result;
      try {
        result = store_.result(*row.job);
      } catch (const JobConflict&) {
        // Resumed (a not converged job, through /v1/jobs) and claimed since the study was read.
        p.status = following(JobState::running);
        points.push_back(std::move(p));
        continue;
      }
      if (result) {
        io::take_result(json::parse(*result), study, p);
      } else {
        p.status = "failed";
        p.message = "its job has no result";
      }
      store_.set_study_point(id, row.index, p.status, io::json_text(p.outputs), p.message);
    } else if (*row.job_state == JobState::failed) {
      p.status = "failed";
      p.message = row.job_error.value_or("the job failed");
      store_.set_study_point(id, row.index, p.status, "{}", p.message);
    } else {
      p.status = following(*row.job_state);
    }
    points.push_back(std::move(p));
  }
  json out = io::study_result_json(study, points, solved);
  out["id"] = id;
  out["created_at"] = record.created_at;
  return out;
}

void StudyRoutes::show(const httplib::Request& req, httplib::Response& res) { send_json(res, 200, view(study_in_path(req))); }

void StudyRoutes::list(const httplib::Request&, httplib::Response& res) {
  json studies = json::array();
  for (const StudyRecord& r : store_.studies()) {
    std::size_t converged = 0, finished = 0;
    for (const StudyPointRow& p : r.points) {
      const bool done = !p.status.empty() || !p.job_state || is_finished(*p.job_state);
      if (done) ++finished;
      if (p.status == "converged" || (p.status.empty() && p.job_state == JobState::converged)) ++converged;
    }
    studies.push_back({{"id", r.id}, {"title", r.title}, {"created_at", r.created_at},
                       {"points_total", r.points.size()}, {"finished", finished}, {"converged", converged}});
  }
  send_json(res, 200, {{"studies", studies}});
}

void StudyRoutes::cancel(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = study_in_path(req);
  (void)view(id);  // 404 for no study; finished points recorded first
  for (const StudyPointRow& p : store_.study(id).points) {
    if (!p.status.empty() || !p.job || !p.job_state || is_finished(*p.job_state)) continue;
    try {
      store_.cancel(*p.job);
    } catch (const JobConflict&) {
      // finished meanwhile
    }
  }
  hub_.notify();
  log_info("study_cancel_requested", {{"study", id}, {"request_id", res.get_header_value("X-Request-Id")}});
  send_json(res, 202, view(id));
}

void StudyRoutes::resume(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = study_in_path(req);
  (void)view(id);
  for (const StudyPointRow& p : store_.study(id).points) {
    if (!p.status.empty() || !p.job || p.job_state != JobState::cancelled) continue;
    try {
      store_.resume(*p.job, {});
    } catch (const JobConflict&) {
      // changed meanwhile
    }
  }
  hub_.notify();
  log_info("study_resume_requested", {{"study", id}, {"request_id", res.get_header_value("X-Request-Id")}});
  send_json(res, 202, view(id));
}

void StudyRoutes::events(const httplib::Request& req, httplib::Response& res) {
  const std::int64_t id = study_in_path(req);
  (void)view(id);  // 404 before a stream is opened
  auto sent = std::make_shared<std::string>();
  auto number = std::make_shared<int>(0);
  res.set_header("Cache-Control", "no-cache");
  res.set_header("X-Accel-Buffering", "no");
  res.set_chunked_content_provider(
      "text/event-stream",
      [this, id, sent, number](std::size_t, httplib::DataSink& sink) {
        const std::uint64_t seen = hub_.version();
        const json now = view(id);
        const json progress = {{"study", id},           {"status", now["status"]},   {"message", now["message"]},
                               {"converged", now["converged"]}, {"failed", now["failed"]},
                               {"cached", now["cached"]},       {"points_total", now["points_total"]}};
        const std::string data = io::json_text(progress);
        if (data != *sent) {
          *sent = data;
          const std::string text = "id: " + std::to_string(++*number) + "\nevent: progress\ndata: " + data + "\n\n";
          if (!sink.write(text.data(), text.size())) return false;
        }
        if (now["status"] != "running") {
          sink.done();
          return true;
        }
        return wait_or_keep_alive(hub_, seen, sink);
      },
      [](bool) {});
}

}  // namespace saasgaps::service
