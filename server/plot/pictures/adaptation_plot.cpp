#include "plot/pictures/adaptation_plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"

namespace saasgaps::plot {

using nlohmann::json;

DataTable draw_adaptation_plot(const Canvas& canvas, const json& document) {
  const auto rows = document.find("adaptation");
  if (rows == document.end() || !rows->is_array() || rows->empty()) {
    throw std::invalid_argument("the adaptation plot needs the cycles of an adaptive run (`adaptation`); this result "
                                "has none (an assembly with adapt, solved by saasgaps solve or as a job)");
  }
  Series error;
  error.name = "estimated relative error";
  error.color = {0.10, 0.30, 0.75};
  error.width = 2.0;
  error.markers = true;
  std::vector<int> cycles;
  double x_lo = HUGE_VAL, x_hi = 0.0, y_lo = HUGE_VAL, y_hi = 0.0;
  for (const json& row : *rows) {
    const double unknowns = row.value("unknowns", 0.0);
    const double eta = row.value("relative_error", 0.0);
    if (!(unknowns > 0.0) || !(eta > 0.0)) continue;  // a zero error has no place on a log scale
    cycles.push_back(row.value("cycle", 0));
    error.x.push_back(std::log10(unknowns));
    error.y.push_back(std::log10(eta));
    x_lo = std::min(x_lo, unknowns);
    x_hi = std::max(x_hi, unknowns);
    y_lo = std::min(y_lo, eta);
    y_hi = std::max(y_hi, eta);
  }
  if (cycles.empty()) throw std::invalid_argument("the adaptation rows have no positive errors to plot");
  const double target = document.value("target_error", 0.0);
  std::vector<Series> legend = {error};
  if (target > 0.0) {
    legend.push_back(reference_series("target " + DataTable::number(target), {0.80, 0.10, 0.10}));
    y_lo = std::min(y_lo, target);
    y_hi = std::max(y_hi, target);
  }
  const std::string title = document.value("title", "");
  const std::string subtitle = std::to_string(cycles.size()) + (cycles.size() == 1 ? " cycle" : " cycles") +
                               " of the adaptive loop: estimated relative error in the energy norm against the "
                               "unknowns, log-log";
  const Rect area = draw_header(canvas, title.empty() ? "Adaptive meshes" : title, subtitle);
  const Chart chart(canvas, area, log_axis(x_lo / 1.5, x_hi * 1.5, "unknowns"),
                    log_axis(y_lo / 1.5, y_hi * 1.5, "estimated relative error"), legend);
  chart.draw_axes();
  if (target > 0.0) chart.draw_reference(std::log10(target), {0.80, 0.10, 0.10});
  chart.draw(error);
  chart.draw_legend();

  DataTable table({"cycle", "unknowns", "relative_error", "px", "py"});
  table.note("SAASGAPS adaptive meshes: " + title);
  table.note("estimated relative error in the energy norm against the unknowns of each cycle (log-log)");
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    const Point p = chart.to_device(error.x[k], error.y[k]);
    table.add_row({std::to_string(cycles[k]), DataTable::number(std::pow(10.0, error.x[k])),
                   DataTable::number(std::pow(10.0, error.y[k])), DataTable::number(p.x), DataTable::number(p.y)});
  }
  return table;
}

}  // namespace saasgaps::plot
