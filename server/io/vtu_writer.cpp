#include "io/vtu_writer.hpp"

#include <charconv>
#include <functional>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace saasgaps::io {

using nlohmann::json;

namespace {

constexpr int vtk_triangle = 5;
constexpr int vtk_quad = 9;

/// Shortest text that reads back as the same double (std::to_chars round trip).
void append_number(std::string& out, double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  out.append(text, error == std::errc() ? end : text);
}

void append_number(std::string& out, long long value) {
  char text[24];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  out.append(text, error == std::errc() ? end : text);
}

/// <DataArray> of one value per item, from value(i) for i < count.
template <typename Value>
void data_array(std::string& out, const char* type, const std::string& name, std::size_t count,
                const std::function<Value(std::size_t)>& value) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"" + name + "\" format=\"ascii\">\n          ";
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) out += (i % 8 == 0) ? "\n          " : " ";
    append_number(out, value(i));
  }
  out += "\n        </DataArray>\n";
}

/// A result's cell: a solid element or a gap element, with its JSON.
struct Cell {
  const json* data;
  bool gap;
};

/// XML comments may not hold "--".
std::string comment_text(std::string s) {
  for (std::size_t at = s.find("--"); at != std::string::npos; at = s.find("--")) s.erase(at, 1);
  return s;
}

}  // namespace

int vtu_gap_state_code(const std::string& state) {
  if (state == "open") return 0;
  if (state == "partial") return 1;
  if (state == "closed") return 2;
  if (state == "overclosed") return 3;
  throw std::invalid_argument("unknown gap state '" + state + "'");
}

namespace {

std::string vtu_document(const json& result) {
  if (result.value("status", "") == "failed") {
    throw std::invalid_argument("the run failed, so the result has no mesh to export: " + result.value("message", ""));
  }
  const json& nodes = result.at("nodes");
  if (nodes.empty() || !nodes.at(0).contains("r")) {
    throw std::invalid_argument("the result document has no node coordinates (nodes[].r, .z): solve the model again");
  }
  std::unordered_map<int, long long> index;
  for (std::size_t n = 0; n < nodes.size(); ++n) index.emplace(nodes[n].at("id").get<int>(), static_cast<long long>(n));
  std::vector<Cell> cells;
  for (const json& e : result.at("elements")) cells.push_back({&e, false});
  if (result.contains("gaps")) {
    for (const json& g : result.at("gaps")) cells.push_back({&g, true});  // pointers into result: no copy
  }

  std::string out;
  out.reserve(256 * (nodes.size() + cells.size()));
  out += "<?xml version=\"1.0\"?>\n";
  out += "<!-- SAASGAPS result: " + comment_text(result.value("title", "")) + " (" +
         comment_text(result.value("analysis", "")) + ", " + comment_text(result.value("status", "")) + ") -->\n";
  out += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  out += "  <UnstructuredGrid>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(nodes.size()) + "\" NumberOfCells=\"" +
         std::to_string(cells.size()) + "\">\n";

  // ---- Point data.
  out += "      <PointData Scalars=\"temperature\" Vectors=\"displacement\">\n";
  out += "        <DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const json& n : nodes) {
    out += "          ";
    append_number(out, n.at("u_r").get<double>());
    out += ' ';
    append_number(out, n.at("u_z").get<double>());
    out += " 0\n";
  }
  out += "        </DataArray>\n";
  data_array<double>(out, "Float64", "temperature", nodes.size(), [&](std::size_t i) { return nodes[i].value("T", 0.0); });
  data_array<long long>(out, "Int32", "node_id", nodes.size(),
                        [&](std::size_t i) { return nodes[i].at("id").get<long long>(); });
  out += "      </PointData>\n";

  // ---- Cell data.
  out += "      <CellData Scalars=\"effective\">\n";
  const std::size_t count = cells.size();
  const auto ints = [&](const char* name, const std::function<long long(const Cell&)>& value) {
    data_array<long long>(out, "Int32", name, count, [&](std::size_t i) { return value(cells[i]); });
  };
  const auto reals = [&](const char* name, const std::function<double(const Cell&)>& value) {
    data_array<double>(out, "Float64", name, count, [&](std::size_t i) { return value(cells[i]); });
  };
  // Element-only values (0 on gaps) and gap-only values (0 on solids), by their document keys.
  const auto element_real = [&](const char* name, const char* key) {
    reals(name, [key](const Cell& c) { return c.gap ? 0.0 : c.data->at(key).get<double>(); });
  };
  const auto gap_real = [&](const char* name, const char* key) {
    reals(name, [key](const Cell& c) { return c.gap ? c.data->at(key).get<double>() : 0.0; });
  };
  ints("element_id", [](const Cell& c) { return c.data->at("id").get<long long>(); });
  ints("is_gap", [](const Cell& c) { return c.gap ? 1LL : 0LL; });
  ints("material", [](const Cell& c) { return c.gap ? 0LL : c.data->value("material", 0LL); });
  for (const char* key : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "sigma_1", "sigma_2"}) element_real(key, key);
  element_real("principal_angle", "angle");
  element_real("effective", "effective");
  for (const char* key : {"eps_r", "eps_z", "gamma_rz", "eps_theta"}) element_real(key, key);
  ints("yield", [](const Cell& c) { return !c.gap && c.data->at("yield").get<bool>() ? 1LL : 0LL; });
  ints("plastic_converged",
       [](const Cell& c) { return c.gap || c.data->at("plastic_converged").get<bool>() ? 1LL : 0LL; });
  gap_real("gap_closure", "closure");
  gap_real("gap_eps_m", "eps_m");
  gap_real("gap_sigma_m", "sigma_m");
  gap_real("gap_modulus", "modulus");
  gap_real("gap_angle", "angle");
  ints("gap_state",
       [](const Cell& c) { return c.gap ? vtu_gap_state_code(c.data->at("state").get<std::string>()) : -1LL; });
  ints("gap_converged", [](const Cell& c) { return c.gap ? (c.data->at("converged").get<bool>() ? 1LL : 0LL) : -1LL; });
  out += "      </CellData>\n";

  // ---- Geometry.
  out += "      <Points>\n";
  out += "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const json& n : nodes) {
    out += "          ";
    append_number(out, n.at("r").get<double>());
    out += ' ';
    append_number(out, n.at("z").get<double>());
    out += " 0\n";
  }
  out += "        </DataArray>\n";
  out += "      </Points>\n";

  std::vector<long long> connectivity, offsets;
  for (const Cell& c : cells) {
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
    offsets.push_back(static_cast<long long>(connectivity.size()));
  }
  out += "      <Cells>\n";
  data_array<long long>(out, "Int64", "connectivity", connectivity.size(), [&](std::size_t i) { return connectivity[i]; });
  data_array<long long>(out, "Int64", "offsets", offsets.size(), [&](std::size_t i) { return offsets[i]; });
  data_array<long long>(out, "UInt8", "types", cells.size(), [&](std::size_t i) {
    return static_cast<long long>(cells[i].data->at("nodes").size() == 4 ? vtk_quad : vtk_triangle);
  });
  out += "      </Cells>\n";
  out += "    </Piece>\n";
  out += "  </UnstructuredGrid>\n";
  out += "</VTKFile>\n";
  return out;
}

}  // namespace

std::string result_to_vtu(const json& result) {
  try {
    return vtu_document(result);
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("malformed result document: ") + e.what());
  }
}

}  // namespace saasgaps::io
