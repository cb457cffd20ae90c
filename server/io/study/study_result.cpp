#include "io/study/study_result.hpp"

#include <charconv>

#include "io/json/json_text.hpp"
#include "io/json/value_quote.hpp"
#include "io/study/study_outputs.hpp"

namespace saasgaps::io {

using nlohmann::json;

void take_result(const json& result, const Study& study, PointOutcome& point) {
  point.status = result.value("status", "failed");
  point.message = result.value("message", "");
  point.outputs = json::object();
  if (point.status == "failed") return;
  for (const StudyOutput& o : study.outputs) {
    try {
      point.outputs[o.name] = reduce_output(result, o);
    } catch (const OutputError& e) {
      point.outputs[o.name] = nullptr;
      point.status = "failed";
      point.message = "output " + quote_string(o.name) + ": " + e.what();
    }
  }
}

StudySummary summarize(const std::vector<PointOutcome>& points) {
  StudySummary s;
  std::size_t waiting = 0, cancelled = 0;
  std::string first_failure;
  for (const PointOutcome& p : points) {
    if (p.status == "converged") {
      ++s.converged;
    } else if (p.status == "queued" || p.status == "running") {
      ++waiting;
    } else if (p.status == "cancelled") {
      ++cancelled;
    } else {
      ++s.failed;
      if (first_failure.empty()) first_failure = "point " + std::to_string(p.index) + " " + p.status + ": " + p.message;
    }
    if (p.cached) ++s.cached;
  }
  const std::size_t n = points.size();
  if (waiting > 0) {
    s.status = "running";
  } else if (cancelled > 0) {
    s.status = "cancelled";
  } else if (s.converged == n) {
    s.status = "converged";
  } else {
    s.status = s.converged > 0 ? "partial" : "failed";
  }
  s.message = std::to_string(s.converged) + " of " + std::to_string(n) + " points converged";
  if (s.failed > 0) s.message += ", " + std::to_string(s.failed) + " did not (" + first_failure + ")";
  if (cancelled > 0) s.message += ", " + std::to_string(cancelled) + " cancelled";
  if (waiting > 0) s.message += ", " + std::to_string(waiting) + " to run";
  return s;
}

json study_result_json(const Study& study, const std::vector<PointOutcome>& points, std::size_t solved) {
  const StudySummary s = summarize(points);
  json out = {{"status", s.status},   {"message", s.message},         {"title", study.title},
              {"points_total", points.size()}, {"converged", s.converged}, {"failed", s.failed},
              {"solved", solved},     {"cached", s.cached}};
  json& list = out["points"] = json::array();
  for (const PointOutcome& p : points) {
    json item = {{"index", p.index},
                 {"parameters", study.point_parameters(p.index)},
                 {"status", p.status},
                 {"job", p.job ? json(*p.job) : json()},
                 {"cached", p.cached},
                 {"outputs", p.outputs}};
    if (!p.message.empty()) item["message"] = p.message;
    list.push_back(std::move(item));
  }
  return out;
}

namespace {

std::string csv_cell(const json& value) {
  if (value.is_null()) return "";
  if (value.is_number()) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value.get<double>()).ptr;
    return std::string(text, end);
  }
  const std::string text = value.is_string() ? value.get<std::string>() : json_text(value);
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

std::string study_csv(const Study& study, const std::vector<PointOutcome>& points) {
  std::string out = "index";
  for (const StudyParameter& p : study.parameters) out += "," + csv_cell(p.name);
  out += ",status,cached,job";
  for (const StudyOutput& o : study.outputs) out += "," + csv_cell(o.name);
  out += "\n";
  for (const PointOutcome& p : points) {
    const json parameters = study.point_parameters(p.index);
    out += std::to_string(p.index);
    for (const StudyParameter& q : study.parameters) out += "," + csv_cell(parameters[q.name]);
    out += "," + p.status + "," + (p.cached ? "true" : "false") + "," + (p.job ? std::to_string(*p.job) : "");
    for (const StudyOutput& o : study.outputs) out += "," + csv_cell(p.outputs.value(o.name, json()));
    out += "\n";
  }
  return out;
}

}  // namespace saasgaps::io
