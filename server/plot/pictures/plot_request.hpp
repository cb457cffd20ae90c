#pragma once
/// One entry point for every plot, for the command line and the service alike: a plot name and its
/// options in, the encoded image (PNG bytes or SVG text) or the plotted numbers (CSV) out, in memory.
///
///   plot::PlotRequest request;
///   request.name = "sigma_theta";
///   request.contour.deformation_scale = 50.0;
///   const std::string png = plot::render_plot(result_document, request);
///
/// What a name draws:
///   a solid or node field        the contour plot; with a path, the field along the path
///   closure                      gap closure along the gap row, one curve per iteration (contact
///                                surfaces only: as contact_pressure)
///   contact_pressure             contact pressure and closure along the gap row, or pressure and gap
///                                along each contact pair (contact_plot.hpp)
///   convergence                  the iteration's convergence
///   friction                     shear and +-mu x pressure along each contact pair with friction,
///                                stick and slip zones shaded (friction_plot.hpp)

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/results/result_arrays.hpp"

#include "plot/draw/canvas.hpp"
#include "plot/pictures/closure_plot.hpp"
#include "plot/pictures/contour_plot.hpp"
#include "plot/pictures/path_plot.hpp"
#include "plot/result/gap_row.hpp"
#include "plot/result/plot_result.hpp"

namespace saasgaps::plot {

struct PlotRequest {
  /// A field of fields(), "convergence" or "friction".
  std::string name = "effective";
  ImageFormat format = ImageFormat::png;
  int width = 1200;  ///< px
  int height = 800;  ///< px
  ContourOptions contour;  ///< for contour plots (its field and centre are taken from name and centre)
  /// Plane models: the centre the cylindrical components (sigma_radial, sigma_hoop, ..) are taken
  /// about, in a contour or path plot.
  PlanePoint centre{0.0, 0.0};
  ClosureOptions closure;  ///< for the closure plot
  GapRowOptions row;       ///< the gaps the closure and contact_pressure plots run along
  std::optional<PathOptions> path;  ///< set: a line plot of the field along this path
  std::string set;  ///< "force": the node set whose summed reactions to plot (force_plot.hpp)
};

/// Sets the deformation of a contour plot from its text form: "auto" or a positive magnification;
/// empty leaves the mesh undeformed. Anything else is a std::invalid_argument quoting the text.
void set_deformation(const std::string& text, ContourOptions& contour);

/// The centre of the cylindrical components from its text form "r,z" (x,y in a plane model); empty
/// leaves it at the origin. Anything else is a std::invalid_argument quoting the text.
void set_centre(const std::string& text, PlanePoint& centre);

/// Sets the gap row from its text forms: ids as parse_gap_ids reads them ("" = every gap), the x
/// axis as row_axis names it. Bad text: std::invalid_argument.
void set_gap_row(const std::string& ids, const std::string& along, GapRowOptions& row);

/// Every plot name: the fields (closure and contact_pressure among them), "convergence" and
/// "friction".
std::vector<std::string> plot_names();

/// Throws std::invalid_argument "unknown field 'x'; fields: sigma_r, ..., closure, convergence"
/// unless name is one of plot_names().
void require_plot_name(const std::string& name);

/// What a plot reads of a result (io/result_arrays.hpp): a convergence plot the history and the
/// gaps, no mesh (at 10^6 unknowns the nodes and elements are 300 MB of text); every other plot the
/// mesh, and of each element besides its id, material and nodes only the values of the field
/// plotted (a cylindrical component: the three in-plane components it is rotated from). The plot
/// drawn from a result read with it is the plot drawn from the whole document. The name must be one
/// of plot_names() (require_plot_name).
io::ResultSelection result_selection_for(const PlotRequest& request);

/// Renders the plot. An unknown name is a std::invalid_argument
/// "unknown field 'x'; fields: sigma_r, ..., closure, convergence"; so are bad options and results
/// the plot cannot be drawn from.
std::string render_plot(const PlotResult& result, const PlotRequest& request);

/// The numbers the plot draws, as CSV (data_table.hpp), laid out for the request's image size: for
/// closure, contact_pressure, friction and a field along a path. Other plots: std::invalid_argument.
std::string render_table(const PlotResult& result, const PlotRequest& request);

}  // namespace saasgaps::plot
