#pragma once
/// The routes that read a job's stored result: the document itself, its contact member, its VTU
/// export, its plots and its values at a point. Each answer is tagged (entity_tags.hpp) without reading the result; the
/// document is streamed in pieces, the others read it as typed arrays (io/results/result_arrays.hpp).

#include <httplib.h>

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

class ResultRoutes {
 public:
  explicit ResultRoutes(JobStore& store) : store_(store) {}

  /// GET /v1/jobs/{id}/result: the result document as stored.
  void document(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/contact: the result's contact member alone.
  void contact(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/result.vtu: the result as a VTU file (?format=).
  void vtu(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/plots/{name}.{png,svg,csv}: a picture of the result or its data table; a
  /// running job's convergence plot is drawn from its history so far.
  void picture(const httplib::Request& req, httplib::Response& res);
  /// GET /v1/jobs/{id}/probe?at=R,Z[&field=NAME,...]: the result's values at a point, as `saasgaps
  /// probe --json` prints them (plot/result/point_probe.hpp). 400 a missing or malformed `at` or an
  /// unknown field, 404 no result yet, 409 a failed run, 422 a point in no solid element.
  void probe(const httplib::Request& req, httplib::Response& res);

  /// The finished job's error_estimate ({"relative", "error", "energy_norm"}, docs/results.md) for
  /// the job resource; null while it is queued or runs (also when `job`, read before, has been
  /// resumed and claimed since), when it failed or its result has none. Read from the
  /// stored result once per finish (the result is read past its nodes and elements, which can be
  /// large), then kept.
  nlohmann::json error_estimate(const JobRecord& job);

 private:
  JobStore& store_;
  std::mutex estimates_mutex_;
  /// job id -> (its finish: finished_at and attempts, the estimate then)
  std::map<std::int64_t, std::pair<std::string, nlohmann::json>> estimates_;
};

}  // namespace saasgaps::service
