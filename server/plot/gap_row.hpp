#pragma once
/// A row of gap elements to plot along (the report's Figs. 12-13 run along the gaps of a contact
/// face): which gaps, in which order, and what the x axis measures.
///
/// The row is an ordered list of gap ids ("81-98" or "81,83,85-90"; default: every gap in the
/// document's order, which for a mesh generator is usually along the face). The x axis is one of
///   index     1, 2, .. along the row, ticks labelled with the gap ids
///   position  arc length s along the chain of gap centroids (undeformed), from the first gap
///   r, z      the gap centroid's coordinate (the row is drawn in its given order; a row that
///             folds back on itself in r or z draws back too)

#include <string>
#include <vector>

#include "plot/chart.hpp"
#include "plot/result_mesh.hpp"

namespace saasgaps::plot {

enum class RowAxis { index, position, r, z };

struct GapRowOptions {
  std::vector<int> gap_ids;  ///< the row in order; empty: every gap in document order
  RowAxis along = RowAxis::index;
};

/// "index", "position", "r", "z"; anything else: std::invalid_argument listing them.
RowAxis row_axis(const std::string& name);

/// "81-98,100" -> 81, 82, .., 98, 100. Bad syntax, a descending range, an empty list or more than
/// 10^6 ids: std::invalid_argument quoting the text.
std::vector<int> parse_gap_ids(const std::string& text);

struct GapRow {
  std::vector<std::size_t> gaps;  ///< indices into mesh.gaps, in row order
  std::vector<double> x;          ///< one per gap, as the axis measures
  Axis axis;                      ///< the x axis: ticks and title (with the length unit)
};

/// The row: an id that is not a gap element of the result is a std::invalid_argument naming it. On
/// the index axis at most max_labels gap ids are written (every k-th gap), so that they do not
/// overlap on a narrow image.
GapRow select_gap_row(const ResultMesh& mesh, const GapRowOptions& options, int max_labels = 24);

}  // namespace saasgaps::plot
