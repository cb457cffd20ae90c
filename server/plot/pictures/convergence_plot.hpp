#pragma once
/// The gap iteration at a glance (the report's Tables I-V as pictures): per iteration, the average
/// and the maximum closure (upper panel, against the 100 % of contact) and the number of closed and
/// of non-converged gaps (lower panel). From the result document's history rows.

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"

namespace saasgaps::plot {

/// Draws the convergence plot over the whole canvas. Throws std::invalid_argument when the history
/// is empty.
void draw_convergence_plot(const Canvas& canvas, const nlohmann::json& result);

}  // namespace saasgaps::plot
