#pragma once
/// The adaptive loop's convergence (docs/plots.md): the estimated relative error in the energy norm
/// (error_estimate.relative of each cycle) against the number of unknowns, log-log, one marker per
/// cycle, the target as a dashed line. From a document's `adaptation` rows (a result of `saasgaps
/// solve ASSEMBLY.json` with `adapt`, or an adaptive job's stored cycles) and its optional
/// `target_error`.

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/draw/data_table.hpp"

namespace saasgaps::plot {

/// Draws the plot over the whole canvas; returns its numbers (cycle, unknowns, relative error and
/// their px). Throws std::invalid_argument when the document has no `adaptation` rows.
DataTable draw_adaptation_plot(const Canvas& canvas, const nlohmann::json& document);

}  // namespace saasgaps::plot
