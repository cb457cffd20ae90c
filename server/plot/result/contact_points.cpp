#include "plot/result/contact_points.hpp"

#include <cmath>
#include <iterator>

#include "plot/draw/data_table.hpp"
#include "plot/result/field.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

using nlohmann::json;

namespace {

constexpr Rgb part_colors[] = {{0.75, 0.10, 0.10}, {0.10, 0.30, 0.75}, {0.10, 0.55, 0.20},
                               {0.85, 0.45, 0.00}, {0.50, 0.20, 0.65}, {0.35, 0.35, 0.35}};

/// A number member (0 when absent or not a number).
double member(const json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : 0.0;
}

}  // namespace

std::vector<ContactPairCurve> contact_pair_curves(const json& result, RowAxis along) {
  std::vector<ContactPairCurve> curves;
  for (const json& pair : array_member(result, "contact")) {
    ContactPairCurve c;
    if (const auto s = pair.find("surfaces"); s != pair.end() && s->is_array() && s->size() == 2 &&
                                              (*s)[0].is_string() && (*s)[1].is_string()) {
      c.name = (*s)[0].get<std::string>() + " / " + (*s)[1].get<std::string>();
    } else {
      c.name = "pair " + std::to_string(curves.size() + 1);
    }
    if (pair.is_object()) c.friction = member(pair, "friction");
    double arc = 0.0;
    for (const json& point : array_member(pair, "points")) {
      const double r = member(point, "r"), z = member(point, "z");
      if (!c.r.empty()) arc += std::hypot(r - c.r.back(), z - c.z.back());
      c.r.push_back(r);
      c.z.push_back(z);
      c.pressure.push_back(member(point, "pressure"));
      c.gap.push_back(member(point, "gap"));
      c.shear.push_back(member(point, "shear"));
      c.slip.push_back(member(point, "slip"));
      const auto state = point.find("state");
      c.state.push_back(state != point.end() && state->is_string() ? state->get<std::string>() : "");
      switch (along) {
        case RowAxis::index: c.x.push_back(static_cast<double>(c.r.size())); break;
        case RowAxis::position: c.x.push_back(arc); break;
        case RowAxis::r: c.x.push_back(r); break;
        case RowAxis::z: c.x.push_back(z); break;
      }
    }
    curves.push_back(std::move(c));
  }
  return curves;
}

Axis contact_x_axis(double low, double high, RowAxis along, const UnitNames& units) {
  static constexpr const char* axis_names[] = {"point along side A", "arc length along side A", "r", "z"};
  const std::string name = axis_names[static_cast<int>(along)];
  return along == RowAxis::index ? integer_axis(static_cast<int>(low), static_cast<int>(high), name, 10, 0.5)
                                 : numeric_axis(low, high, with_unit(name, Quantity::length, units));
}

RunFacts run_facts(const json& result) {
  const auto text = [&](const char* key) {
    const auto it = result.find(key);
    return it != result.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  const auto count = result.find("iterations");
  return {text("title"), text("status"), count != result.end() && count->is_number_integer() ? count->get<int>() : 0};
}

UnitNames result_units(const json& result) {
  UnitNames units;
  if (const auto u = result.find("units"); u != result.end() && u->is_object()) {
    units = {u->value("length", ""), u->value("force", ""), u->value("stress", ""), u->value("temperature", "")};
  }
  return units;
}

Rgb pair_color(std::size_t k) { return part_colors[k % std::size(part_colors)]; }

std::string y_tick_note(const char* panel, const Chart& chart) {
  std::string note = std::string("ticks ") + panel + ":";
  for (const double t : chart.y_axis().ticks) {
    note += " " + DataTable::number(t) + "@" + DataTable::number(chart.to_device(chart.x_axis().min, t).y);
  }
  return note;
}

}  // namespace saasgaps::plot
