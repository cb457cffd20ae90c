#pragma once
/// The tree writer that io/result_writer.hpp replaced, kept as the reference its streamed text is
/// compared with (tests/io/result_writer_test.cpp). A field added to the result document is added
/// here too. The result document of docs/results.md: status, history, node displacements, element stresses
/// and strains, gap states. Additions to the contract, so that a result stands on its own for
/// plotting and export: node coordinates r, z and temperature T; element corner node ids, material
/// id and temperature; gap corner node ids and angle (M axis); title, analysis,
/// reference_temperature; in each history row, gap_closures (every gap's closure, model order).

#include <string>

#include <nlohmann/json.hpp>

#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps::io::reference {

/// The result of a finished run. A stopped run reports status not_converged (it can be resumed).
nlohmann::json result_document(const Model& model, const Solution& solution);

/// The result document of a run that failed (singular model, bad restart state, ...).
nlohmann::json failed_result_document(const std::string& message);

}  // namespace saasgaps::io::reference
