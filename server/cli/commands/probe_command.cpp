#include "cli/commands/probe_command.hpp"

#include <iostream>

#include "cli/common/result_file.hpp"
#include "plot/pictures/path_plot.hpp"
#include "plot/result/plot_result.hpp"
#include "plot/result/point_probe.hpp"

namespace saasgaps::cli {

int run_probe(const ProbeOptions& options) {
  const plot::PlanePoint at = plot::parse_point(options.at);
  std::vector<std::string> fields;
  for (const std::string& item : options.fields) {
    for (std::size_t begin = 0; begin <= item.size();) {
      const std::size_t end = std::min(item.find(',', begin), item.size());
      if (end > begin) fields.push_back(item.substr(begin, end - begin));
      begin = end + 1;
    }
  }
  io::ResultSelection selection;
  for (const std::string& key : plot::probe_element_keys(fields)) selection.element_keys.push_back(key);
  const plot::PlotResult result(read_result_arrays(options.result_path, selection));
  const plot::Probe probe = plot::probe_point(result, at, fields);
  if (options.json) {
    std::cout << plot::probe_json(probe, result.mesh()).dump(2) << "\n";
  } else {
    std::cout << plot::probe_text(probe, result.mesh());
  }
  return 0;
}

}  // namespace saasgaps::cli
