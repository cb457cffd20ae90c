#pragma once
/// Counters for GET /metrics, in the Prometheus text exposition format (version 0.0.4). Counters
/// that live in the process (HTTP requests, iterations, solve time) are kept here; gauges that live
/// in the database (jobs by state, queue length, file size) are read from the store when scraped.
/// One registry per process, like Prometheus client libraries' default registry.

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "service/store/job_store.hpp"

namespace saasgaps::service {

class Metrics {
 public:
  static Metrics& global();

  void count_request(const std::string& route, int status);
  void count_iteration(double seconds);
  void count_finished(JobState state);
  void count_store_error();
  /// The worker pool's last database failure ("" once a write succeeds again): /readyz reports it.
  void set_store_failing(const std::string& why);
  [[nodiscard]] std::string store_failing();

  struct Gauges {
    int open_streams = 0;
    int workers = 0;
    bool ready = true;
  };
  /// The exposition text: the counters above and the store's gauges.
  [[nodiscard]] std::string render(JobStore& store, const Gauges& gauges);

 private:
  std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> requests_;
  std::map<std::string, std::uint64_t> finished_;
  std::uint64_t iterations_ = 0;
  double solve_seconds_ = 0.0;
  std::uint64_t store_errors_ = 0;
  std::string store_failing_;
};

/// The route a path belongs to, as a metrics label: "/v1/jobs/{id}/result", ... or "other".
std::string route_label(const std::string& path);

/// The methods a known route allows ("GET, HEAD", ...), or "" for a path no route serves.
std::string allowed_methods(const std::string& path);

}  // namespace saasgaps::service
