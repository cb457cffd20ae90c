#pragma once
/// The progress line of a job (docs/http-api.md, "Progress"): where on its load path the run is
/// (step, increment, iteration), the fraction of the load path done and an estimate of the time
/// left. The job's JSON carries it as `progress`; `saasgaps watch` and the dashboard show its text.

#include <chrono>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// A model's load path: each step's name and increments, in order; empty for a model without steps.
struct LoadPlan {
  std::vector<std::pair<std::string, int>> steps;
};

/// The load path of a model document's text (only its steps' names and increments are read).
/// A text that is not a model gives an empty plan.
LoadPlan load_plan(std::string_view model_text);

/// The load path a job's `progress` carries (its load_path; empty without steps).
LoadPlan load_plan_of_progress(const nlohmann::json& progress);

/// The job's progress from its last history row (`row`: null before the first iteration), its
/// state and the seconds it has run:
///   {"load_path": [{"name", "increments"}] (null without steps), "step", "steps", "step_name", "increment", "increments", "iteration", "max_iterations",
///    "fraction", "seconds_left", "text"}
/// step and increment are 1-based (a model without steps has one step of one increment: no name).
/// fraction = increments finished / increments of the whole path (1 once the job converged);
/// seconds_left = elapsed (1 - fraction) / fraction, null until an increment has finished (and
/// once the job has stopped). max_iterations bounds the iterations of each increment.
nlohmann::json job_progress(const LoadPlan& plan, const nlohmann::json& row, bool running, bool converged,
                            int max_iterations, double elapsed_seconds);

/// Seconds from an ISO 8601 UTC time as the service writes it (service/ops/utc_time.hpp) to `now`; 0 when the
/// text is not such a time.
double seconds_since(const std::string& utc, std::chrono::system_clock::time_point now);

}  // namespace saasgaps::io
