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
///
/// A row may cross from one interface to another (every gap of a model with a retainer and a cap
/// interface): the row falls into parts, runs of neighbouring gaps in row order that are connected,
/// and a curve along the row is drawn one line per part, never a line from one interface to
/// another. Two gaps next to each other in the row are connected when they share a node, or, for
/// gaps that do not (each its own node pairs), when they abut along the face: their centroids are
/// at most 0.6 (L_a + L_b) apart, L the gap's length along its face (perpendicular to M); abutting
/// gaps are 0.5 (L_a + L_b) apart.

#include <string>
#include <vector>

#include "plot/draw/canvas.hpp"
#include "plot/draw/chart.hpp"
#include "plot/result/result_mesh.hpp"

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
  /// Per gap of the row, its part (see above): 0 for the first run of connected gaps, 1, .. after.
  std::vector<int> part;
  int parts() const { return part.empty() ? 0 : part.back() + 1; }
  /// The points (x[i], y[i]) of gaps from..to (row positions, to excluded) as one series whose
  /// line breaks between parts (a NaN point between them).
  void set_points(Series& series, const std::vector<double>& y, std::size_t from = 0,
                  std::size_t to = static_cast<std::size_t>(-1)) const;
  /// Row positions [begin, end) of part k.
  std::pair<std::size_t, std::size_t> part_range(int k) const;
};

/// Whether gaps a and b are connected (see above).
bool gaps_connected(const ResultMesh& mesh, const GapElement& a, const GapElement& b);

/// The row: an id that is not a gap element of the result is a std::invalid_argument naming it. On
/// the index axis at most max_labels gap ids are written (every k-th gap), so that they do not
/// overlap on a narrow image.
GapRow select_gap_row(const ResultMesh& mesh, const GapRowOptions& options, int max_labels = 24);

/// How many labels as wide as the mesh's widest gap id fit side by side along the canvas.
int gap_labels_that_fit(const Canvas& canvas, const ResultMesh& mesh);

}  // namespace saasgaps::plot
