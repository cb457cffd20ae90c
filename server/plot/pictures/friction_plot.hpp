#pragma once
/// Friction along the contact surfaces (plot name `friction`): for each contact pair with friction
/// > 0 (result `contact[].friction`, the model pair's Coulomb mu), its points along side A against
/// the arc length from A's first point: the shear (tangential traction) as a solid curve, the
/// Coulomb bound +-mu x pressure as dashed curves of the same colour, the stick zones shaded blue
/// and the slip zones shaded orange behind them (each zone reaches halfway to the neighbouring
/// points), and each point marked by its state: a filled dot sticks, an open ring slips, nothing
/// is drawn at open points. One curve set per pair, never a line joining two pairs. Where a point
/// slips, its shear lies on the bound; where it sticks, strictly inside.

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/draw/data_table.hpp"

namespace saasgaps::plot {

/// Whether the result has a contact pair with friction > 0 and at least one point.
bool has_friction_points(const nlohmann::json& document);

/// Draws the plot over the whole canvas and returns its data table: per point its pair (1, 2, ..
/// among the result's pairs, named with their mu in a note), the point's number along A, x (arc
/// length), r, z, pressure, shear, mu, mu_pressure (mu x pressure), slip and state, and the px
/// where the shear marker and the bound's marker were drawn; the notes give the y ticks' px
/// positions and the stick and slip zones' x ranges. A result without a pair with friction > 0 and
/// points: std::invalid_argument.
DataTable draw_friction_plot(const Canvas& canvas, const nlohmann::json& document);

}  // namespace saasgaps::plot
