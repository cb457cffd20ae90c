#include "io/results/load_progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>

#include "io/json/json_subset.hpp"

namespace saasgaps::io {

using nlohmann::json;

LoadPlan load_plan_of_progress(const json& progress) {
  LoadPlan plan;
  const auto path = progress.find("load_path");
  if (path == progress.end() || !path->is_array()) return plan;
  for (const json& s : *path) {
    if (s.is_object()) plan.steps.emplace_back(s.value("name", std::string()), s.value("increments", 1));
  }
  return plan;
}

LoadPlan load_plan(std::string_view model_text) {
  LoadPlan plan;
  try {
    // Only the steps' names and increments: one pass over the text, no tree of the mesh.
    const json model = parse_json_subset(model_text, [](int depth, std::string_view section, std::string_view key) {
      if (depth == 1) return key == "steps";
      // The steps' own members (their loads and constraints have no such keys).
      return section == "steps" && (key == "name" || key == "increments");
    });
    const auto steps = model.find("steps");
    if (steps == model.end() || !steps->is_array()) return plan;
    for (const json& s : *steps) {
      if (!s.is_object()) continue;
      const json name = s.value("name", json(""));
      const json increments = s.value("increments", json(1));
      plan.steps.emplace_back(name.is_string() ? name.get<std::string>() : std::string(),
                              increments.is_number_integer() ? increments.get<int>() : 1);
    }
  } catch (const std::exception&) {
    plan.steps.clear();
  }
  return plan;
}

json job_progress(const LoadPlan& plan, const json& row, bool running, bool converged, int max_iterations,
                  double elapsed_seconds) {
  const bool stepped = !plan.steps.empty();
  const int steps = stepped ? static_cast<int>(plan.steps.size()) : 1;
  int total = 0;
  for (const auto& s : plan.steps) total += s.second;
  if (!stepped) total = 1;
  const bool has_row = row.is_object();
  const int iteration = has_row ? row.value("iteration", 0) : 0;
  const int step = std::clamp(has_row ? row.value("step", 1) : 1, 1, steps);
  const int increments = stepped ? plan.steps[static_cast<std::size_t>(step - 1)].second : 1;
  const int increment = std::clamp(has_row ? row.value("increment", 1) : 1, 1, increments);
  // Increments finished: every one before the row's; the row's own once the job converged.
  int done = increment - 1;
  for (int k = 0; k + 1 < step; ++k) done += plan.steps[static_cast<std::size_t>(k)].second;
  const double fraction = converged ? 1.0 : static_cast<double>(done) / total;
  json seconds_left = nullptr;
  if (running && fraction > 0.0 && fraction < 1.0 && elapsed_seconds > 0.0) {
    seconds_left = elapsed_seconds * (1.0 - fraction) / fraction;
  }
  std::ostringstream text;
  if (stepped) {
    const std::string& name = plan.steps[static_cast<std::size_t>(step - 1)].first;
    text << "step " << step << "/" << steps << (name.empty() ? "" : " \"" + name + "\"") << ", increment " << increment
         << "/" << increments << ", ";
  }
  text << "iteration " << iteration;
  if (!stepped) text << " (at most " << max_iterations << ")";
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.0f", std::floor(100.0 * fraction));
  text << ": " << percent << " % of the load path done";
  if (seconds_left.is_number()) {
    const double left = seconds_left.get<double>();
    if (left < 90.0) {
      text << ", about " << static_cast<long>(std::ceil(left)) << " s left";
    } else {
      text << ", about " << static_cast<long>(std::ceil(left / 60.0)) << " min left";
    }
  }
  json path = nullptr;
  if (stepped) {
    path = json::array();
    for (const auto& [name, count] : plan.steps) path.push_back({{"name", name}, {"increments", count}});
  }
  return {{"load_path", path},
          {"step", step},
          {"steps", steps},
          {"step_name", stepped ? json(plan.steps[static_cast<std::size_t>(step - 1)].first) : json(nullptr)},
          {"increment", increment},
          {"increments", increments},
          {"iteration", iteration},
          {"max_iterations", max_iterations},
          {"fraction", fraction},
          {"seconds_left", seconds_left},
          {"text", text.str()}};
}

double seconds_since(const std::string& utc, std::chrono::system_clock::time_point now) {
  std::tm tm{};
  int millis = 0;
  if (std::sscanf(utc.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d.%3dZ", &tm.tm_year, &tm.tm_mon, &tm.tm_mday, &tm.tm_hour,
                  &tm.tm_min, &tm.tm_sec, &millis) != 7) {
    return 0.0;
  }
  tm.tm_year -= 1900;
  tm.tm_mon -= 1;
  const auto then = std::chrono::system_clock::from_time_t(timegm(&tm)) + std::chrono::milliseconds(millis);
  return std::max(0.0, std::chrono::duration<double>(now - then).count());
}

}  // namespace saasgaps::io
