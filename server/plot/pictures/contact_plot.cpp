#include "plot/pictures/contact_plot.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"
#include "plot/result/contact_points.hpp"
#include "plot/result/field.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

/// The gap row's colours: a single part's panels, or one per part (the contact pairs' colours).
Rgb part_color(int k) { return pair_color(static_cast<std::size_t>(k)); }

}  // namespace

bool has_contact_points(const json& result) {
  const json& pairs = array_member(result, "contact");
  return std::any_of(pairs.begin(), pairs.end(), [](const json& pair) { return !array_member(pair, "points").empty(); });
}

DataTable draw_surface_contact_plot(const Canvas& canvas, const json& result, RowAxis along) {
  if (!has_contact_points(result)) {
    throw std::invalid_argument("the result has no contact surface points: there is no contact pressure to plot");
  }
  const std::vector<ContactPairCurve> curves = contact_pair_curves(result, along);
  const UnitNames units = result_units(result);
  const auto [title, status, iterations] = run_facts(result);

  // Always show 0 in both panels (and a gap panel of some height when every gap is 0).
  double low_x = INFINITY, high_x = -INFINITY, high_pressure = 0.0, low_gap = 0.0, high_gap = 0.0;
  std::size_t points = 0;
  for (const ContactPairCurve& c : curves) {
    points += c.x.size();
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      low_x = std::min(low_x, c.x[i]);
      high_x = std::max(high_x, c.x[i]);
      high_pressure = std::max(high_pressure, c.pressure[i]);
      low_gap = std::min(low_gap, c.gap[i]);
      high_gap = std::max(high_gap, c.gap[i]);
    }
  }
  if (!(high_x > low_x)) {
    low_x -= 0.5;
    high_x += 0.5;
  }
  // Touching points' gaps are round-off (1e-17 on a part of size 1): they belong on the 0 line, not
  // spread over an axis of their own. Gaps below 1e-9 of the parts' size do not widen the axis.
  double extent = 0.0;
  for (const ContactPairCurve& c : curves) {
    for (std::size_t i = 0; i < c.r.size(); ++i) extent = std::max({extent, std::abs(c.r[i]), std::abs(c.z[i])});
  }
  const double negligible = 1e-9 * (extent > 0.0 ? extent : 1.0);
  if (-low_gap < negligible) low_gap = 0.0;
  if (high_gap < negligible) high_gap = 0.0;
  if (!(high_gap > low_gap)) high_gap = low_gap + 1e3 * negligible;
  const bool markers = points <= 200;
  std::vector<Series> pressure_parts, gap_parts;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ContactPairCurve& c = curves[k];
    if (c.x.empty()) continue;
    Series pressure, gap;
    pressure.name = gap.name = c.name;
    pressure.color = gap.color = pair_color(k);
    pressure.x = gap.x = c.x;
    pressure.y = c.pressure;
    gap.y = c.gap;
    for (Series* s : {&pressure, &gap}) {
      s->width = 2.0;
      s->markers = markers;
    }
    pressure_parts.push_back(std::move(pressure));
    gap_parts.push_back(std::move(gap));
  }

  const Axis x_axis = contact_x_axis(low_x, high_x, along, units);
  const std::string subtitle = "Contact pressure " + unit_phrase(Quantity::stress, units) + " and gap along side A of " +
                               std::to_string(pressure_parts.size()) + " contact pair" +
                               (pressure_parts.size() == 1 ? "" : "s") + " (" + std::to_string(points) +
                               " points) \u2014 " + run_summary(status, iterations);
  const Rect area = draw_header(canvas, title.empty() ? "Contact along the contact surfaces" : title, subtitle);
  const Typography t = typography(canvas);
  const Rect upper{area.x, area.y, area.width, area.height / 2.0 - 0.2 * t.margin};
  const Rect lower{area.x, upper.bottom() + 0.4 * t.margin, area.width, upper.height};
  const Axis pressure_axis =
      numeric_axis(0.0, high_pressure > 0.0 ? high_pressure : 1.0, with_unit("contact pressure", Quantity::stress, units));
  const Axis gap_axis = numeric_axis(low_gap, high_gap, with_unit("gap", Quantity::length, units));
  std::vector<Series> bottom_legend = gap_parts;
  bottom_legend.push_back(reference_series("0 (touching)", colors::axis));
  const Gutters a = Chart::gutters_for(canvas, pressure_axis, pressure_parts);
  const Gutters b = Chart::gutters_for(canvas, gap_axis, bottom_legend);
  const Gutters both{std::max(a.left, b.left), std::max(a.right, b.right)};
  const Chart top(canvas, upper, x_axis, pressure_axis, pressure_parts, both);
  top.draw_axes();
  for (const Series& s : pressure_parts) top.draw(s);
  top.draw_legend();
  const Chart bottom(canvas, lower, x_axis, gap_axis, bottom_legend, both);
  bottom.draw_axes();
  bottom.draw_reference(0.0, colors::axis);
  for (const Series& s : gap_parts) bottom.draw(s);
  bottom.draw_legend();

  DataTable table({"pair", "point", "x", "r", "z", "pressure", "gap", "state", "px", "py_pressure", "py_gap"});
  table.note("SAASGAPS contact along the contact surfaces: " + title);
  table.note("x: " + x_axis.title + "; pair: 1, 2, .. the result's contact pairs (one curve each); point: 1, 2, .. "
             "along side A; pressure " + unit_phrase(Quantity::stress, units) + ", gap " +
             unit_phrase(Quantity::length, units));
  std::string names = "pairs (surfaces A / B):";
  for (std::size_t k = 0; k < curves.size(); ++k) names += " " + std::to_string(k + 1) + " = " + curves[k].name + ";";
  std::replace(names.begin(), names.end(), '\n', ' ');  // names are free text; a note is one line
  table.note(names);
  table.note("image " + std::to_string(canvas.width()) + "x" + std::to_string(canvas.height()) +
             " px; px, py_*: where each marker is drawn");
  table.note(y_tick_note("pressure", top));
  table.note(y_tick_note("gap", bottom));
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const ContactPairCurve& c = curves[k];
    for (std::size_t i = 0; i < c.x.size(); ++i) {
      const Point p = top.to_device(c.x[i], c.pressure[i]);
      const Point g = bottom.to_device(c.x[i], c.gap[i]);
      table.add_row({std::to_string(k + 1), std::to_string(i + 1), DataTable::number(c.x[i]),
                     DataTable::number(c.r[i]), DataTable::number(c.z[i]), DataTable::number(c.pressure[i]),
                     DataTable::number(c.gap[i]), c.state[i], DataTable::number(p.x), DataTable::number(p.y),
                     DataTable::number(g.y)});
    }
  }
  return table;
}

DataTable draw_contact_plot(const Canvas& canvas, const PlotResult& result, const GapRowOptions& row_options) {
  if (row_options.gap_ids.empty() && has_contact_points(result.document())) {
    return draw_surface_contact_plot(canvas, result.document(), row_options.along);
  }
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
  std::vector<Series> pressure_parts, closure_parts;
  for (int k = 0; k < row.parts(); ++k) {
    const auto [begin, end] = row.part_range(k);
    Series pressure, closure;
    if (row.parts() == 1) {
      pressure.name = "contact pressure";
      closure.name = "closure (final)";
      pressure.color = part_color(0);
      closure.color = part_color(1);
    } else {
      pressure.name = closure.name = "gaps " + std::to_string(mesh.gaps[row.gaps[begin]].id) + "\u2013" +
                                     std::to_string(mesh.gaps[row.gaps[end - 1]].id);
      pressure.color = closure.color = part_color(k);
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
  table.note(y_tick_note("pressure", top));
  table.note(y_tick_note("closure", bottom));
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
