#include "plot/pictures/closure_plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

struct Curve {
  int iteration = 0;  ///< 0: the final state only (no per-iteration closures in the history)
  std::vector<double> closures;
};

/// Every history row that has one closure per gap, else the final closures as one curve; each
/// curve holds the row's gaps in row order.
std::vector<Curve> closure_curves(const PlotResult& result, const ResultMesh& mesh, const GapRow& row) {
  std::vector<Curve> curves;
  for (const json& history_row : array_member(result.document(), "history")) {
    const auto closures = history_row.find("gap_closures");
    if (closures == history_row.end() || !closures->is_array() || closures->size() != mesh.gaps.size()) continue;
    Curve c{history_row.at("iteration").get<int>(), {}};
    for (const std::size_t g : row.gaps) c.closures.push_back((*closures)[g].get<double>());
    curves.push_back(std::move(c));
  }
  if (curves.empty()) {
    Curve final_state;
    for (const std::size_t g : row.gaps) final_state.closures.push_back(mesh.gaps[g].closure);
    curves.push_back(final_state);
  }
  return curves;
}

/// At most `count` of the curves: the first, the last and evenly spaced ones between.
std::vector<Curve> thin_out(std::vector<Curve> curves, int count) {
  const int n = static_cast<int>(curves.size());
  count = std::max(2, count);
  if (n <= count) return curves;
  std::vector<Curve> kept;
  for (int k = 0; k < count; ++k) {
    const auto index = static_cast<std::size_t>(std::lround(static_cast<double>(k) * (n - 1) / (count - 1)));
    kept.push_back(curves[index]);
  }
  return kept;
}

}  // namespace

DataTable draw_closure_plot(const Canvas& canvas, const PlotResult& result, const GapRowOptions& row_options,
                            const ClosureOptions& options) {
  const ResultMesh& mesh = result.mesh();
  if (mesh.gaps.empty()) throw std::invalid_argument("the result has no gap elements: there is no closure to plot");
  const GapRow row = select_gap_row(mesh, row_options, gap_labels_that_fit(canvas, mesh));
  const std::vector<Curve> all = closure_curves(result, mesh, row);
  const std::vector<Curve> curves = thin_out(all, options.max_curves);
  const std::vector<double>& x = row.x;
  double low = 0.0, high = 110.0;  // always show 0 and the 100 % line
  for (const Curve& c : curves) {
    for (const double v : c.closures) {
      low = std::min(low, v);
      high = std::max(high, v);
    }
  }

  std::string subtitle = "Closure of each gap (% of its width; 100 % = faces in contact), one curve per iteration";
  if (row.parts() > 1) subtitle += " and row of gaps (" + std::to_string(row.parts()) + " separate rows)";
  if (curves.size() < all.size()) {
    subtitle += " (" + std::to_string(curves.size()) + " of " + std::to_string(all.size()) + " shown)";
  }
  subtitle += " \u2014 " + run_summary(mesh.status, mesh.iterations);
  const Rect area = draw_header(canvas, mesh.title.empty() ? "Gap closure" : mesh.title, subtitle);

  // Earlier iterations light, later ones darker; the last in black with markers: the answer.
  const ColorMap palette = ColorMap::named("viridis");
  const bool markers = row.gaps.size() <= 60;
  std::vector<Series> series;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    Series s;
    const bool last = k + 1 == curves.size();
    s.name = curves[k].iteration > 0 ? "iteration " + std::to_string(curves[k].iteration) : "final";
    row.set_points(s, curves[k].closures);  // broken between the row's parts
    const double t = curves.size() > 1 ? 0.8 * (1.0 - static_cast<double>(k) / static_cast<double>(curves.size() - 1)) : 0.0;
    s.color = last ? colors::black : palette.at(t);
    s.width = last ? 2.5 : 1.4;
    s.markers = markers && last;
    series.push_back(s);
  }
  const Rgb contact_color{0.80, 0.10, 0.10};
  std::vector<Series> legend = series;
  legend.push_back(reference_series("100 % (contact)", contact_color));
  const Chart chart(canvas, area, row.axis, numeric_axis(low, high, "closure (%)"), legend);
  chart.draw_axes();
  chart.draw_reference(100.0, contact_color);
  for (const Series& s : series) chart.draw(s);
  chart.draw_legend();

  // The table holds every iteration, drawn or not, and where the last curve's markers are.
  std::vector<std::string> columns{"gap", "x", "row_part"};
  for (const Curve& c : all) columns.push_back(c.iteration > 0 ? "iteration_" + std::to_string(c.iteration) : "final");
  columns.insert(columns.end(), {"px", "py_last"});
  DataTable table(columns);
  table.note("SAASGAPS gap closure per iteration: " + mesh.title);
  table.note("x: " + row.axis.title + "; row_part: 1, 2, .. the connected run of gaps (one line each); closures "
             "in % of each gap's width, 100 = contact");
  for (std::size_t i = 0; i < row.gaps.size(); ++i) {
    std::vector<std::string> cells{std::to_string(mesh.gaps[row.gaps[i]].id), DataTable::number(x[i]),
                                   std::to_string(row.part[i] + 1)};
    for (const Curve& c : all) cells.push_back(DataTable::number(c.closures[i]));
    const Point p = chart.to_device(x[i], all.back().closures[i]);
    cells.insert(cells.end(), {DataTable::number(p.x), DataTable::number(p.y)});
    table.add_row(std::move(cells));
  }
  return table;
}

}  // namespace saasgaps::plot
