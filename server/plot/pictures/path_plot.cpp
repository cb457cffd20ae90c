#include "plot/pictures/path_plot.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "plot/draw/chart.hpp"
#include "plot/draw/figure.hpp"
#include "plot/draw/number_format.hpp"
#include "plot/result/element_field.hpp"
#include "plot/result/field.hpp"
#include "plot/result/point_locator.hpp"

namespace saasgaps::plot {

using nlohmann::json;

PlanePoint parse_point(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) throw std::invalid_argument("'" + text + "' is not a point r,z");
  PlanePoint p{};
  for (int k = 0; k < 2; ++k) {
    const std::string number = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    const auto [stop, error] = std::from_chars(number.data(), number.data() + number.size(), p[k]);
    if (number.empty() || error != std::errc() || stop != number.data() + number.size() || !std::isfinite(p[k])) {
      throw std::invalid_argument("'" + number + "' in '" + text + "' is not a number");
    }
  }
  return p;
}

std::vector<std::array<double, 2>> parse_path(const std::string& text) {
  const auto fail = [&text](const std::string& why) {
    return std::invalid_argument("a path is 'r0,z0;r1,z1;..' with at least two points; '" + text + "': " + why);
  };
  std::vector<std::array<double, 2>> points;
  for (std::size_t begin = 0; begin <= text.size();) {
    const std::size_t end = std::min(text.find(';', begin), text.size());
    try {
      points.push_back(parse_point(text.substr(begin, end - begin)));
    } catch (const std::invalid_argument& e) {
      throw fail(e.what());
    }
    begin = end + 1;
  }
  if (points.size() < 2) throw fail("one point is not a path");
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    length += std::hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]);
  }
  if (!(length > 0.0)) throw fail("the path has no length");
  return points;
}

namespace {

struct Sample {
  double s, r, z;
};

/// `count` points evenly spaced by arc length along the polyline, both ends included.
std::vector<Sample> samples_along(const std::vector<std::array<double, 2>>& points, int count) {
  std::vector<double> at{0.0};  // arc length at each corner
  for (std::size_t i = 1; i < points.size(); ++i) {
    at.push_back(at.back() + std::hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1]));
  }
  std::vector<Sample> out;
  std::size_t segment = 1;
  for (int k = 0; k < count; ++k) {
    const double s = at.back() * k / (count - 1);
    while (segment + 1 < points.size() && at[segment] < s) ++segment;
    const double length = at[segment] - at[segment - 1];
    const double w = length > 0.0 ? std::clamp((s - at[segment - 1]) / length, 0.0, 1.0) : 0.0;
    out.push_back({s, points[segment - 1][0] + w * (points[segment][0] - points[segment - 1][0]),
                   points[segment - 1][1] + w * (points[segment][1] - points[segment - 1][1])});
  }
  return out;
}

std::string point_text(const std::array<double, 2>& p) {
  return "(" + format_value(p[0]) + ", " + format_value(p[1]) + ")";
}

}  // namespace

DataTable draw_path_plot(const Canvas& canvas, const PlotResult& result, const std::string& field_name,
                         const PathOptions& options, const PlanePoint& centre) {
  const FieldInfo& field = find_field(field_name);
  if (field.location == FieldLocation::gap) {
    throw std::invalid_argument("'" + field_name + "' is a gap field: plot it along a row of gaps, not a path");
  }
  if (options.points.size() < 2) throw std::invalid_argument("a path needs at least two points");
  if (options.samples < 2 || options.samples > 100000) {
    throw std::invalid_argument("a path takes 2 to 100000 samples, not " + std::to_string(options.samples));
  }
  const ResultMesh& mesh = result.mesh();
  if (mesh.solids.empty()) throw std::invalid_argument("the result has no solid elements to sample");
  const PointLocator locator(mesh);
  const ElementField values(result, field, centre);

  Series curve;
  curve.name = field_title(field, mesh);
  curve.color = {0.10, 0.30, 0.75};
  curve.width = 2.0;
  std::vector<Sample> samples = samples_along(options.points, options.samples);
  std::vector<int> element_ids;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Sample& p : samples) {
    double value = std::numeric_limits<double>::quiet_NaN();
    int id = 0;
    if (const std::optional<Location> at = locator.locate(p.r, p.z)) {
      id = mesh.solids[at->element].id;
      value = values.value(*at);
      low = std::min(low, value);
      high = std::max(high, value);
    }
    curve.x.push_back(p.s);
    curve.y.push_back(value);
    element_ids.push_back(id);
  }
  if (!std::isfinite(low)) {
    throw std::invalid_argument("the path " + point_text(options.points.front()) + " .. " +
                                point_text(options.points.back()) + " does not pass through the mesh");
  }

  std::string route;
  for (const auto& p : options.points) route += (route.empty() ? "" : " \u2192 ") + point_text(p);
  const std::string label = field_label(field, mesh, centre);
  const Rect area = draw_header(canvas, mesh.title.empty() ? "SAASGAPS result" : mesh.title,
                                label + " " + unit_phrase(field.quantity, mesh.units) + ", along " + route + "\n" +
                                    source_phrase(values.source()) + " interpolated in the elements at " +
                                    std::to_string(samples.size()) + " points of the undeformed mesh \u2014 " +
                                    run_summary(mesh.status, mesh.iterations));
  const double length = samples.back().s;
  const Chart chart(canvas, area, numeric_axis(0.0, length, with_unit("distance s along the path", Quantity::length, mesh.units)),
                    numeric_axis(low, high, with_unit(curve.name, field.quantity, mesh.units)), {curve});
  chart.draw_axes();
  chart.draw(curve);
  chart.draw_legend();

  DataTable table({"s", "r", "z", "element", field_name, "px", "py"});
  table.note("SAASGAPS " + field_name + " along a path: " + mesh.title);
  if (field.cylindrical != Cylindrical::none) table.note(label);  // says the centre
  table.note("s, r, z " + unit_phrase(Quantity::length, mesh.units) + "; " + field_name + " " +
             unit_phrase(field.quantity, mesh.units) + "; element empty and value empty outside the mesh");
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const bool inside = element_ids[k] != 0;
    const Point p = chart.to_device(samples[k].s, inside ? curve.y[k] : 0.0);
    table.add_row({DataTable::number(samples[k].s), DataTable::number(samples[k].r), DataTable::number(samples[k].z),
                   inside ? std::to_string(element_ids[k]) : "", DataTable::number(curve.y[k]), DataTable::number(p.x),
                   inside ? DataTable::number(p.y) : ""});
  }
  return table;
}

}  // namespace saasgaps::plot
