#pragma once
/// The study routes (docs/studies.md, docs/http-api.md):
///   POST /v1/studies                 a study document: judged whole (422 with every error at its
///                                    pointer), each point's model read (a point the reader refuses
///                                    fails alone), each point answered from the result cache or
///                                    queued as a job; 202 with Location /v1/studies/{id}. A study
///                                    of an assembly comes as multipart/form-data (a part "study"
///                                    and the files its assembly names): each point is imported
///                                    (meshed) before the answer, an import that fails fails that
///                                    point alone, and the imported model runs as any point's
///   GET  /v1/studies                 every study, newest first, with its counts
///   GET  /v1/studies/{id}            the study result: points with their states, jobs and outputs
///   GET  /v1/studies/{id}/events     Server-Sent Events: `progress` when a point finishes, until none runs
///   POST /v1/studies/{id}/cancel     cancels every point's job still queued or running
///   POST /v1/studies/{id}/resume     resumes every cancelled or interrupted point's job
/// A point's outputs are reduced from its job's result when the job has finished (at the first read
/// of the study after that) and stored with the point.

#include <httplib.h>

#include <atomic>
#include <cstddef>

#include "io/study/study_document.hpp"
#include "service/store/event_hub.hpp"
#include "service/store/job_store.hpp"

namespace saasgaps::service {

/// Points a study of an assembly may have through the service: each is imported (its mesh made by
/// the sandboxed mesher) while the request waits.
inline constexpr std::size_t max_assembly_points = 100;

class StudyRoutes {
 public:
  StudyRoutes(JobStore& store, EventHub& hub, std::size_t max_points = io::default_max_study_points)
      : store_(store), hub_(hub), max_points_(max_points) {}

  void install(httplib::Server& server);

 private:
  void submit(const httplib::Request& req, httplib::Response& res);
  void list(const httplib::Request& req, httplib::Response& res);
  void show(const httplib::Request& req, httplib::Response& res);
  void events(const httplib::Request& req, httplib::Response& res);
  void cancel(const httplib::Request& req, httplib::Response& res);
  void resume(const httplib::Request& req, httplib::Response& res);

  /// The study result document of a study now (finished points' outputs reduced and stored first).
  nlohmann::json view(std::int64_t id);

  JobStore& store_;
  EventHub& hub_;
  std::size_t max_points_;
};

}  // namespace saasgaps::service
