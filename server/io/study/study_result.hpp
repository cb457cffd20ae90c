#pragma once
/// The study result (docs/studies.md) and its CSV:
///   {"status", "message", "title", "points_total", "converged", "failed", "solved", "cached",
///    "points": [{"index", "parameters": {name: value}, "status", "job", "cached",
///                "outputs": {name: value}, "message"}]}
/// `status` is "converged" when every point converged, "partial" when some did and some did not,
/// "failed" when none did (the service adds "queued", "running" and "cancelled" for a study under
/// way); `message` says how many converged ("5 of 6 points converged; point 3 failed: ...").
/// `solved` counts the points solved by this run, `cached` those answered from the result cache.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/study/study_document.hpp"

namespace saasgaps::io {

struct PointOutcome {
  std::size_t index = 0;
  /// converged, not_converged, failed (and for the service queued, running, cancelled).
  std::string status = "queued";
  std::optional<std::int64_t> job;  ///< the job (the CLI: the cache entry) whose solve gave the result
  bool cached = false;
  nlohmann::json outputs = nlohmann::json::object();  ///< name: number (null when not computed)
  std::string message;                                ///< why it failed, or how the run ended
};

/// A point's status, message and outputs from its result document: the result's status and message,
/// each output reduced (an output that cannot be, io/study/study_outputs.hpp, fails the point with
/// its reason; a failed result has no outputs).
void take_result(const nlohmann::json& result, const Study& study, PointOutcome& point);

/// Counts and wording of a set of points.
struct StudySummary {
  std::string status, message;
  std::size_t converged = 0, failed = 0, cached = 0;
};
StudySummary summarize(const std::vector<PointOutcome>& points);

/// The study result document. `solved`: points solved by this run (the cache's answers excluded).
nlohmann::json study_result_json(const Study& study, const std::vector<PointOutcome>& points, std::size_t solved);

/// The CSV beside it: a header "index,<parameters...>,status,cached,job,<outputs...>" and a row per
/// point; numbers shortest-round-trip, strings quoted when they hold a comma, quote or line break.
std::string study_csv(const Study& study, const std::vector<PointOutcome>& points);

}  // namespace saasgaps::io
