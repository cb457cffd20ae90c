// The VTU writer as it was before the stored-result reader (issue 23): a tree of the result,
// each cell read from its JSON. Kept as the reference the typed writer is compared with
// (plot_reader_test), as tests/io/results/result_tree_reference.cpp keeps the tree result writer.
#include "plot/vtu_tree_reference.hpp"

#include "io/results/vtu_writer.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace saasgaps::io::reference {

using nlohmann::json;

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

/// The contact point arrays (io/results/vtu_writer.hpp names them): every point of every pair of result
/// `contact` written onto the node at its (r, z), a side-A node's reference position, found by a
/// scan of the nodes (the first node there); a node on side A of two pairs keeps the later pair's.
/// Nodes no point lands on hold 0, state -1 and pair 0.
void add_contact_arrays(const json& result, const json& nodes, std::vector<VtuArray>& point_data) {
  const auto contact = result.find("contact");
  if (contact == result.end() || !contact->is_array() || contact->empty()) return;
  struct Landed {
    double pressure = 0.0, gap = 0.0, shear = 0.0, slip = 0.0;
    std::int32_t state = -1, pair = 0;
  };
  std::vector<Landed> at(nodes.size());
  std::int32_t pair = 0;
  for (const json& entry : *contact) {
    ++pair;
    for (const json& point : entry.at("points")) {
      const double r = point.at("r").get<double>(), z = point.at("z").get<double>();
      std::size_t n = 0;
      while (n < nodes.size() && !(nodes[n].at("r").get<double>() == r && nodes[n].at("z").get<double>() == z)) ++n;
      if (n == nodes.size()) {
        throw std::invalid_argument("contact pair " + std::to_string(pair) + ": no node at the point (" + json(r).dump() +
                                    ", " + json(z).dump() + ")");
      }
      static const std::vector<std::string> states = {"open", "stick", "slip"};
      const auto state = std::find(states.begin(), states.end(), point.at("state").get<std::string>());
      if (state == states.end()) throw std::invalid_argument("contact state " + point.at("state").dump() + " is unknown");
      at[n] = {point.at("pressure").get<double>(),
               point.at("gap").get<double>(),
               point.contains("shear") ? point["shear"].get<double>() : 0.0,
               point.contains("slip") ? point["slip"].get<double>() : 0.0,
               static_cast<std::int32_t>(state - states.begin()),
               pair};
    }
  }
  const std::string stress = vtu_unit_suffix(result, "stress"), length = vtu_unit_suffix(result, "length");
  const auto reals = [&](const std::string& name, double Landed::*member) {
    std::vector<double> v;
    for (const Landed& l : at) v.push_back(l.*member);
    point_data.push_back({name, 1, std::move(v)});
  };
  const auto ints = [&](const std::string& name, std::int32_t Landed::*member) {
    std::vector<std::int32_t> v;
    for (const Landed& l : at) v.push_back(l.*member);
    point_data.push_back({name, 1, std::move(v)});
  };
  reals("contact_pressure" + stress, &Landed::pressure);
  reals("contact_gap" + length, &Landed::gap);
  reals("contact_shear" + stress, &Landed::shear);
  reals("contact_slip" + length, &Landed::slip);
  ints("contact_state", &Landed::state);
  ints("contact_pair", &Landed::pair);
}

std::vector<VtuArray> id_arrays(const Mesh& m) {
  std::vector<std::int32_t> ids, gap;
  for (const Cell& c : m.cells) {
    ids.push_back(c.data->at("id").get<std::int32_t>());
    gap.push_back(c.gap ? 1 : 0);
  }
  return {{"element_id", 1, std::move(ids)}, {"is_gap", 1, std::move(gap)}};
}

