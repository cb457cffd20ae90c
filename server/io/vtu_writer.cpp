#include "io/vtu_writer.hpp"

#include <cstdio>
#include <map>
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

namespace {

constexpr std::uint8_t vtk_triangle = 5;
constexpr std::uint8_t vtk_quad = 9;

/// A result's cell: a solid element or a gap element, with its JSON.
struct Cell {
  const json* data;
  bool gap;
};

/// The mesh of a result: nodes, cells (solids then gaps) and the piece's geometry arrays.
struct Mesh {
  const json* nodes = nullptr;
  std::vector<Cell> cells;
  VtuPiece piece;
};

Mesh read_mesh(const json& result) {
  if (result.value("status", "") == "failed") {
    throw std::invalid_argument("the run failed, so the result has no mesh to export: " + result.value("message", ""));
  }
  Mesh m;
  m.nodes = &result.at("nodes");
  const json& nodes = *m.nodes;
  if (nodes.empty() || !nodes.at(0).contains("r")) {
    throw std::invalid_argument("the result document has no node coordinates (nodes[].r, .z): solve the model again");
  }
  std::unordered_map<int, std::int64_t> index;
  for (std::size_t n = 0; n < nodes.size(); ++n) index.emplace(nodes[n].at("id").get<int>(), static_cast<std::int64_t>(n));
  for (const json& e : result.at("elements")) m.cells.push_back({&e, false});
  if (result.contains("gaps")) {
    for (const json& g : result.at("gaps")) m.cells.push_back({&g, true});  // pointers into result: no copy
  }
  m.piece.points = nodes.size();
  m.piece.cells = m.cells.size();
  m.piece.comment = "SAASGAPS result: " + result.value("title", "") + " (" + result.value("analysis", "") + ", " +
                    result.value("status", "") + ")";
  std::vector<double> xyz;
  for (const json& n : nodes) {
    xyz.insert(xyz.end(), {n.at("r").get<double>(), n.at("z").get<double>(), 0.0});
  }
  m.piece.coordinates = {"Points", 3, std::move(xyz)};
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  for (const Cell& c : m.cells) {
    const json& ids = c.data->at("nodes");
    if (ids.size() != 3 && ids.size() != 4) {
      throw std::invalid_argument("element " + c.data->at("id").dump() + " has " + std::to_string(ids.size()) +
                                  " nodes; 3 or 4 expected");
    }
    for (const json& id : ids) {
      const auto found = index.find(id.get<int>());
      if (found == index.end()) {
        throw std::invalid_argument("element " + c.data->at("id").dump() + " refers to node " + id.dump() +
                                    ", which is not in the result's nodes");
      }
      connectivity.push_back(found->second);
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(ids.size() == 4 ? vtk_quad : vtk_triangle);
  }
  m.piece.connectivity = {"connectivity", 1, std::move(connectivity)};
  m.piece.offsets = {"offsets", 1, std::move(offsets)};
  m.piece.types = {"types", 1, std::move(types)};
  return m;
}

/// " [psi]" when the result names the unit of that kind ("stress", "length", "temperature").
std::string unit_suffix(const json& result, const char* kind) {
  const auto units = result.find("units");
  if (units == result.end() || !units->is_object()) return "";
  const std::string name = units->value(kind, "");
  return name.empty() ? "" : " [" + name + "]";
}

std::vector<VtuArray> id_arrays(const Mesh& m) {
  std::vector<std::int32_t> ids, gap;
  for (const Cell& c : m.cells) {
    ids.push_back(c.data->at("id").get<std::int32_t>());
    gap.push_back(c.gap ? 1 : 0);
  }
  return {{"element_id", 1, std::move(ids)}, {"is_gap", 1, std::move(gap)}};
}

/// The contact_* point arrays (see the header): each point of result `contact` on the node at its
/// (r, z), which is where the solver puts it (a side-A node's reference position, the same double).
void add_contact_point_data(const json& result, const json& nodes, const std::string& stress, const std::string& length,
                            std::vector<VtuArray>& point_data) {
  const auto contact = result.find("contact");
  if (contact == result.end() || !contact->is_array() || contact->empty()) return;
  std::map<std::pair<double, double>, std::size_t> at;
  for (std::size_t n = 0; n < nodes.size(); ++n) at.emplace(std::pair{nodes[n].at("r").get<double>(), nodes[n].at("z").get<double>()}, n);
  std::vector<double> pressure(nodes.size(), 0.0), gap(nodes.size(), 0.0), shear(nodes.size(), 0.0), slip(nodes.size(), 0.0);
  std::vector<std::int32_t> state(nodes.size(), -1), pair_number(nodes.size(), 0);
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

std::string vtu_document(const json& result, VtuFormat format) {
  Mesh m = read_mesh(result);
  const json& nodes = *m.nodes;
  const std::string stress = unit_suffix(result, "stress"), length = unit_suffix(result, "length"),
                    temperature = unit_suffix(result, "temperature");

  // ---- Point data.
  std::vector<double> displacement, temperatures;
  std::vector<std::int32_t> node_ids;
  for (const json& n : nodes) {
    displacement.insert(displacement.end(), {n.at("u_r").get<double>(), n.at("u_z").get<double>(), 0.0});
    temperatures.push_back(n.value("T", 0.0));
    node_ids.push_back(n.at("id").get<std::int32_t>());
  }
  m.piece.active_vectors = "displacement" + length;
  m.piece.active_scalars = "temperature" + temperature;
  m.piece.point_data = {{m.piece.active_vectors, 3, std::move(displacement)},
                        {m.piece.active_scalars, 1, std::move(temperatures)},
                        {"node_id", 1, std::move(node_ids)}};
  add_contact_point_data(result, nodes, stress, length, m.piece.point_data);

  // ---- Cell data: element-only values (0 on gaps) and gap-only values (0 on solids), by their
  // document keys.
  std::vector<VtuArray>& cells = m.piece.cell_data;
  const auto ints = [&](const std::string& name, const auto& value) {
    std::vector<std::int32_t> v;
    for (const Cell& c : m.cells) v.push_back(value(c));
    cells.push_back({name, 1, std::move(v)});
  };
  const auto reals = [&](const std::string& name, const char* key, bool on_gaps) {
    std::vector<double> v;
    for (const Cell& c : m.cells) v.push_back(c.gap == on_gaps ? c.data->at(key).get<double>() : 0.0);
    cells.push_back({name, 1, std::move(v)});
  };
  cells = id_arrays(m);
  ints("material", [](const Cell& c) { return c.gap ? 0 : c.data->value("material", 0); });
  for (const char* key : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "sigma_1", "sigma_2"}) {
    reals(key + stress, key, false);
  }
  reals("principal_angle", "angle", false);
  m.piece.active_cell_scalars = "effective" + stress;
  reals(m.piece.active_cell_scalars, "effective", false);
  for (const char* key : {"eps_r", "eps_z", "gamma_rz", "eps_theta"}) reals(key, key, false);
  ints("yield", [](const Cell& c) { return !c.gap && c.data->at("yield").get<bool>() ? 1 : 0; });
  ints("plastic_converged", [](const Cell& c) { return c.gap || c.data->at("plastic_converged").get<bool>() ? 1 : 0; });
  reals("gap_closure", "closure", true);
  reals("gap_eps_m", "eps_m", true);
  reals("gap_sigma_m" + stress, "sigma_m", true);
  {
    // Results written before contact_pressure was added get it from sigma_m, by the same rule.
    std::vector<double> v;
    for (const Cell& c : m.cells) {
      v.push_back(c.gap ? c.data->value("contact_pressure", std::max(0.0, -c.data->at("sigma_m").get<double>())) : 0.0);
    }
    cells.push_back({"gap_contact_pressure" + stress, 1, std::move(v)});
  }
  reals("gap_modulus" + stress, "modulus", true);
  reals("gap_angle", "angle", true);
  ints("gap_state", [](const Cell& c) { return c.gap ? vtu_gap_state_code(c.data->at("state").get<std::string>()) : -1; });
  ints("gap_converged", [](const Cell& c) { return c.gap ? (c.data->at("converged").get<bool>() ? 1 : 0) : -1; });
  return encode_vtu(m.piece, format);
}

/// One iteration of the series: the mesh, ids and that iteration's gap closures.
std::string iteration_document(const json& result, const json& closures, int iteration, VtuFormat format) {
  Mesh m = read_mesh(result);
  m.piece.comment += ", iteration " + std::to_string(iteration);
  m.piece.cell_data = id_arrays(m);
  std::vector<double> closure;
  std::size_t g = 0;
  for (const Cell& c : m.cells) closure.push_back(c.gap ? closures.at(g++).get<double>() : 0.0);
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

}  // namespace

std::string result_to_vtu(const json& result, VtuFormat format) {
  return malformed_is_invalid([&] { return vtu_document(result, format); });
}

void write_vtu_series(const json& result, const std::string& stem, VtuFormat format,
                      const std::function<void(const std::string&, const std::string&)>& write) {
  malformed_is_invalid([&] {
    const std::size_t gaps = result.contains("gaps") ? result.at("gaps").size() : 0;
    std::vector<const json*> rows;
    if (result.contains("history")) {
      for (const json& row : result.at("history")) {
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
      write(stem + suffix,
            last ? vtu_document(result, format) : iteration_document(result, rows[k]->at("gap_closures"), iteration, format));
      entry(iteration, base + suffix);
    }
    if (rows.empty()) {
      write(stem + ".vtu", vtu_document(result, format));
      entry(result.value("iterations", 0), base + ".vtu");
    }
    pvd += "  </Collection>\n</VTKFile>\n";
    write(stem + ".pvd", pvd);
    return 0;
  });
}

}  // namespace saasgaps::io
