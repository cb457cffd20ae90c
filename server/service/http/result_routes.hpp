#pragma once
/// The routes that read a job's stored result: the document itself, its contact member, its VTU
/// export and its plots. Each answer is tagged (entity_tags.hpp) without reading the result; the
/// document is streamed in pieces, the others read it as typed arrays (io/results/result_arrays.hpp).

#include <httplib.h>

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

 private:
  JobStore& store_;
};

}  // namespace saasgaps::service
