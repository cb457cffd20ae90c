/// The assembly's `loads` (docs/import.md): the kinds of load_kind_names, each on the nodes or edges
/// of the physical groups it names; pressures on curves, nodal forces at points, temperatures by
/// group or from a file another program wrote (nodal_values_file.hpp). The body force passes
/// through.
#include "io/import/assembly_importer.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/import/nodal_values_file.hpp"
#include "io/json/json_pointer.hpp"
#include "io/json/value_rules.hpp"
#include "solver/model/loads.hpp"

namespace saasgaps::io::assembly {

void Importer::loads(json& model) {
  const auto it = doc_.find("loads");
  if (it == doc_.end()) return;
  if (auto out = converted_loads(*it, "/loads")) model["loads"] = std::move(*out);
}

std::optional<json> Importer::converted_loads(const json& loads, const std::string& p) {
  const auto kinds = load_kind_names.names();
  if (!check_object(loads, p, {}, kinds, reporter())) return std::nullopt;
  json out = json::object();
  pressures(loads, p, out);
  nodal_forces(loads, p, out);
  temperatures(loads, p, out);
  if (const auto b = loads.find("body_force"); b != loads.end()) out["body_force"] = *b;
  return out;
}

/// pressures: [{group (curve), normal?, shear?}] on every edge of the group, each edge listed in the
/// counter-clockwise order of the one solid element that owns it (shear > 0 runs that way).
void Importer::pressures(const json& loads, const std::string& lp, json& out) {
  const json* list = array(loads, lp, "pressures", false);
  if (list == nullptr || !mesh_loaded_) return;
  json& result = out["pressures"] = json::array();
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string p = pointer_append(pointer_append(lp, "pressures"), i);
    const json& o = (*list)[i];
    if (!object(o, p, {"group"}, {"normal", "shear"})) continue;
    const PhysicalGroup* g = group(o, p, {{1}, "a pressure", "a curve (dimension 1)"});
    const double normal = number(o, p, "normal").value_or(0.0);
    const double shear = number(o, p, "shear").value_or(0.0);
    if (g == nullptr) continue;
    for (const BoundaryEdge& e : boundary_edges(*g, p, "a pressure").value_or(std::vector<BoundaryEdge>{})) {
      result.push_back({{"nodes", {tag_of(e.a), tag_of(e.b)}}, {"normal", normal}, {"shear", shear}});
    }
  }
}

/// nodal_forces: [{group (points), fr?, fz?}]: the force at each point of the group.
void Importer::nodal_forces(const json& loads, const std::string& lp, json& out) {
  const json* list = array(loads, lp, "nodal_forces", false);
  if (list == nullptr || !mesh_loaded_) return;
  json& result = out["nodal_forces"] = json::array();
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string p = pointer_append(pointer_append(lp, "nodal_forces"), i);
    const json& o = (*list)[i];
    if (!object(o, p, {"group"}, {"fr", "fz"})) continue;
    const PhysicalGroup* g = group(o, p, {{0}, "a nodal force", "points (dimension 0)"});
    const double fr = number(o, p, "fr").value_or(0.0), fz = number(o, p, "fz").value_or(0.0);
    if (g == nullptr) continue;
    for (const int node : group_nodes(*g, p)) result.push_back({{"node", tag_of(node)}, {"fr", fr}, {"fz", fz}});
  }
}

