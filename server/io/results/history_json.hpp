#pragma once
/// The iteration history row as JSON (docs/results.md, "History rows"): the same object in the result document,
/// in GET /v1/jobs/{id}/iterations, in restart states and in the service's database.

#include <string>

#include <nlohmann/json.hpp>

#include "io/json/json_writer.hpp"
#include "solver/state/iteration_record.hpp"

namespace saasgaps::io {

/// The row, members in alphabetical order: attempt, average_closure, bimodulus_changes,
/// closed_gaps, extrapolated, gap_closures, iteration, max_closure, nonconverged_gaps,
/// nonconverged_plastic, seconds, tensile_modulus, watch {elements, gaps}, yielded_elements; in
/// exact contact mode also active_set_iterations, complementarity and contact_pairs; in a stepped
/// model step and increment; with friction (has_friction_columns) friction_residual, slip_points
/// and stick_points; at the end of a converged increment, pair_forces [{fr, fz, surfaces}] (models
/// with contact pairs) and set_reactions [{fr, fz, set}] (models whose constraints name node sets).
void write_history_row(JsonWriter& out, const IterationRecord& row);

/// Whether the row carries the friction columns stick_points, slip_points and friction_residual: a
/// run with friction > 0 on a contact pair (stick + slip > 0 or a residual != 0). Frictionless rows
/// are written exactly as before friction existed; a reader takes absent columns as 0.
bool has_friction_columns(const IterationRecord& row);

/// The row as compact text (what the service stores).
std::string history_row_text(const IterationRecord& row);

/// The row as a tree, for restart states: CBOR keeps every double exactly, nan included, which
/// text cannot (a test holds its compact dump equal to history_row_text).
nlohmann::json history_row_json(const IterationRecord& row);

/// The inverse of history_row_json; throws nlohmann::json::exception on a malformed row.
IterationRecord history_row_from_json(const nlohmann::json& row);

}  // namespace saasgaps::io
