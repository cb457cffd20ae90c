#include "io/results/vtu_writer.hpp"

#include "solver/fe/element_family.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <unordered_map>
#include <vector>

namespace saasgaps::io {

using nlohmann::json;

int vtu_gap_state_code(const std::string& state) {
  if (state == "open") return 0;
  if (state == "partial") return 1;
  if (state == "closed") return 2;
  if (state == "overclosed") return 3;
  throw std::invalid_argument("unknown gap state '" + state + "'");
}

std::string vtu_unit_suffix(const json& result, const char* kind) {
  const auto units = result.find("units");
  if (units == result.end() || !units->is_object()) return "";
  const std::string name = units->value(kind, "");
  return name.empty() ? "" : " [" + name + "]";
}

const ResultSelection& vtu_result_selection() {
  static const ResultSelection selection{
      .mesh = true,
      .element_keys = {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "sigma_1", "sigma_2", "angle", "effective", "eps_r",
                       "eps_z", "gamma_rz", "eps_theta", "yield", "plastic_converged", "q_r", "q_z", "error"}};
  return selection;
}

namespace {


/// The mesh of a result: the solids (typed), the gaps (from the tree), the piece's geometry arrays.
struct Mesh {
  const ResultNodes* nodes = nullptr;
  const ResultElements* solids = nullptr;
  std::vector<const json*> gaps;  ///< pointers into the result's tree: no copy
  VtuPiece piece;

