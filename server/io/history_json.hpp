#pragma once
/// The iteration history row as JSON (model-format.md): the same object in the result document,
/// in GET /v1/jobs/{id}/iterations, in restart states and in the service's database.

#include <string>

#include <nlohmann/json.hpp>

#include "io/json_writer.hpp"
#include "iteration_record.hpp"

namespace saasgaps::io {

/// The row, members in alphabetical order: attempt, average_closure, bimodulus_changes,
/// closed_gaps, extrapolated, gap_closures, iteration, max_closure, nonconverged_gaps,
/// nonconverged_plastic, seconds, tensile_modulus, watch {elements, gaps}, yielded_elements; in
/// exact contact mode also active_set_iterations, complementarity and contact_pairs.
void write_history_row(JsonWriter& out, const IterationRecord& row);

/// The row as compact text (what the service stores).
std::string history_row_text(const IterationRecord& row);

/// The row as a tree, for restart states: CBOR keeps every double exactly, nan included, which
/// text cannot (a test holds its compact dump equal to history_row_text).
nlohmann::json history_row_json(const IterationRecord& row);

/// The inverse of history_row_json; throws nlohmann::json::exception on a malformed row.
IterationRecord history_row_from_json(const nlohmann::json& row);

}  // namespace saasgaps::io
