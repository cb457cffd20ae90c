#pragma once
/// A field along a path through the mesh: a line plot of the value at evenly spaced points of a
/// polyline (r0, z0) -> (r1, z1) -> .., against the distance s along it. Each point takes the value
/// of the field inside the solid element that holds it (element_field.hpp: stresses from the
/// recovered nodal stresses, each element from its own material's side; other element fields from
/// nodal averages; node fields from the nodes), interpolated with the element's shape functions in
/// the undeformed mesh, so the value at a point is the same whichever element holds it (on an
/// edge between materials: the first element's side).
/// Points outside every solid element (a gap, a hole, beyond the body) have no value: the curve
/// breaks there.

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/draw/canvas.hpp"
#include "plot/draw/data_table.hpp"
#include "plot/result/field.hpp"
#include "plot/result/plot_result.hpp"

namespace saasgaps::plot {

struct PathOptions {
  std::vector<std::array<double, 2>> points;  ///< the polyline's corners (r, z), at least two
  int samples = 201;                          ///< points along it, ends included (2 .. 100000)
};

/// "r0,z0;r1,z1;.." (numbers as in JSON); fewer than two points, a non-number or a zero-length
/// path: std::invalid_argument quoting the text.
std::vector<std::array<double, 2>> parse_path(const std::string& text);

/// "r,z": one point, as a path's corners are written. Anything else: std::invalid_argument
/// quoting the text.
PlanePoint parse_point(const std::string& text);

/// Draws the plot of the field (a name of fields(), not a gap field) over the whole canvas and
/// returns its data table: per sample s, r, z, the element id (empty outside), the value and its px.
/// Cylindrical components are taken about `centre`.
DataTable draw_path_plot(const Canvas& canvas, const PlotResult& result, const std::string& field,
                         const PathOptions& options, const PlanePoint& centre = {0.0, 0.0});

}  // namespace saasgaps::plot
