#include "plot/pictures/force_plot.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

DataTable draw_force_plot(const Canvas& canvas, const json& result, const std::string& set) {
  if (set.empty()) throw std::invalid_argument("--field force needs --set NAME: the node set whose reactions to plot");
  const json& history = array_member(result, "history");
  Series fr, fz;
  fr.name = "fr (summed reactions along r)";
  fz.name = "fz (summed reactions along z)";
  fr.color = {0.10, 0.30, 0.75};
  fz.color = {0.80, 0.10, 0.10};
  fr.width = fz.width = 2.0;
  std::vector<std::pair<int, int>> at;  // (step, increment) of each point
  std::set<std::string> names;
  for (const json& row : history) {
    const auto sums = row.find("set_reactions");
    if (sums == row.end() || !sums->is_array()) continue;
    for (const json& s : *sums) {
      const std::string name = s.value("set", "");
      names.insert(name);
      if (name != set) continue;
      const double x = static_cast<double>(fz.x.size() + 1);
      fr.x.push_back(x);
      fz.x.push_back(x);
      fr.y.push_back(s.value("fr", 0.0));
      fz.y.push_back(s.value("fz", 0.0));
      at.emplace_back(row.value("step", 0), row.value("increment", 0));
    }
  }
  if (fz.x.empty()) {
    std::string known;
    for (const std::string& n : names) known += (known.empty() ? "" : ", ") + ("'" + n + "'");
    throw std::invalid_argument("the history has no reactions of set '" + set + "'" +
                                (known.empty() ? std::string("; it has none at all (set_reactions come with "
                                                             "constraints that name a node set, docs/model.md)")
                                               : "; its sets: " + known));
  }
  fr.markers = fz.markers = fz.x.size() <= 60;
  const json units = result.value("units", json::object());
  const std::string force = units.is_object() && units.contains("force") && units["force"].is_string()
                                ? " (" + units["force"].get<std::string>() + ")"
                                : std::string();
  const std::string title = result.value("title", "");
  const Rect area = draw_header(canvas, title.empty() ? "Support force" : title,
                                "Summed reactions of set '" + set + "' at the end of each increment \u2014 " +
                                    run_summary(result.value("status", ""), result.value("iterations", 0)));
  double lo = 0.0, hi = 0.0;
  for (const Series* s : {&fr, &fz}) {
    for (const double v : s->y) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  const std::vector<Series> legend = {fr, fz};
  const Axis x_axis = integer_axis(1, static_cast<int>(fz.x.size()), "increment of the load path", 10, 0.5);
  const Chart chart(canvas, area, x_axis, numeric_axis(lo, hi > lo ? hi : lo + 1.0, "force" + force), legend);
  chart.draw_axes();
  chart.draw(fr);
  chart.draw(fz);
  chart.draw_legend();

  DataTable table({"increment", "step", "step_increment", "fr", "fz", "px", "py_fr", "py_fz"});
  table.note("SAASGAPS support force of set " + set + ": " + title);
  table.note("force" + force + " against the increments of the load path (the end of each converged increment)");
  for (std::size_t k = 0; k < fz.x.size(); ++k) {
    const Point p_r = chart.to_device(fr.x[k], fr.y[k]), p_z = chart.to_device(fz.x[k], fz.y[k]);
    table.add_row({std::to_string(k + 1), std::to_string(at[k].first), std::to_string(at[k].second),
                   DataTable::number(fr.y[k]), DataTable::number(fz.y[k]), DataTable::number(p_z.x),
                   DataTable::number(p_r.y), DataTable::number(p_z.y)});
  }
  return table;
}

}  // namespace saasgaps::plot
