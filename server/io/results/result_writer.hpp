#pragma once
/// The result document of docs/results.md, written as a stream (io/json_writer.hpp): status,
/// history, node displacements, element stresses and strains, gap states, contact pairs, support
/// reactions ({fr, fz, node} per constrained node; empty when nothing was solved). Additions to the
/// contract, so that a result stands on its own for plotting and export: node coordinates r, z and
/// temperature T; element corner node ids, material id and temperature; gap corner node ids and
/// angle (M axis); title, analysis, reference_temperature; units (the model's unit names, when it
/// gives any) and each gap's contact_pressure (io/result_annotations.hpp); in each history row,
/// gap_closures (every gap's closure, model order); reaction_sum ({fr, fz}: the reactions summed per
/// direction); each contact pair's force ({fr, fz}: what side B exerts on side A).
///
/// Every object's members are in alphabetical order (byte order: "T" before "id"), as the tree
/// writer this replaces printed them, so the text is the same: analysis, elements, gaps, history,
/// iterations, message, nodes, reaction_sum, reactions, reference_temperature, status, title, units
/// ("_" sorts before "s"). Nothing but the writer's
/// 64 KiB buffer is held: the document never exists as a tree.

#include <functional>
#include <string>

#include "io/json/json_writer.hpp"
#include "io/json/parallel_items.hpp"
#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps::io {

/// The result of a finished run. A stopped run reports status not_converged (it can be resumed).
/// The nodes and elements are formatted in pieces on several threads (io/parallel_items.hpp; the
/// same text on one).
/// `leading` writes members that sort before "analysis" (the adaptive loop's "adaptation").
void write_result(JsonWriter& out, const Model& model, const Solution& solution, const ItemPieces& pieces = {},
                  const std::function<void(JsonWriter&)>& leading = {});

/// The result document of a run that failed (singular model, bad restart state, ...).
void write_failed_result(JsonWriter& out, const std::string& message);

/// The result document as compact text (the service stores it so).
std::string result_text(const Model& model, const Solution& solution);
std::string failed_result_text(const std::string& message);

}  // namespace saasgaps::io
