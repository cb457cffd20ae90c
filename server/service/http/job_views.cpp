#include "service/http/job_views.hpp"

#include <optional>
#include <string_view>

#include "io/json/json_subset.hpp"
#include "io/json/json_text.hpp"
#include "io/model/model_reader.hpp"
#include "io/restart/read_card.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::service {

using nlohmann::json;

namespace {

/// A JSON text the store wrote, or null when it is missing or damaged (a damaged row must not make
/// the whole job unreadable).
json stored_json(const std::optional<std::string>& text) {
  if (!text) return nullptr;
  try {
    return io::parse_document(*text);
  } catch (const ModelError&) {
    return nullptr;
  }
}

/// The warnings of a run's message: each clause that follows "warning: " up to the next one (the
/// solver appends them to the message as "; warning: ..."). Empty for a clean run, so that clients
/// can tell "converged" from "converged with a warning" without reading prose.
json message_warnings(const std::optional<std::string>& message) {
  json warnings = json::array();
  if (!message) return warnings;
  static constexpr std::string_view marker = "warning: ";
  std::size_t at = message->find(marker);
  while (at != std::string::npos) {
    const std::size_t start = at + marker.size();
    const std::size_t next = message->find("; " + std::string(marker), start);
    warnings.push_back(message->substr(start, next == std::string::npos ? std::string::npos : next - start));
    at = next == std::string::npos ? next : message->find(marker, next);
  }
  return warnings;
}

}  // namespace

json job_json(const JobRecord& j) {
  const std::string self = "/v1/jobs/" + std::to_string(j.id);
  return {{"id", j.id},
          {"state", to_string(j.state)},
          {"title", j.title},
          {"created_at", j.created_at},
          {"started_at", j.started_at ? json(*j.started_at) : json(nullptr)},
          {"finished_at", j.finished_at ? json(*j.finished_at) : json(nullptr)},
          {"iteration", j.iteration},
          {"max_iterations", j.max_iterations},
          {"last_row", stored_json(j.last_row)},
          {"attempts", j.attempts},
          {"interruptions", j.interruptions},
          {"cancel_requested", j.cancel_requested},
          {"message", j.message ? json(*j.message) : json(nullptr)},
          {"warnings", message_warnings(j.message)},
          {"error", j.error ? json(*j.error) : json(nullptr)},
          {"resume_settings", io::read_card_to_json(j.settings, io::ReadCardForm::in_force)},
          {"slurm", j.slurm_job_id ? json{{"job_id", *j.slurm_job_id}, {"state", j.slurm_state.value_or("")}} : json(nullptr)},
          {"links",
           {{"self", self},
            {"iterations", self + "/iterations"},
            {"thermal", self + "/thermal"},
            {"events", self + "/events"},
            {"result", self + "/result"},
            {"model", self + "/model"}}}};
}

json job_list_item(const JobRecord& j) {
  json item = job_json(j);
  if (item["last_row"].is_object()) item["last_row"].erase("gap_closures");
  return item;
}

std::string rows_page(std::int64_t id, const char* member, const std::vector<std::string>& rows) {
  std::string page = "{\"job\":" + std::to_string(id) + ",\"" + member + "\":[";
  for (std::size_t i = 0; i < rows.size(); ++i) page += (i ? "," : "") + rows[i];
  return page + "]}";
}

json model_units(const std::string& model_text) {
  const json model =
      io::parse_json_subset(model_text, [](int depth, std::string_view, std::string_view key) { return depth > 1 || key == "units"; });
  const auto units = model.find("units");
  return units != model.end() && units->is_object() ? *units : json::object();
}

void send_json(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(io::json_text(body), "application/json");
}

}  // namespace saasgaps::service
