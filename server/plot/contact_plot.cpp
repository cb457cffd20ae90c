#include "plot/contact_plot.hpp"

#include <algorithm>

#include "plot/chart.hpp"
#include "plot/field.hpp"
#include "plot/figure.hpp"
#include "plot/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

/// "# ticks <panel>: value@px value@px ..": where each y tick sits on the image.
std::string tick_note(const char* panel, const Chart& chart) {
  std::string note = std::string("ticks ") + panel + ":";
  for (const double t : chart.y_axis().ticks) {
    note += " " + DataTable::number(t) + "@" + DataTable::number(chart.to_device(chart.x_axis().min, t).y);
  }
  return note;
}

}  // namespace

DataTable draw_contact_plot(const Canvas& canvas, const PlotResult& result, const GapRowOptions& row_options) {
  const ResultMesh& mesh = result.mesh();
  if (mesh.gaps.empty()) throw std::invalid_argument("the result has no gap elements: there is no contact pressure to plot");
  const GapRow row = select_gap_row(mesh, row_options, gap_labels_that_fit(canvas, mesh));

  // One series per part of the row (an interface): a line never joins two interfaces. A single
  // part keeps the panels' colours; several get one colour each, the same in both panels.
  double high_pressure = 0.0, low_closure = 0.0, high_closure = 110.0;  // always show 0 and the 100 % line
  std::vector<double> pressures, closures;
  for (const std::size_t g : row.gaps) {
    pressures.push_back(mesh.gaps[g].contact_pressure);
    closures.push_back(mesh.gaps[g].closure);
    high_pressure = std::max(high_pressure, mesh.gaps[g].contact_pressure);
    low_closure = std::min(low_closure, mesh.gaps[g].closure);
    high_closure = std::max(high_closure, mesh.gaps[g].closure);
  }
  const bool markers = row.gaps.size() <= 200;
  static constexpr Rgb part_colors[] = {{0.75, 0.10, 0.10}, {0.10, 0.30, 0.75}, {0.10, 0.55, 0.20},
                                        {0.85, 0.45, 0.00}, {0.50, 0.20, 0.65}, {0.35, 0.35, 0.35}};
  std::vector<Series> pressure_parts, closure_parts;
  for (int k = 0; k < row.parts(); ++k) {
    const auto [begin, end] = row.part_range(k);
    Series pressure, closure;
    if (row.parts() == 1) {
      pressure.name = "contact pressure";
      closure.name = "closure (final)";
      pressure.color = part_colors[0];
      closure.color = part_colors[1];
    } else {
      pressure.name = closure.name = "gaps " + std::to_string(mesh.gaps[row.gaps[begin]].id) + "\u2013" +
                                     std::to_string(mesh.gaps[row.gaps[end - 1]].id);
      pressure.color = closure.color = part_colors[k % std::size(part_colors)];
    }
    row.set_points(pressure, pressures, begin, end);
    row.set_points(closure, closures, begin, end);
    for (Series* s : {&pressure, &closure}) {
      s->width = 2.0;
      s->markers = markers;
    }
    pressure_parts.push_back(std::move(pressure));
    closure_parts.push_back(std::move(closure));
  }

  const std::string first = std::to_string(mesh.gaps[row.gaps.front()].id);
  const std::string last = std::to_string(mesh.gaps[row.gaps.back()].id);
  const std::string subtitle = "Contact pressure max(0, \u2212\u03c3M) " + unit_phrase(Quantity::stress, mesh.units) +
                               " and closure along gaps " + first + " \u2026 " + last + " (" +
                               std::to_string(row.gaps.size()) + " gaps" +
                               (row.parts() > 1 ? " in " + std::to_string(row.parts()) + " separate rows" : "") +
                               ") \u2014 " +
                               run_summary(mesh.status, mesh.iterations);
  const Rect area = draw_header(canvas, mesh.title.empty() ? "Contact along a row of gaps" : mesh.title, subtitle);
  const Typography t = typography(canvas);
  const Rect upper{area.x, area.y, area.width, area.height / 2.0 - 0.2 * t.margin};
  const Rect lower{area.x, upper.bottom() + 0.4 * t.margin, area.width, upper.height};

  const Axis pressure_axis =
      numeric_axis(0.0, high_pressure > 0.0 ? high_pressure : 1.0, with_unit("contact pressure", Quantity::stress, mesh.units));
  const Axis closure_axis = numeric_axis(low_closure, high_closure, "closure [%]");
  const Rgb contact_color = colors::axis;
  const std::vector<Series>& top_legend = pressure_parts;
  std::vector<Series> bottom_legend = closure_parts;
  bottom_legend.push_back(reference_series("100 % (contact)", contact_color));
  const Gutters a = Chart::gutters_for(canvas, pressure_axis, top_legend);
  const Gutters b = Chart::gutters_for(canvas, closure_axis, bottom_legend);
  const Gutters both{std::max(a.left, b.left), std::max(a.right, b.right)};

  const Chart top(canvas, upper, row.axis, pressure_axis, top_legend, both);
  top.draw_axes();
  for (const Series& s : pressure_parts) top.draw(s);
  top.draw_legend();
  const Chart bottom(canvas, lower, row.axis, closure_axis, bottom_legend, both);
  bottom.draw_axes();
  bottom.draw_reference(100.0, contact_color);
  for (const Series& s : closure_parts) bottom.draw(s);
  bottom.draw_legend();

  DataTable table(
      {"gap", "x", "row_part", "contact_pressure", "closure", "sigma_m", "state", "px", "py_pressure", "py_closure"});
  table.note("SAASGAPS contact along a row of gaps: " + mesh.title);
  table.note("x: " + row.axis.title + "; row_part: 1, 2, .. the connected run of gaps (one curve each); "
             "contact_pressure = max(0, -sigma_m) " + unit_phrase(Quantity::stress, mesh.units) + "; closure in %");
  table.note("image " + std::to_string(canvas.width()) + "x" + std::to_string(canvas.height()) +
             " px; px, py_*: where each marker is drawn");
  table.note(tick_note("pressure", top));
  table.note(tick_note("closure", bottom));
  for (std::size_t i = 0; i < row.gaps.size(); ++i) {
    const GapElement& g = mesh.gaps[row.gaps[i]];
    const Point p = top.to_device(row.x[i], g.contact_pressure);
    const Point c = bottom.to_device(row.x[i], g.closure);
    table.add_row({std::to_string(g.id), DataTable::number(row.x[i]), std::to_string(row.part[i] + 1),
                   DataTable::number(g.contact_pressure),
                   DataTable::number(g.closure), DataTable::number(g.sigma_m), std::string(to_string(g.state)),
                   DataTable::number(p.x), DataTable::number(p.y), DataTable::number(c.y)});
  }
  return table;
}

}  // namespace saasgaps::plot
