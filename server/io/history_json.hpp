#pragma once
/// The iteration history row as JSON (model-format.md): the same object in the result document,
/// in GET /v1/jobs/{id}/iterations, in restart states and in the service's database.

#include <nlohmann/json.hpp>

#include "iteration_record.hpp"

namespace saasgaps::io {

nlohmann::json history_row_json(const IterationRecord& row);

/// The inverse of history_row_json; throws nlohmann::json::exception on a malformed row.
IterationRecord history_row_from_json(const nlohmann::json& row);

}  // namespace saasgaps::io
