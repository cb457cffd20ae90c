#include "cli/plot_command.hpp"

#include <stdexcept>

#include "cli/file_io.hpp"
#include "cli/result_file.hpp"
#include "plot/plot_request.hpp"

namespace saasgaps::cli {

int run_plot(const PlotOptions& options) {
  plot::PlotRequest request;
  request.name = options.field;
  // Checked before the result is read: a typo should not cost the parse of a large document.
  plot::require_plot_name(request.name);
  request.format = plot::image_format_for_path(options.output_path);
  request.width = options.width;
  request.height = options.height;
  try {
    plot::set_deformation(options.deformed, request.contour);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--deformed: ") + e.what());
  }
  request.contour.mesh = options.mesh;
  request.contour.max_bands = options.bands;
  request.contour.color_map = options.color_map;
  request.closure.along = plot::closure_axis(options.along);
  write_file_atomically(options.output_path, plot::render_plot(read_result_document(options.result_path), request));
  return 0;
}

}  // namespace saasgaps::cli
