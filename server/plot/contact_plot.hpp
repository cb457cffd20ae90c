#pragma once
/// Contact pressure and closure along a row of gaps (the report's Figs. 12-13, and what an analyst
/// checks first in a contact run): two panels over one x axis, the contact pressure
/// max(0, -sigma_m) of each gap on top and its final closure (%) below, with the 100 % contact line.

#include <nlohmann/json.hpp>

#include "plot/canvas.hpp"
#include "plot/plot_result.hpp"
#include "plot/data_table.hpp"
#include "plot/gap_row.hpp"

namespace saasgaps::plot {

/// Draws the plot over the whole canvas and returns its data table: per gap its id, x, contact
/// pressure, closure, sigma_m and state, and the px where the two markers were drawn; the notes give
/// the y ticks' px positions. A result without gaps, or a row naming a gap it lacks:
/// std::invalid_argument.
DataTable draw_contact_plot(const Canvas& canvas, const PlotResult& result, const GapRowOptions& row);

}  // namespace saasgaps::plot
