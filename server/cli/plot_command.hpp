#pragma once
/// `saasgaps plot RESULT.json --field NAME [--deformed SCALE|auto] [--mesh] [--width W --height H]
/// -o FILE.png|svg`: a contour plot of a field, the closure plot (--field closure) or the
/// convergence plot (--field convergence), drawn from a result document. The format follows the
/// extension of -o.

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
  std::string color_map = "rainbow";
  std::string along = "index";  ///< closure plot x axis: index | position
};

/// Exit code 0. An unknown field, a bad --deformed or output extension is a std::invalid_argument
/// whose message lists what is accepted; main() maps it to exit 1.
int run_plot(const PlotOptions& options);

}  // namespace saasgaps::cli