  [[nodiscard]] std::size_t cells() const { return solids->size() + gaps.size(); }
};

Mesh read_mesh(const ResultArrays& result) {
  const json& document = result.document;
  if (document.value("status", "") == "failed") {
    throw std::invalid_argument("the run failed, so the result has no mesh to export: " + document.value("message", ""));
  }
  if (result.mesh_error) throw std::invalid_argument(*result.mesh_error);
  if (!result.nodes || result.nodes->id.empty()) {
    throw std::invalid_argument("the result document has no node coordinates (nodes[].r, .z): solve the model again");
  }
  if (!result.elements) throw std::invalid_argument("malformed result document: /elements is missing or not an array");
  Mesh m;
  m.nodes = &*result.nodes;
  m.solids = &*result.elements;
  const ResultNodes& nodes = *m.nodes;
  std::unordered_map<int, std::int64_t> index;
  for (std::size_t n = 0; n < nodes.id.size(); ++n) index.emplace(nodes.id[n], static_cast<std::int64_t>(n));
  if (const auto gaps = document.find("gaps"); gaps != document.end()) {
    for (const json& g : *gaps) m.gaps.push_back(&g);
  }
  m.piece.points = nodes.id.size();
  m.piece.cells = m.cells();
  m.piece.comment = "SAASGAPS result: " + document.value("title", "") + " (" + document.value("analysis", "") + ", " +
                    document.value("status", "") + ")";
  std::vector<double> xyz;
  xyz.reserve(3 * nodes.id.size());
  for (std::size_t n = 0; n < nodes.id.size(); ++n) xyz.insert(xyz.end(), {nodes.r[n], nodes.z[n], 0.0});
  m.piece.coordinates = {"Points", 3, std::move(xyz)};
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  const auto cell = [&](const std::string& id, const auto& node_ids) {
    // The node count names the VTK cell: the families that share one (saas and quad4i) share the cell.
    const std::optional<ElementType> type = default_element_type(static_cast<int>(node_ids.size()));
    if (!type) {
      throw std::invalid_argument("element " + id + " has " + std::to_string(node_ids.size()) +
                                  " nodes; 3, 4, 6, 8 or 9 expected");
    }
    for (const auto& node : node_ids) {
      const int node_id = static_cast<int>(node);
      const auto found = index.find(node_id);
      if (found == index.end()) {
        throw std::invalid_argument("element " + id + " refers to node " + std::to_string(node_id) +
                                    ", which is not in the result's nodes");
      }
      connectivity.push_back(found->second);
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(static_cast<std::uint8_t>(family(*type).vtk_type));
  };
  const ResultElements& solids = *m.solids;
  for (std::size_t e = 0; e < solids.size(); ++e) {
    cell(std::to_string(solids.id[e]),
         std::vector<int>(solids.node_ids.begin() + static_cast<std::ptrdiff_t>(solids.first_node[e]),
                          solids.node_ids.begin() + static_cast<std::ptrdiff_t>(solids.first_node[e + 1])));
  }
  for (const json* g : m.gaps) cell(g->at("id").dump(), g->at("nodes").get<std::vector<int>>());
  m.piece.connectivity = {"connectivity", 1, std::move(connectivity)};
  m.piece.offsets = {"offsets", 1, std::move(offsets)};
  m.piece.types = {"types", 1, std::move(types)};
  return m;
}

std::vector<VtuArray> id_arrays(const Mesh& m) {
  std::vector<std::int32_t> ids(m.solids->id.begin(), m.solids->id.end()), gap(m.solids->size(), 0);
  for (const json* g : m.gaps) {
    ids.push_back(g->at("id").get<std::int32_t>());
    gap.push_back(1);
  }
  return {{"element_id", 1, std::move(ids)}, {"is_gap", 1, std::move(gap)}};
}

/// The contact_* point arrays (see the header): each point of result `contact` on the node at its
/// (r, z), which is where the solver puts it (a side-A node's reference position, the same double).
void add_contact_point_data(const json& result, const ResultNodes& nodes, const std::string& stress, const std::string& length,
                            std::vector<VtuArray>& point_data) {
  const auto contact = result.find("contact");
  if (contact == result.end() || !contact->is_array() || contact->empty()) return;
  std::map<std::pair<double, double>, std::size_t> at;
  const std::size_t count = nodes.id.size();
  for (std::size_t n = 0; n < count; ++n) at.emplace(std::pair{nodes.r[n], nodes.z[n]}, n);
  std::vector<double> pressure(count, 0.0), gap(count, 0.0), shear(count, 0.0), slip(count, 0.0);
  std::vector<std::int32_t> state(count, -1), pair_number(count, 0);
  for (std::size_t k = 0; k < contact->size(); ++k) {
    for (const json& point : (*contact)[k].at("points")) {
      const double r = point.at("r").get<double>(), z = point.at("z").get<double>();
      const auto node = at.find({r, z});
      if (node == at.end()) {
        throw std::invalid_argument("contact pair " + std::to_string(k + 1) + " has a point at (" + json(r).dump() + ", " +
                                    json(z).dump() + "), which is not a node of the result");
      }
      const std::size_t n = node->second;
      pressure[n] = point.at("pressure").get<double>();
      gap[n] = point.at("gap").get<double>();
      shear[n] = point.value("shear", 0.0);
      slip[n] = point.value("slip", 0.0);
      const std::string name = point.at("state").get<std::string>();
      if (name != "open" && name != "stick" && name != "slip") throw std::invalid_argument("unknown contact state '" + name + "'");
      state[n] = name == "open" ? 0 : name == "stick" ? 1 : 2;
      pair_number[n] = static_cast<std::int32_t>(k + 1);
    }
  }
  point_data.push_back({"contact_pressure" + stress, 1, std::move(pressure)});
  point_data.push_back({"contact_gap" + length, 1, std::move(gap)});
  point_data.push_back({"contact_shear" + stress, 1, std::move(shear)});
  point_data.push_back({"contact_slip" + length, 1, std::move(slip)});
  point_data.push_back({"contact_state", 1, std::move(state)});
  point_data.push_back({"contact_pair", 1, std::move(pair_number)});
}

/// The solids' column of an element member (vtu_result_selection's keys).
const std::vector<double>& solid_column(const ResultArrays& result, std::string_view key) {
  const std::vector<std::string>& keys = result.element_keys;
  const auto k = static_cast<std::size_t>(std::find(keys.begin(), keys.end(), key) - keys.begin());
  if (k == keys.size()) throw std::logic_error("the result was read without the elements' '" + std::string(key) + "'");
  const ResultElements& solids = *result.elements;
  if (const std::optional<std::size_t> missing = solids.first_missing[k]) {
    throw std::invalid_argument("malformed result document: element " + std::to_string(solids.id[*missing]) +
                                " has no '" + std::string(key) + "'");
  }
  return solids.values[k];
}

std::string vtu_document(const ResultArrays& result, VtuFormat format) {
  Mesh m = read_mesh(result);
  const ResultNodes& nodes = *m.nodes;
  const json& document = result.document;
  const std::string stress = vtu_unit_suffix(document, "stress"), length = vtu_unit_suffix(document, "length"),
                    temperature = vtu_unit_suffix(document, "temperature");

  // ---- Point data.
  std::vector<double> displacement;
  displacement.reserve(3 * nodes.id.size());
  for (std::size_t n = 0; n < nodes.id.size(); ++n) displacement.insert(displacement.end(), {nodes.u_r[n], nodes.u_z[n], 0.0});
  m.piece.active_vectors = "displacement" + length;
  m.piece.active_scalars = "temperature" + temperature;
  m.piece.point_data = {{m.piece.active_vectors, 3, std::move(displacement)},
                        {m.piece.active_scalars, 1, nodes.T},
                        {"node_id", 1, std::vector<std::int32_t>(nodes.id.begin(), nodes.id.end())}};
  if (const auto reactions = document.find("reactions"); reactions != document.end() && reactions->is_array()) {
    // (fr, fz, 0) at constrained nodes, 0 elsewhere (results written before reactions have none).
    std::unordered_map<int, std::size_t> point_of;
    for (std::size_t n = 0; n < nodes.id.size(); ++n) point_of.emplace(nodes.id[n], n);
    std::vector<double> force(3 * nodes.id.size(), 0.0);
    for (const json& r : *reactions) {
      const auto p = point_of.find(r.at("node").get<int>());
      if (p == point_of.end()) continue;
      force[3 * p->second] = r.at("fr").is_number() ? r["fr"].get<double>() : 0.0;
      force[3 * p->second + 1] = r.at("fz").is_number() ? r["fz"].get<double>() : 0.0;
    }
    m.piece.point_data.push_back({"reaction" + vtu_unit_suffix(document, "force"), 3, std::move(force)});
  }
  // Plane models name their components x, y (the result's r, z) and z out of the plane; axisymmetric
  // ones keep the cylindrical names (docs/vtu.md).
  const bool plane = document.value("analysis", std::string()).starts_with("plane");
  const auto named = [plane](const char* key) -> std::string {
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 10> in_plane{{
        {"sigma_r", "sigma_x"}, {"sigma_z", "sigma_y"}, {"tau_rz", "tau_xy"}, {"sigma_theta", "sigma_z"},
        {"eps_r", "eps_x"}, {"eps_z", "eps_y"}, {"gamma_rz", "gamma_xy"}, {"eps_theta", "eps_z"},
        {"q_r", "q_x"}, {"q_z", "q_y"}}};
    if (plane) {
      for (const auto& [cylindrical, planar] : in_plane) {
        if (cylindrical == key) return std::string(planar);
      }
    }
    return key;
  };
  add_contact_point_data(document, nodes, stress, length, m.piece.point_data);
  // The recovered nodal stresses (docs/recovery.md), named "recovered_" and the component (plane or
  // cylindrical as the cells' stresses).
  if (std::any_of(nodes.stress[0].begin(), nodes.stress[0].end(), [](double v) { return !std::isnan(v); })) {
    const std::array<const char*, 5> keys{"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective"};
    for (std::size_t k = 0; k < keys.size(); ++k) {
      // 0 at a node of no solid element, as a cell's missing value (VTK's ASCII reader reads no "nan").
      std::vector<double> v = nodes.stress[k];
      for (double& x : v) x = std::isnan(x) ? 0.0 : x;
      m.piece.point_data.push_back({"recovered_" + named(keys[k]) + stress, 1, std::move(v)});
    }
  }

  // ---- Cell data: element-only values (0 on gaps) and gap-only values (0 on solids), by their
  // document keys.
  std::vector<VtuArray>& cells = m.piece.cell_data;
  const std::size_t solids = m.solids->size();
  const auto solid_values = [&](const std::string& name, const char* key) {
    std::vector<double> v = solid_column(result, key);
    v.resize(m.cells(), 0.0);
    cells.push_back({name, 1, std::move(v)});
  };
  const auto solid_flags = [&](const std::string& name, const char* key, std::int32_t on_gaps) {
    const std::vector<double>& column = solid_column(result, key);
    std::vector<std::int32_t> v;
    v.reserve(m.cells());
    for (const double x : column) v.push_back(x != 0.0 ? 1 : 0);
    v.resize(m.cells(), on_gaps);
    cells.push_back({name, 1, std::move(v)});
  };
  const auto gap_values = [&](const std::string& name, const auto& value) {
    std::vector<double> v(solids, 0.0);
    for (const json* g : m.gaps) v.push_back(value(*g));
    cells.push_back({name, 1, std::move(v)});
  };
  const auto gap_ints = [&](const std::string& name, const auto& value) {
    std::vector<std::int32_t> v(solids, -1);
    for (const json* g : m.gaps) v.push_back(value(*g));
    cells.push_back({name, 1, std::move(v)});
  };
  const auto gap_member = [](const char* key) { return [key](const json& g) { return g.at(key).get<double>(); }; };
  cells = id_arrays(m);
  {
    std::vector<std::int32_t> material(m.solids->material.begin(), m.solids->material.end());
    material.resize(m.cells(), 0);
    cells.push_back({"material", 1, std::move(material)});
  }
  for (const char* key : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "sigma_1", "sigma_2"}) {
    solid_values(named(key) + stress, key);
  }
  solid_values("principal_angle", "angle");
  m.piece.active_cell_scalars = "effective" + stress;
  solid_values(m.piece.active_cell_scalars, "effective");
  for (const char* key : {"eps_r", "eps_z", "gamma_rz", "eps_theta"}) solid_values(named(key), key);
  // Thermal runs: the element heat flux (power / area; the result has it on every solid or none).
  if (const auto q = std::find(result.element_keys.begin(), result.element_keys.end(), "q_r");
      m.solids->size() > 0 && q != result.element_keys.end() &&
      m.solids->first_missing[static_cast<std::size_t>(q - result.element_keys.begin())] != std::size_t{0}) {
    for (const char* key : {"q_r", "q_z"}) solid_values(named(key), key);
  }
  // The estimated error in the energy norm per element (results with an error estimate).
  if (const auto err = std::find(result.element_keys.begin(), result.element_keys.end(), "error");
      m.solids->size() > 0 && err != result.element_keys.end() &&
      m.solids->first_missing[static_cast<std::size_t>(err - result.element_keys.begin())] != std::size_t{0}) {
    solid_values("error", "error");
  }
  solid_flags("yield", "yield", 0);
  solid_flags("plastic_converged", "plastic_converged", 1);
  if (m.gaps.empty()) return encode_vtu(m.piece, format);  // no gap elements: no all-zero gap arrays
  gap_values("gap_closure", gap_member("closure"));
  gap_values("gap_eps_m", gap_member("eps_m"));
  gap_values("gap_sigma_m" + stress, gap_member("sigma_m"));
  // Results written before contact_pressure was added get it from sigma_m, by the same rule.
  gap_values("gap_contact_pressure" + stress,
             [](const json& g) { return g.value("contact_pressure", std::max(0.0, -g.at("sigma_m").get<double>())); });
  gap_values("gap_modulus" + stress, gap_member("modulus"));
  gap_values("gap_angle", gap_member("angle"));
  gap_ints("gap_state", [](const json& g) { return vtu_gap_state_code(g.at("state").get<std::string>()); });
  gap_ints("gap_converged", [](const json& g) { return g.at("converged").get<bool>() ? 1 : 0; });
  return encode_vtu(m.piece, format);
}

/// One iteration of the series: the mesh, ids and that iteration's gap closures.
std::string iteration_document(const ResultArrays& result, const json& closures, int iteration, VtuFormat format) {
  Mesh m = read_mesh(result);
  m.piece.comment += ", iteration " + std::to_string(iteration);
  m.piece.cell_data = id_arrays(m);
  std::vector<double> closure(m.solids->size(), 0.0);
  for (std::size_t g = 0; g < m.gaps.size(); ++g) closure.push_back(closures.at(g).get<double>());
  m.piece.active_cell_scalars = "gap_closure";
  m.piece.cell_data.push_back({"gap_closure", 1, std::move(closure)});
  return encode_vtu(m.piece, format);
}

template <typename F>
auto malformed_is_invalid(F&& f) {
  try {
    return f();
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("malformed result document: ") + e.what());
  }
}

/// A tree as the arrays the writer reads (tests and small in-memory documents).
ResultArrays arrays_of(const json& result) {
  try {
    return read_result_arrays(result.dump(), vtu_result_selection());
  } catch (const ResultTextError& e) {  // a tree always dumps as JSON; a nan or inf dumps as null
    throw std::invalid_argument(std::string("malformed result document: ") + e.what());
  }
}

}  // namespace

