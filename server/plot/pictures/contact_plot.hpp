#pragma once
/// Contact pressure and closure along a row of gaps (the report's Figs. 12-13, and what an analyst
/// checks first in a contact run): two panels over one x axis, the contact pressure
/// max(0, -sigma_m) of each gap on top and its final closure (%) below, with the 100 % contact line.
///
/// Contact surfaces (result `contact`, one entry per pair with its points along side A) are drawn
/// the same way: the contact pressure of each point on top and its gap (length) below, one curve per
/// pair, never a line joining two pairs. The x axis of the row options measures along side A:
/// index (the point's number along A, 1, 2, ..), position (arc length along A from its first point),
/// r or z.

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/draw/data_table.hpp"
#include "plot/result/gap_row.hpp"
#include "plot/result/plot_result.hpp"

namespace saasgaps::plot {

/// Draws the plot over the whole canvas and returns its data table: per gap its id, x, contact
/// pressure, closure, sigma_m and state, and the px where the two markers were drawn; the notes give
/// the y ticks' px positions. A result without gaps, or a row naming a gap it lacks:
/// std::invalid_argument.
/// With contact pairs in the result and no gap ids in `row`, the contact surfaces' plot is drawn
/// instead (draw_surface_contact_plot).
DataTable draw_contact_plot(const Canvas& canvas, const PlotResult& result, const GapRowOptions& row);

/// Whether the result has a contact pair with at least one point (result `contact`; `document` is
/// the result, or PlotResult::document(), which holds it).
bool has_contact_points(const nlohmann::json& document);

/// The contact surfaces' plot (see above) and its data table: per point its pair (1, 2, .., named
/// in a note), the point's number along A, x, r, z, pressure, gap and state, and the px where
/// the two markers were drawn. A result without contact points: std::invalid_argument.
DataTable draw_surface_contact_plot(const Canvas& canvas, const nlohmann::json& document, RowAxis along);

}  // namespace saasgaps::plot
