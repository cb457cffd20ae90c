#pragma once
/// One entry point for every plot, for the command line and the service alike: a plot name and its
/// options in, the encoded image (PNG bytes or SVG text) out, in memory.
///
///   plot::PlotRequest request;
///   request.name = "sigma_theta";
///   request.contour.deformation_scale = 50.0;
///   const std::string png = plot::render_plot(result_document, request);

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/canvas.hpp"
#include "plot/closure_plot.hpp"
#include "plot/contour_plot.hpp"

namespace saasgaps::plot {

struct PlotRequest {
  /// A field of fields() (a contour plot; "closure" is the closure plot) or "convergence".
  std::string name = "effective";
  ImageFormat format = ImageFormat::png;
  int width = 1200;  ///< px
  int height = 800;  ///< px
  ContourOptions contour;  ///< for contour plots (its field is taken from name)
  ClosureOptions closure;  ///< for the closure plot
};

/// Sets the deformation of a contour plot from its text form: "auto" or a positive magnification;
/// empty leaves the mesh undeformed. Anything else is a std::invalid_argument quoting the text.
void set_deformation(const std::string& text, ContourOptions& contour);

/// The closure plot's x axis by name: "index" (gap index) or "position" (along the gaps).
ClosureAxis closure_axis(const std::string& name);

/// Every plot name: the fields (closure among them) and "convergence".
std::vector<std::string> plot_names();

/// Throws std::invalid_argument "unknown field 'x'; fields: sigma_r, ..., closure, convergence"
/// unless name is one of plot_names().
void require_plot_name(const std::string& name);

/// Renders the plot. An unknown name is a std::invalid_argument
/// "unknown field 'x'; fields: sigma_r, ..., closure, convergence"; so are bad options and results
/// the plot cannot be drawn from.
std::string render_plot(const nlohmann::json& result, const PlotRequest& request);

}  // namespace saasgaps::plot