/// temperatures: {default?, groups?: [{group, T}], file?: {path, field?, tolerance?}}. A node takes
/// its value from at most one source besides the default (groups that share a node must agree).
void Importer::temperatures(const json& loads, const std::string& lp, json& out) {
  const auto it = loads.find("temperatures");
  if (it == loads.end()) return;
  const std::string tp = pointer_append(lp, "temperatures");
  if (!object(*it, tp, {}, {"default", "groups", "file"}) || !mesh_loaded_) return;
  json result = json::object();
  if (const auto d = number(*it, tp, "default")) result["default"] = *d;
  std::vector<std::optional<double>> T(mesh_.node_tags.size());
  std::vector<std::string> source(mesh_.node_tags.size());
  if (const json* list = array(*it, tp, "groups", false)) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string p = pointer_append(pointer_append(tp, "groups"), i);
      const json& o = (*list)[i];
      if (!object(o, p, {"group", "T"}, {})) continue;
      const PhysicalGroup* g = group(o, p, {{0, 1, 2}, "a temperature", "a point, curve or surface"});
      const auto value = number(o, p, "T");
      if (g == nullptr || !value) continue;
      for (const int node : group_nodes(*g, p)) {
        const auto n = static_cast<std::size_t>(node);
        if (T[n] && *T[n] != *value) {
          report(pointer_append(p, "T"), "node " + std::to_string(tag_of(node)) + " gets T = " + json(*value).dump() +
                                             " here and T = " + json(*T[n]).dump() + " from " + source[n] +
                                             "; groups that share nodes must agree");
          break;
        }
        T[n] = *value;
        source[n] = pointer_append(p, "T");
      }
    }
  }
  if (const auto f = it->find("file"); f != it->end()) temperature_file(*f, pointer_append(tp, "file"), T, source);
  json nodal = json::array();
  for (std::size_t n = 0; n < T.size(); ++n) {
    if (T[n]) nodal.push_back({{"node", tag_of(static_cast<int>(n))}, {"T", *T[n]}});
  }
  if (!nodal.empty()) result["nodal"] = std::move(nodal);
  out["temperatures"] = std::move(result);
}

/// {path (.csv or .vtu), field? = "T", tolerance?}: values by node id, or by position within
/// tolerance (default 1e-6 of the mesh's extent). Every row must find its node.
void Importer::temperature_file(const json& file, const std::string& p, std::vector<std::optional<double>>& T,
                                std::vector<std::string>& source) {
  if (!object(file, p, {"path"}, {"field", "tolerance"})) return;
  const auto name = string(file, p, "path");
  const std::string field = string(file, p, "field").value_or("T");
  const auto tolerance_given = number(file, p, "tolerance", positive);
  if (!name) return;
  const auto resolved = resolve_file(*name, pointer_append(p, "path"));
  if (!resolved) return;
  const fs::path& path = *resolved;
  NodalValues values;
  try {
    if (path.extension() == ".csv") {
      values = read_nodal_csv(path, field);
    } else if (path.extension() == ".vtu") {
      values = read_vtu_point_field(path, field);
    } else {
      report(pointer_append(p, "path"), "\"" + *name + "\" must be a .csv or .vtu file");
      return;
    }
  } catch (const NodalFileError& e) {
    report(pointer_append(p, "path"), e.what());
    return;
  }
  const double tolerance = tolerance_given.value_or(1e-6 * std::max(extent(), 1e-300));
  const std::vector<int> matched = match_rows(values, mesh_.node_tags, mesh_.r, mesh_.z, tolerance);
  const std::string at = pointer_append(p, "path");
  std::size_t unmatched = 0;
  std::string first_unmatched;
  for (std::size_t row = 0; row < values.values.size(); ++row) {
    const int node = matched[row];
    if (node < 0) {
      if (unmatched++ == 0) {
        first_unmatched = (path.extension() == ".csv" ? "line " : "point ") + std::to_string(values.origin[row]) +
                          (values.by_id ? " (node " + std::to_string(values.ids[row]) + ")"
                                        : " at (" + json(values.r[row]).dump() + ", " + json(values.z[row]).dump() + ")");
      }
      continue;
    }
    const auto n = static_cast<std::size_t>(node);
    if (T[n] && source[n] != at) {
      report(at, "node " + std::to_string(tag_of(node)) + " has a temperature from " + source[n] +
                     " and from this file; give each node one temperature");
      return;
    }
    T[n] = values.values[row];
    source[n] = at;
  }
  if (unmatched > 0) {
    report(at, std::to_string(unmatched) + " row(s) of " + *name + " match no node of the mesh" +
                   (values.by_id ? "" : " within " + json(tolerance).dump()) + ", first " + first_unmatched);
  }
}

}  // namespace saasgaps::io::assembly