std::string result_to_vtu(const ResultArrays& result, VtuFormat format) {
  return malformed_is_invalid([&] { return vtu_document(result, format); });
}

std::string result_to_vtu(const json& result, VtuFormat format) { return result_to_vtu(arrays_of(result), format); }

void write_vtu_collection(const json& document, const std::string& stem,
                          const std::function<std::string()>& whole,
                          const std::function<std::string(const json& closures, int iteration)>& iteration_file,
                          const std::function<void(const std::string&, const std::string&)>& write) {
  malformed_is_invalid([&] {
    const std::size_t gaps = document.contains("gaps") ? document.at("gaps").size() : 0;
    std::vector<const json*> rows;
    if (document.contains("history")) {
      for (const json& row : document.at("history")) {
        if (gaps > 0 && row.contains("gap_closures") && row.at("gap_closures").size() == gaps) rows.push_back(&row);
      }
    }
    // The base name the .pvd refers to: the files sit beside it.
    const std::size_t slash = stem.find_last_of('/');
    const std::string base = slash == std::string::npos ? stem : stem.substr(slash + 1);
    std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                      "  <Collection>\n";
    const auto entry = [&](int step, const std::string& file) {
      pvd += "    <DataSet timestep=\"" + std::to_string(step) + "\" part=\"0\" file=\"" + file + "\"/>\n";
    };
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const int iteration = rows[k]->at("iteration").get<int>();
      char suffix[32];
      std::snprintf(suffix, sizeof suffix, "_iter%04d.vtu", iteration);
      const bool last = k + 1 == rows.size();
      write(stem + suffix, last ? whole() : iteration_file(rows[k]->at("gap_closures"), iteration));
      entry(iteration, base + suffix);
    }
    if (rows.empty()) {
      write(stem + ".vtu", whole());
      entry(document.value("iterations", 0), base + ".vtu");
    }
    pvd += "  </Collection>\n</VTKFile>\n";
    write(stem + ".pvd", pvd);
    return 0;
  });
}

void write_vtu_series(const ResultArrays& result, const std::string& stem, VtuFormat format,
                      const std::function<void(const std::string&, const std::string&)>& write) {
  write_vtu_collection(
      result.document, stem, [&] { return vtu_document(result, format); },
      [&](const json& closures, int iteration) { return iteration_document(result, closures, iteration, format); },
      write);
}

void write_vtu_series(const json& result, const std::string& stem, VtuFormat format,
                      const std::function<void(const std::string& file, const std::string& bytes)>& write) {
  write_vtu_series(arrays_of(result), stem, format, write);
}

}  // namespace saasgaps::io
