#include "cli/commands/plot_command.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cli/common/file_io.hpp"
#include "cli/common/result_file.hpp"
#include "plot/pictures/plot_request.hpp"

namespace saasgaps::cli {

int run_plot(const PlotOptions& options) {
  plot::PlotRequest request;
  request.name = options.field;
  // Checked before the result is read: a typo should not cost the parse of a large document.
  plot::require_plot_name(request.name);
  // --along sets the x axis of a gap row or contact pair: every other plot has none, and says so
  // rather than draw something else than asked.
  if (!options.along.empty() && (!options.path.empty() || (options.field != "closure" && options.field != "contact_pressure"))) {
    throw std::invalid_argument("--along " + options.along + ": only the closure and contact_pressure plots run along a "
                                "gap row or contact pair; the " + options.field +
                                (options.path.empty() ? " plot has no such axis" : " plot along --path runs along the path"));
  }
  const bool table = options.output_path.size() >= 4 &&
                     options.output_path.compare(options.output_path.size() - 4, 4, ".csv") == 0;
  if (!table) request.format = plot::image_format_for_path(options.output_path);
  require_writable(options.output_path, "-o");
  request.set = options.set;
  if (!options.set.empty() && options.field != "force") {
    throw std::invalid_argument("--set " + options.set + ": only --field force plots a node set's reactions");
  }
  request.width = options.width;
  request.height = options.height;
  try {
    plot::set_deformation(options.deformed, request.contour);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--deformed: ") + e.what());
  }
  request.contour.mesh = options.mesh;
  request.contour.max_bands = options.bands;
  request.contour.levels = plot::level_rule(options.levels);
  request.contour.color_map = options.color_map;
  try {
    plot::set_centre(options.centre, request.centre);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--centre: ") + e.what());
  }
  try {
    plot::set_gap_row(options.gaps, options.along, request.row);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--gaps/--along: ") + e.what());
  }
  if (!options.path.empty()) {
    try {
      request.path = plot::PathOptions{plot::parse_path(options.path), options.samples};
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--path: ") + e.what());
    }
  }
  const plot::PlotResult result(read_result_arrays(options.result_path, plot::result_selection_for(request)));
  write_file_atomically(options.output_path,
                        table ? plot::render_table(result, request) : plot::render_plot(result, request));
  return 0;
}

}  // namespace saasgaps::cli
