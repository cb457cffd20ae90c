#pragma once
/// Closure of each gap along the gap, one curve per iteration (the report's Figs. 12 and 13): how
/// the contact spreads or recedes as the gap moduli are corrected. From the history rows'
/// gap_closures (closure % of every gap, in the order of the document's "gaps").

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/draw/data_table.hpp"
#include "plot/result/gap_row.hpp"
#include "plot/result/plot_result.hpp"

namespace saasgaps::plot {

struct ClosureOptions {
  /// At most this many curves: with more iterations, the first, the last and evenly spaced ones
  /// between are drawn (the subtitle says so), since 40 curves cannot be told apart.
  int max_curves = 12;
};

/// Draws the closure plot over the whole canvas and returns its data table: per gap of the row its
/// id, x, its closure in every iteration, and where the last iteration's marker is drawn. Throws
/// std::invalid_argument when the result has no gaps or the row names a gap it does not have.
DataTable draw_closure_plot(const Canvas& canvas, const PlotResult& result, const GapRowOptions& row,
                       const ClosureOptions& options = {});

}  // namespace saasgaps::plot
