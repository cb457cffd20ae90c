#pragma once
/// A support set's force against the load path (`saasgaps plot RESULT --field force --set NAME`):
/// the set's summed reactions fr and fz (history rows' set_reactions, docs/results.md) at the end of
/// each converged increment, against the increments of the load path 1, 2, ... From the result
/// document's history alone.

#include <string>

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/draw/data_table.hpp"

namespace saasgaps::plot {

/// Draws the plot over the whole canvas and returns its numbers (columns increment, step,
/// step_increment, fr, fz, px, py_fr, py_fz). Throws std::invalid_argument naming the sets there
/// are when the history has no reactions of `set`.
DataTable draw_force_plot(const Canvas& canvas, const nlohmann::json& result, const std::string& set);

}  // namespace saasgaps::plot
