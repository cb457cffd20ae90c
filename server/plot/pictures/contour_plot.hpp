#pragma once
/// Filled contour plot of a field over the mesh (the report's Figs. 9-11 and 16-18): colour bands
/// between round level values on the undeformed or the deformed mesh, the gap elements marked by
/// state (closed, overclosed, partial, open), r and z axes with round ticks (one step for both:
/// the drawing is to scale), a colour bar with the levels and the unit, and the field's extremes
/// with where they are. The field is the one probes read (element_field.hpp): stresses from the
/// recovered nodal stresses, interpolated in each element with its own shape functions (a quadratic
/// element drawn in 4 x 4 pieces with curved edges), each element from its own material's side. A
/// field whose range spans zero is drawn by default in the diverging map centred on zero
/// (color_map.hpp), any other in viridis.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/draw/band_levels.hpp"
#include "plot/draw/canvas.hpp"
#include "plot/result/field.hpp"
#include "plot/result/plot_result.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

/// How the colour bands are filled. paths: one cairo path per level, every triangle's part above
/// it (contour_bands.hpp): antialiased band edges, vector in SVG, but a cost of triangles x bands
/// and cairo's copies of the paths. raster: each triangle scan-converted once into an image of the
/// canvas (band_raster.hpp), the band edges stroked over it: O(triangles + pixels), the image's
/// memory. automatic: paths up to path_fill_limit solid elements (every report example: pictures
/// as before), raster above.
enum class BandFill { automatic, paths, raster };
inline constexpr std::size_t path_fill_limit = 20000;

struct ContourOptions {
  std::string field = "effective";
  /// Magnification s of the displacements: nodes drawn at (r + s u_r, z + s u_z), s > 0. None:
  /// the undeformed mesh.
  std::optional<double> deformation_scale;
  /// Deformed, with automatic_deformation_scale() (overrides deformation_scale).
  bool automatic_deformation = false;
  bool mesh = false;  ///< draw the element edges
  int max_bands = 12;
  LevelRule levels = LevelRule::even;  ///< see band_levels.hpp
  /// A name of ColorMap::names(); "auto": diverging when the field's range spans zero, else viridis.
  std::string color_map = "auto";
  /// Plane models: the centre of the cylindrical components (sigma_hoop, ..), (x, y).
  PlanePoint centre{0.0, 0.0};
  BandFill fill = BandFill::automatic;
};

/// What the colour bar and the extreme labels say, as drawn: all three from the field's values at
/// the points the bands are drawn from (each element's drawing subdivision, element_field.hpp and
/// element_map.hpp), so the top level encloses `max` and the "max" label names it.
struct ContourLegend {
  std::vector<double> levels;
  double min = 0.0, max = 0.0;
  int min_element = 0, max_element = 0;  ///< ids of the elements the extremes lie in
  PlanePoint min_at{}, max_at{};         ///< where (undeformed model coordinates)
  FieldSource source = FieldSource::nodal;
};

/// Draws the contour plot over the whole canvas and returns its legend. Unknown field or colour
/// map, a gap field, or a result without a mesh: std::invalid_argument.
ContourLegend draw_contour_plot(const Canvas& canvas, const PlotResult& result, const ContourOptions& options);

/// A round magnification (1, 2 or 5 times a power of ten) that draws the largest displacement at
/// about 8 % of the model's larger extent; 1 when nothing moves.
double automatic_deformation_scale(const ResultMesh& mesh);

}  // namespace saasgaps::plot
