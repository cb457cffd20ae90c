#include "plot/result/point_probe.hpp"

#include <algorithm>
#include <sstream>

#include "plot/draw/number_format.hpp"
#include "plot/result/element_field.hpp"
#include "plot/result/point_locator.hpp"

namespace saasgaps::plot {

namespace {

/// Characters, not bytes, of UTF-8 text (for columns).
std::size_t text_width(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

std::string point_text(const PlanePoint& p) { return "(" + format_value(p[0]) + ", " + format_value(p[1]) + ")"; }

const char* source_name(FieldSource source) {
  switch (source) {
    case FieldSource::recovered: return "recovered";
    case FieldSource::averaged: return "averaged";
    case FieldSource::nodal: return "nodal";
    case FieldSource::element: return "element";
  }
  return "";
}

}  // namespace

PointOutsideMesh::PointOutsideMesh(const PlanePoint& point)
    : std::invalid_argument("the point (r, z) = " + point_text(point) +
                            " lies in no solid element of the result (outside the body, in a hole or a gap)"),
      at(point) {}

std::vector<std::string> default_probe_fields(const ResultMesh& mesh) {
  std::vector<std::string> fields{"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective", "u_r", "u_z"};
  if (std::any_of(mesh.nodes.begin(), mesh.nodes.end(), [](const MeshNode& n) { return n.temperature != 0.0; })) {
    fields.emplace_back("temperature");
  }
  return fields;
}

std::vector<std::string> probe_element_keys(const std::vector<std::string>& fields) {
  std::vector<std::string> keys;
  const auto add = [&keys](std::string_view key) {
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.emplace_back(key);
  };
  if (fields.empty()) {
    for (const char* key : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective"}) add(key);
  }
  for (const std::string& name : fields) {
    for (const std::string_view key : element_keys(find_field(name))) add(key);
  }
  return keys;
}

Probe probe_point(const PlotResult& result, const PlanePoint& at, std::vector<std::string> fields) {
  const ResultMesh& mesh = result.mesh();
  if (fields.empty()) fields = default_probe_fields(mesh);
  std::vector<ElementField> values;
  values.reserve(fields.size());
  for (const std::string& name : fields) {
    const FieldInfo& field = find_field(name);
    if (field.location == FieldLocation::gap) {
      throw std::invalid_argument("'" + name + "' is a gap field, without values inside the elements");
    }
    values.emplace_back(result, field);
  }
  const PointLocator locator(mesh);
  const std::vector<Location> holders = locator.locate_all(at[0], at[1]);
  if (holders.empty()) throw PointOutsideMesh(at);
  Probe probe{at, fields, {}, FieldSource::recovered};
  for (const ElementField& v : values) {
    if (v.info().quantity == Quantity::stress && v.source() != FieldSource::recovered) probe.stress_source = v.source();
  }
  for (const Location& location : holders) {
    const SolidElement& e = mesh.solids[location.element];
    const bool seen = std::any_of(probe.sides.begin(), probe.sides.end(),
                                  [&e](const ProbeSide& side) { return side.material == e.material; });
    if (seen) continue;
    ProbeSide side{e.id, e.material, {}};
    for (const ElementField& v : values) side.values.push_back(v.value(location));
    probe.sides.push_back(std::move(side));
  }
  return probe;
}

nlohmann::json probe_json(const Probe& probe, const ResultMesh& mesh) {
  const auto values_of = [&probe](const ProbeSide& side) {
    nlohmann::json v = nlohmann::json::object();
    for (std::size_t k = 0; k < probe.fields.size(); ++k) v[probe.fields[k]] = side.values[k];
    return v;
  };
  nlohmann::json out{{"at", {{"r", probe.at[0]}, {"z", probe.at[1]}}},
                     {"element", probe.sides.front().element},
                     {"material", probe.sides.front().material},
                     {"stresses", source_name(probe.stress_source)},
                     {"values", values_of(probe.sides.front())},
                     {"sides", nlohmann::json::array()}};
  for (std::size_t s = 1; s < probe.sides.size(); ++s) {
    out["sides"].push_back({{"element", probe.sides[s].element},
                            {"material", probe.sides[s].material},
                            {"values", values_of(probe.sides[s])}});
  }
  const UnitNames& u = mesh.units;
  if (!u.length.empty() || !u.stress.empty() || !u.temperature.empty()) {
    out["units"] = {{"length", u.length}, {"stress", u.stress}, {"temperature", u.temperature}};
  }
  return out;
}

std::string probe_text(const Probe& probe, const ResultMesh& mesh) {
  std::ostringstream out;
  out << "point " << (mesh.plane() ? "(x, y) = " : "(r, z) = ") << point_text(probe.at) << " in element "
      << probe.sides.front().element << " (material " << probe.sides.front().material << ")";
  if (probe.stress_source != FieldSource::recovered) {
    out << "; stresses: " << source_phrase(probe.stress_source) << " (the result has no recovered stresses)";
  }
  out << "\n";
  std::size_t width = 0;
  std::vector<std::string> names;
  for (const std::string& name : probe.fields) {
    names.push_back(with_unit(field_title(find_field(name), mesh), find_field(name).quantity, mesh.units));
    width = std::max(width, text_width(names.back()));
  }
  for (std::size_t s = 0; s < probe.sides.size(); ++s) {
    if (s > 0) {
      out << "material " << probe.sides[s].material << "'s side (element " << probe.sides[s].element << "):\n";
    }
    for (std::size_t k = 0; k < probe.fields.size(); ++k) {
      out << "  " << names[k] << std::string(width - text_width(names[k]) + 2, ' ')
          << format_value(probe.sides[s].values[k], 6) << "\n";
    }
  }
  return out.str();
}

}  // namespace saasgaps::plot
