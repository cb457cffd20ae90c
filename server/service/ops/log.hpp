#pragma once
/// Structured logs: one JSON object per line on stderr, which journald and Docker keep as they are.
/// Every line has "time" (UTC, ISO 8601 ms), "level" ("info", "warning", "error") and "event";
/// the other fields depend on the event (docs/operations.md lists them). Lines are written whole
/// under a lock, so lines from different threads never interleave.
///
/// A hand-written writer rather than spdlog: the lines are JSON objects that nlohmann::json already
/// builds and escapes (spdlog would format text, and its JSON would be escaped by hand), and the
/// sink is stderr only.

#include <nlohmann/json.hpp>
#include <string>

namespace saasgaps::service {

void log_info(const std::string& event, nlohmann::json fields = nlohmann::json::object());
void log_warning(const std::string& event, nlohmann::json fields = nlohmann::json::object());
void log_error(const std::string& event, nlohmann::json fields = nlohmann::json::object());

}  // namespace saasgaps::service
