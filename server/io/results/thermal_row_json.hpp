#pragma once
/// The thermal history row (solver/thermal_record.hpp) as JSON: the same object in
/// GET /v1/jobs/{id}/thermal, in the `thermal` events of the job's event stream and in the
/// service's database.

#include <string>

#include <nlohmann/json.hpp>

#include "io/json/json_writer.hpp"
#include "solver/state/thermal_record.hpp"

namespace saasgaps::io {

/// The row, members in alphabetical order: index, iterations, kind ("steady" | "transient"),
/// max_T, max_change, min_T, pass, pass_change, time, time_steps.
void write_thermal_row(JsonWriter& out, const ThermalRecord& row);

/// The row as compact text (what the service stores and sends).
std::string thermal_row_text(const ThermalRecord& row);

/// The inverse of thermal_row_text's object; throws nlohmann::json::exception on a malformed row
/// (a missing member, a number of the wrong type, an unknown kind).
ThermalRecord thermal_row_from_json(const nlohmann::json& row);

}  // namespace saasgaps::io