std::string vtu_document(const json& result, VtuFormat format) {
  Mesh m = read_mesh(result);
  const json& nodes = *m.nodes;
  const std::string stress = vtu_unit_suffix(result, "stress"), length = vtu_unit_suffix(result, "length"),
                    temperature = vtu_unit_suffix(result, "temperature");

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
  if (const auto reactions = result.find("reactions"); reactions != result.end() && reactions->is_array()) {
    // (fr, fz, 0) at constrained nodes, 0 elsewhere (results written before reactions have none).
    std::unordered_map<int, std::size_t> point_of;
    for (std::size_t n = 0; n < m.nodes->size(); ++n) point_of.emplace((*m.nodes)[n].at("id").get<int>(), n);
    std::vector<double> force(3 * m.nodes->size(), 0.0);
    for (const json& r : *reactions) {
      const auto p = point_of.find(r.at("node").get<int>());
      if (p == point_of.end()) continue;
      force[3 * p->second] = r.at("fr").is_number() ? r["fr"].get<double>() : 0.0;
      force[3 * p->second + 1] = r.at("fz").is_number() ? r["fz"].get<double>() : 0.0;
    }
    m.piece.point_data.push_back({"reaction" + vtu_unit_suffix(result, "force"), 3, std::move(force)});
  }
  // Plane models name their components in the plane's axes (x, y = r, z; z out of the plane).
  const bool plane = result.value("analysis", std::string()).starts_with("plane");
  const auto named = [plane](const std::string& key) -> std::string {
    static const std::map<std::string, std::string> in_plane{
        {"sigma_r", "sigma_x"}, {"sigma_z", "sigma_y"}, {"tau_rz", "tau_xy"}, {"sigma_theta", "sigma_z"},
        {"eps_r", "eps_x"},     {"eps_z", "eps_y"},     {"gamma_rz", "gamma_xy"}, {"eps_theta", "eps_z"},
        {"q_r", "q_x"},         {"q_z", "q_y"}};
    const auto found = in_plane.find(key);
    return plane && found != in_plane.end() ? found->second : key;
  };
  // Contact surfaces: their points on side A's nodes.
  add_contact_arrays(result, nodes, m.piece.point_data);
  // The recovered nodal stresses, 0 at a node of no solid element.
  if (std::any_of(nodes.begin(), nodes.end(), [](const json& n) { return n.contains("sigma_r"); })) {
    for (const char* key : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective"}) {
      std::vector<double> v;
      for (const json& n : nodes) v.push_back(n.value(key, 0.0));
      m.piece.point_data.push_back({"recovered_" + named(key) + stress, 1, std::move(v)});
    }
  }

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
    reals(named(key) + stress, key, false);
  }
  reals("principal_angle", "angle", false);
  m.piece.active_cell_scalars = "effective" + stress;
  reals(m.piece.active_cell_scalars, "effective", false);
  for (const char* key : {"eps_r", "eps_z", "gamma_rz", "eps_theta"}) reals(named(key), key, false);
  // Thermal runs: the element heat flux (the result has it on every solid or none).
  if (std::any_of(m.cells.begin(), m.cells.end(), [](const Cell& c) { return !c.gap && c.data->contains("q_r"); })) {
    for (const char* key : {"q_r", "q_z"}) reals(named(key), key, false);
  }
  if (std::any_of(m.cells.begin(), m.cells.end(), [](const Cell& c) { return !c.gap && c.data->contains("error"); })) {
    reals("error", "error", false);
  }
  ints("yield", [](const Cell& c) { return !c.gap && c.data->at("yield").get<bool>() ? 1 : 0; });
  ints("plastic_converged", [](const Cell& c) { return c.gap || c.data->at("plastic_converged").get<bool>() ? 1 : 0; });
  // No gap elements: no gap arrays.
  if (std::none_of(m.cells.begin(), m.cells.end(), [](const Cell& c) { return c.gap; })) return encode_vtu(m.piece, format);
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
  // The layout of the collection is the writer's; what the reference checks is each file.
  write_vtu_collection(
      result, stem, [&] { return malformed_is_invalid([&] { return vtu_document(result, format); }); },
      [&](const json& closures, int iteration) {
        return malformed_is_invalid([&] { return iteration_document(result, closures, iteration, format); });
      },
      write);
}

}  // namespace saasgaps::io::reference
