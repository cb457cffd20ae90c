#pragma once
/// `saasgaps plot RESULT.json --field NAME [options] -o FILE.png|svg|csv`: a contour plot of a field,
/// the field along a path (--path), the closure plot (--field closure), contact pressure and closure
/// along a row of gaps (--field contact_pressure, --gaps, --along) or the convergence plot (--field
/// convergence), drawn from a result document. The format follows the extension of -o; .csv writes
/// the numbers of a path, closure or contact_pressure plot instead of the picture.

#include <string>

namespace saasgaps::cli {

struct PlotOptions {
  std::string result_path;
  std::string output_path;
  std::string field = "effective";
  std::string deformed;  ///< empty: undeformed; "auto" or a magnification
  bool mesh = false;
  int width = 1200;
  int height = 800;
  int bands = 12;
  std::string levels = "even";  ///< even | quantile
  std::string color_map = "auto";  ///< auto (diverging when the range spans zero, else viridis) or a map
  std::string centre;  ///< "r,z": the centre of sigma_radial, sigma_hoop, ..; empty: the origin
  std::string gaps;             ///< the gap row: "81-98" etc.; empty: every gap
  std::string along;            ///< gap row x axis: index | position | r | z (empty: index)
  std::string path;             ///< "r0,z0;r1,z1;..": plot the field along it
  std::string set;              ///< --field force: the node set whose summed reactions to plot
  int samples = 201;
};

/// Exit code 0. An unknown field, a bad --deformed or output extension is a std::invalid_argument
/// whose message lists what is accepted; main() maps it to exit 1.
int run_plot(const PlotOptions& options);

}  // namespace saasgaps::cli
