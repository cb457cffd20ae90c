#include "plot/pictures/convergence_plot.hpp"

#include <algorithm>
#include <stdexcept>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

/// One curve of history[key] against the iteration, from iteration `from` on.
Series history_series(const json& history, const char* key, std::string name, Rgb color, bool dashed = false,
                      int from = 1) {
  Series s;
  s.name = std::move(name);
  for (const json& row : history) {
    if (row.at("iteration").get<int>() < from) continue;
    s.x.push_back(row.at("iteration").get<double>());
    s.y.push_back(row.at(key).get<double>());
  }
  s.color = color;
  s.width = 2.0;
  s.dashed = dashed;
  s.markers = history.size() <= 60;
  return s;
}

double largest(const std::vector<Series>& series, double at_least) {
  for (const Series& s : series) {
    for (const double v : s.y) at_least = std::max(at_least, v);
  }
  return at_least;
}

}  // namespace

void draw_convergence_plot(const Canvas& canvas, const json& result) {
  const json& history = array_member(result, "history");
  if (history.empty()) throw std::invalid_argument("the result has no iteration history to plot");
  const int last = history.back().at("iteration").get<int>();
  const int first = history.front().at("iteration").get<int>();
  const int gaps = static_cast<int>(array_member(result, "gaps").size());

  const std::string title = result.value("title", "");
  const Rect area = draw_header(canvas, title.empty() ? "Gap iteration" : title,
                                "Convergence of the gap iteration (average closure over the gaps closed beyond "
                                "100 %) \u2014 " +
                                    run_summary(result.value("status", ""), result.value("iterations", 0)));
  const Typography t = typography(canvas);
  const Rect upper{area.x, area.y, area.width, area.height / 2.0 - 0.2 * t.margin};
  const Rect lower{area.x, upper.bottom() + 0.4 * t.margin, area.width, upper.height};

  const std::vector<Series> closure = {
      history_series(history, "max_closure", "maximum closure", {0.80, 0.10, 0.10}),
      history_series(history, "average_closure", "average closure", {0.10, 0.30, 0.75}),
      reference_series("100 % (contact)", colors::axis),
  };
  // The report leaves iteration 1's non-converged count blank: there is nothing to compare with.
  const std::vector<Series> counts = {
      history_series(history, "closed_gaps", "closed gaps", colors::black),
      history_series(history, "nonconverged_gaps", "non-converged gaps", {0.85, 0.45, 0.00}, true, 2),
  };
  double low = 0.0;
  for (const Series& s : closure) {
    for (const double v : s.y) low = std::min(low, v);
  }
  const Axis closure_axis = numeric_axis(low, largest(closure, 110.0), "closure (%)");
  const Axis count_axis = integer_axis(0, std::max(1, static_cast<int>(largest(counts, gaps))), "number of gaps", 6);
  // One gutter for both panels, so that their iteration axes line up.
  const Gutters a = Chart::gutters_for(canvas, closure_axis, closure), b = Chart::gutters_for(canvas, count_axis, counts);
  const Gutters both{std::max(a.left, b.left), std::max(a.right, b.right)};

  const Chart top(canvas, upper, integer_axis(first, last, "iteration", 10, 0.5), closure_axis, closure, both);
  top.draw_axes();
  top.draw_reference(100.0, colors::axis);
  for (const Series& s : closure) top.draw(s);
  top.draw_legend();

  const Chart bottom(canvas, lower, integer_axis(first, last, "iteration", 10, 0.5), count_axis, counts, both);
  bottom.draw_axes();
  for (const Series& s : counts) bottom.draw(s);
  bottom.draw_legend();
}

}  // namespace saasgaps::plot
