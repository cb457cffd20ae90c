#include "io/results/thermal_row_json.hpp"

namespace saasgaps::io {

void write_thermal_row(JsonWriter& out, const ThermalRecord& r) {
  out.begin_object()
      .field("index", r.index)
      .field("iterations", r.iterations)
      .field("kind", std::string(to_string(r.kind)))
      .field("max_T", r.max_T)
      .field("max_change", r.max_change)
      .field("min_T", r.min_T)
      .field("pass", r.pass)
      .field("pass_change", r.pass_change)
      .field("time", r.time)
      .field("time_steps", r.time_steps)
      .end_object();
}

std::string thermal_row_text(const ThermalRecord& row) {
  std::string text;
  JsonWriter out(string_sink(text));
  write_thermal_row(out, row);
  out.flush();
  return text;
}

ThermalRecord thermal_row_from_json(const nlohmann::json& j) {
  ThermalRecord r;
  const std::string kind = j.at("kind").get<std::string>();
  const auto known = thermal_row_kind_names.value(kind);
  if (!known) throw nlohmann::json::other_error::create(501, "unknown thermal row kind \"" + kind + "\"", &j);
  r.kind = *known;
  r.index = j.at("index").get<int>();
  r.iterations = j.at("iterations").get<int>();
  r.max_T = j.at("max_T").get<double>();
  r.max_change = j.at("max_change").get<double>();
  r.min_T = j.at("min_T").get<double>();
  r.pass = j.at("pass").get<int>();
  r.pass_change = j.at("pass_change").get<double>();
  r.time = j.at("time").get<double>();
  r.time_steps = j.at("time_steps").get<int>();
  return r;
}

}  // namespace saasgaps::io
