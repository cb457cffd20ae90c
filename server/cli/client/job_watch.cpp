#include "cli/client/job_watch.hpp"

#include <unistd.h>

#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "cli/common/progress_table.hpp"
#include "cli/common/usage.hpp"
#include "io/results/history_json.hpp"
#include "io/results/thermal_row_json.hpp"
#include "io/results/load_progress.hpp"

namespace saasgaps::cli {

namespace {

using nlohmann::json;

/// What the live line and the last line show of a job.
struct JobView {
  std::string state = "queued";
  int iteration = 0;
  std::optional<IterationRecord> row;
  json row_json;  ///< the last iteration event's row, for the progress line
};

/// Where the job is on its load path (io/results/load_progress.hpp), from the job as the watch
/// began: the load path, the iteration limit and when it started.
struct PathView {
  io::LoadPlan plan;
  int max_iterations = 0;
  std::chrono::steady_clock::time_point since = std::chrono::steady_clock::now();
  double elapsed_before = 0.0;  ///< seconds the job had run when the watch began
};

/// The live line: "job 3  running  step 2/2 "push", increment 3/10, iteration 12: 20 % of the load
/// path done, about 8 s left" and the row's key columns (live_summary).
std::string live_line(std::int64_t job, const JobView& view, const PathView& path) {
  const double elapsed =
      path.elapsed_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - path.since).count();
  const json progress = io::job_progress(path.plan, view.row_json, view.state == "running",
                                              view.state == "converged", path.max_iterations, elapsed);
  std::string line = "job " + std::to_string(job) + "  " + view.state + "  " + progress.value("text", std::string());
  if (view.row) line += live_summary(*view.row);
  return line;
}

class Watcher {
 public:
  Watcher(std::int64_t job, bool wide, PathView path)
      : job_(job), live_(::isatty(STDOUT_FILENO) == 1), table_(std::cout, wide), path_(std::move(path)) {}

  void on_event(const ServerEvent& event) {
    last_id_ = event.id;
    const json data = json::parse(event.data, nullptr, false);
    if (!data.is_object()) return;  // not ours to read; the next event may be
    if (event.name == "state") {
      view_.state = data.value("state", view_.state);
      view_.iteration = data.value("iteration", view_.iteration);
      if (!live_) std::cout << "job " << job_ << ": " << view_.state << '\n';
    } else if (event.name == "iteration") {
      try {
        view_.row = io::history_row_from_json(data);
      } catch (const json::exception&) {
        return;  // a row of another version: the live line keeps the last one understood
      }
      view_.iteration = view_.row->iteration;
      view_.row_json = data;
      if (!live_) table_.print(*view_.row);
    } else if (event.name == "thermal") {
      try {
        const ThermalRecord row = io::thermal_row_from_json(data);
        // The live line shows the stress iterations; a thermal row gets a line of its own above it.
        if (live_) std::cout << "\r\033[K";
        table_.print(row);
      } catch (const json::exception&) {
        return;  // a row of another version: skipped like an unknown iteration row
      }
    }
    if (live_) std::cout << "\r\033[K" << live_line(job_, view_, path_);
    std::cout.flush();
  }

  /// Ends the live line and prints how the job ended.
  void finish(const json& job) {
    view_.state = job.value("state", view_.state);
    if (live_) std::cout << "\r\033[K" << live_line(job_, view_, path_) << '\n';
    // Piped output has no live line: the job's own progress line closes it.
    if (!live_ && job.contains("progress")) std::cout << "job " << job_ << ": " << job["progress"].value("text", "") << '\n';
    std::cout << "job " << job_ << " " << view_.state;
    const json message = job.value("message", json());
    const json error = job.value("error", json());
    if (error.is_string()) {
      std::cout << ": " << error.get<std::string>();
    } else if (message.is_string()) {
      std::cout << ": " << message.get<std::string>();
    }
    std::cout << std::endl;
  }

  [[nodiscard]] const std::string& last_id() const { return last_id_; }

 private:
  std::int64_t job_;
  bool live_;
  ProgressTable table_;
  PathView path_;
  JobView view_;
  std::string last_id_;
};

}  // namespace

int exit_code_of_job_state(const std::string& state) {
  if (state == "converged") return exit_code::ok;
  if (state == "not_converged" || state == "cancelled" || state == "interrupted") return exit_code::not_converged;
  if (state == "failed") return exit_code::failure;
  return -1;
}

int watch_job(ServiceClient& client, std::int64_t job, bool wide) {
  const std::string path = "/v1/jobs/" + std::to_string(job);
  // The load path, the iteration limit and the time run so far, from the job as the watch begins.
  PathView path_view;
  {
    const json first = json::parse(client.get(path));
    const json progress = first.value("progress", json::object());
    path_view.plan = io::load_plan_of_progress(progress);
    path_view.max_iterations = first.value("max_iterations", 0);
    const json started = first.value("started_at", json());
    if (started.is_string()) path_view.elapsed_before = io::seconds_since(started.get<std::string>(), std::chrono::system_clock::now());
  }
  Watcher watcher(job, wide, std::move(path_view));
  constexpr int reconnects = 5;
  for (int attempt = 0;; ++attempt) {
    // The stream ends when the job has finished, or breaks (the server stopped: the job is then
    // interrupted, which ends this command too, or a network fault: reconnect).
    client.follow_events(path + "/events", watcher.last_id(), [&](const ServerEvent& e) { watcher.on_event(e); });
    // The job's final word (message, error) is the job's own.
    const json state = json::parse(client.get(path));
    const int code = exit_code_of_job_state(state.value("state", ""));
    if (code >= 0) {
      watcher.finish(state);
      return code;
    }
    if (attempt == reconnects) {
      throw std::runtime_error("the event stream of job " + std::to_string(job) + " at " + client.url() +
                               " broke " + std::to_string(reconnects + 1) + " times; the job is still " +
                               state.value("state", "running"));
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
  }
}

}  // namespace saasgaps::cli
