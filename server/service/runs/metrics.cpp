#include "service/runs/metrics.hpp"

#include <regex>
#include <sstream>

#include "web/web_assets.hpp"

namespace saasgaps::service {

namespace {

struct Route {
  std::regex pattern;
  std::string label;
  std::string allow;
};

const std::vector<Route>& routes() {
  static const std::vector<Route> table = [] {
    std::vector<Route> t = {
        {std::regex(R"(/v1/jobs)"), "/v1/jobs", "GET, HEAD, POST"},
        {std::regex(R"(/v1/jobs/\d+)"), "/v1/jobs/{id}", "GET, HEAD, DELETE"},
        {std::regex(R"(/v1/jobs/\d+/iterations)"), "/v1/jobs/{id}/iterations", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/thermal)"), "/v1/jobs/{id}/thermal", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/events)"), "/v1/jobs/{id}/events", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/result)"), "/v1/jobs/{id}/result", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/result\.vtu)"), "/v1/jobs/{id}/result.vtu", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/model)"), "/v1/jobs/{id}/model", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/plots/\w+\.(png|svg))"), "/v1/jobs/{id}/plots/{name}", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/cancel)"), "/v1/jobs/{id}/cancel", "POST"},
        {std::regex(R"(/v1/jobs/\d+/resume)"), "/v1/jobs/{id}/resume", "POST"},
        // The remote worker protocol (worker_api.cpp): bodies and answers are CBOR.
        {std::regex(R"(/v1/jobs/\d+/lease)"), "/v1/jobs/{id}/lease", "POST"},
        {std::regex(R"(/v1/jobs/\d+/work)"), "/v1/jobs/{id}/work", "GET, HEAD"},
        {std::regex(R"(/v1/jobs/\d+/work/iterations)"), "/v1/jobs/{id}/work/iterations", "POST"},
        {std::regex(R"(/v1/jobs/\d+/work/thermal)"), "/v1/jobs/{id}/work/thermal", "POST"},
        {std::regex(R"(/v1/jobs/\d+/work/finish)"), "/v1/jobs/{id}/work/finish", "POST"},
        {std::regex(R"(/v1/imports)"), "/v1/imports", "POST"},
        {std::regex(R"(/healthz)"), "/healthz", "GET, HEAD"},
        {std::regex(R"(/readyz)"), "/readyz", "GET, HEAD"},
        {std::regex(R"(/metrics)"), "/metrics", "GET, HEAD"},
    };
    for (const web::Asset& asset : web::assets()) {
      t.push_back({std::regex(std::regex_replace(std::string(asset.path), std::regex(R"([.])"), R"(\.)")),
                   "/ (dashboard)", "GET, HEAD"});
    }
    return t;
  }();
  return table;
}

const Route* find_route(const std::string& path) {
  for (const Route& r : routes()) {
    if (std::regex_match(path, r.pattern)) return &r;
  }
  return nullptr;
}

/// A label value with \ " and newline escaped (the exposition format's rule).
std::string label_value(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

}  // namespace

std::string route_label(const std::string& path) {
  const Route* r = find_route(path);
  return r != nullptr ? r->label : "other";
}

std::string allowed_methods(const std::string& path) {
  const Route* r = find_route(path);
  return r != nullptr ? r->allow : "";
}

Metrics& Metrics::global() {
  static Metrics metrics;
  return metrics;
}

void Metrics::count_request(const std::string& route, int status) {
  std::lock_guard lock(mutex_);
  ++requests_[{route, status}];
}

void Metrics::count_iteration(double seconds) {
  std::lock_guard lock(mutex_);
  ++iterations_;
  solve_seconds_ += seconds;
}

void Metrics::count_finished(JobState state) {
  std::lock_guard lock(mutex_);
  ++finished_[to_string(state)];
}

void Metrics::count_store_error() {
  std::lock_guard lock(mutex_);
  ++store_errors_;
}

void Metrics::set_store_failing(const std::string& why) {
  std::lock_guard lock(mutex_);
  store_failing_ = why;
}

std::string Metrics::store_failing() {
  std::lock_guard lock(mutex_);
  return store_failing_;
}

std::string Metrics::render(JobStore& store, const Gauges& gauges) {
  std::ostringstream out;
  out.precision(17);
  out << "# HELP saasgaps_jobs Jobs in the database by state.\n# TYPE saasgaps_jobs gauge\n";
  for (const auto& [state, count] : store.count_by_state()) {
    out << "saasgaps_jobs{state=\"" << to_string(state) << "\"} " << count << '\n';
  }
  out << "# HELP saasgaps_queue_length Jobs waiting for a worker (queued or interrupted).\n"
         "# TYPE saasgaps_queue_length gauge\nsaasgaps_queue_length "
      << store.queue_length() << '\n';
  out << "# HELP saasgaps_workers Jobs solved at once.\n# TYPE saasgaps_workers gauge\nsaasgaps_workers "
      << gauges.workers << '\n';
  out << "# HELP saasgaps_event_streams_open Open Server-Sent Event streams.\n"
         "# TYPE saasgaps_event_streams_open gauge\nsaasgaps_event_streams_open "
      << gauges.open_streams << '\n';
  out << "# HELP saasgaps_ready 1 when the server takes jobs (see /readyz).\n# TYPE saasgaps_ready gauge\n"
         "saasgaps_ready "
      << (gauges.ready ? 1 : 0) << '\n';
  out << "# HELP saasgaps_database_bytes Size of the SQLite file and its WAL.\n"
         "# TYPE saasgaps_database_bytes gauge\nsaasgaps_database_bytes "
      << store.database_bytes() << '\n';
  std::lock_guard lock(mutex_);
  out << "# HELP saasgaps_iterations_total Iterations solved and committed by this process.\n"
         "# TYPE saasgaps_iterations_total counter\nsaasgaps_iterations_total "
      << iterations_ << '\n';
  out << "# HELP saasgaps_solve_seconds_total Wall time of those iterations.\n"
         "# TYPE saasgaps_solve_seconds_total counter\nsaasgaps_solve_seconds_total "
      << solve_seconds_ << '\n';
  out << "# HELP saasgaps_jobs_finished_total Runs ended by this process, by final state.\n"
         "# TYPE saasgaps_jobs_finished_total counter\n";
  for (const auto& [state, count] : finished_) {
    out << "saasgaps_jobs_finished_total{state=\"" << state << "\"} " << count << '\n';
  }
  out << "# HELP saasgaps_store_errors_total Database operations that failed (disk full, I/O).\n"
         "# TYPE saasgaps_store_errors_total counter\nsaasgaps_store_errors_total "
      << store_errors_ << '\n';
  out << "# HELP saasgaps_http_requests_total HTTP requests answered, by route and status.\n"
         "# TYPE saasgaps_http_requests_total counter\n";
  for (const auto& [key, count] : requests_) {
    out << "saasgaps_http_requests_total{route=\"" << label_value(key.first) << "\",status=\"" << key.second
        << "\"} " << count << '\n';
  }
  return out.str();
}

}  // namespace saasgaps::service
