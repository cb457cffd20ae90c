#include "support/calculix_run.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace saasgaps::testing {
namespace {

using nlohmann::json;

std::string element_type(const json& model, const json& element) {
  const std::string analysis = model.at("analysis").at("type");
  if (analysis != "plane_stress" && analysis != "plane_strain") {
    throw std::invalid_argument("calculix_deck: analysis " + analysis + " is not converted");
  }
  const char plane = analysis == "plane_stress" ? 'S' : 'E';
  const std::size_t n = element.at("nodes").size();
  const std::string type = element.value("type", n == 8 ? "quad8" : n == 6 ? "tri6" : "");
  const bool reduced = element.value("integration", "full") == "reduced";
  if (type == "quad8") return std::string("CP") + plane + (reduced ? "8R" : "8");
  if (type == "tri6") return std::string("CP") + plane + "6";
  throw std::invalid_argument("calculix_deck: element type " + type + " is not converted");
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::filesystem::path fresh_folder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "saasgaps-ccx-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("run_calculix: no temporary folder");
  return pattern;
}

bool ccx_installed() { return std::system("command -v ccx >/dev/null 2>&1") == 0; }

/// The rows of a *NODE PRINT block in ccx's .dat: "node v1 v2 ..." after a header naming `what`.
std::map<int, std::vector<double>> print_block(const std::string& dat, const std::string& what) {
  std::map<int, std::vector<double>> rows;
  std::istringstream in(dat);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.find(what) != std::string::npos && line.find("for set") != std::string::npos) {
      inside = true;
      continue;
    }
    std::istringstream words(line);
    int node = 0;
    if (!(words >> node)) {
      if (inside && !rows.empty() && line.find_first_not_of(' ') != std::string::npos) break;
      continue;
    }
    if (!inside) continue;
    std::vector<double> values;
    double v = 0.0;
    while (words >> v) values.push_back(v);
    rows[node] = values;
  }
  return rows;
}

/// The nodal values of the result block `name` (" -4  STRESS ...") of ccx's .frd file: rows
/// " -1" + node (10 columns) + values of 12 columns each, until " -3".
std::map<int, std::vector<double>> frd_block(const std::string& frd, const std::string& name) {
  std::map<int, std::vector<double>> rows;
  std::istringstream in(frd);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind(" -4  " + name, 0) == 0) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.rfind(" -3", 0) == 0) break;
    if (line.rfind(" -1", 0) != 0) continue;
    const int node = std::stoi(line.substr(3, 10));
    std::vector<double> values;
    for (std::size_t at = 13; at + 12 <= line.size(); at += 12) values.push_back(std::stod(line.substr(at, 12)));
    rows[node] = values;
  }
  return rows;
}

/// The element and face (CalculiX's P1..P4 / P1..P3: the edge from corner k to corner k + 1)
/// of the edge a-b, as the model's pressures name it.
std::pair<int, int> face_of(const json& model, int a, int b) {
  for (const json& element : model.at("elements")) {
    const std::vector<int> nodes = element.at("nodes");
    const std::size_t corners = nodes.size() == 6 || nodes.size() == 3 ? 3 : 4;
    for (std::size_t k = 0; k < corners; ++k) {
      const int from = nodes[k];
      const int to = nodes[(k + 1) % corners];
      if ((from == a && to == b) || (from == b && to == a)) return {element.at("id").get<int>(), static_cast<int>(k) + 1};
    }
  }
  throw std::invalid_argument("calculix_deck: no element has the edge " + std::to_string(a) + "-" + std::to_string(b));
}

}  // namespace

std::string calculix_deck(const json& model) {
  std::ostringstream deck;
  deck << "*HEADING\nsaasgaps side-by-side\n*NODE, NSET=NALL\n";
  for (const json& node : model.at("nodes")) {
    deck << node.at("id").get<int>() << ", " << number(node.at("r")) << ", " << number(node.at("z")) << "\n";
  }
  std::map<std::string, std::vector<const json*>> by_type;
  for (const json& element : model.at("elements")) by_type[element_type(model, element)].push_back(&element);
  for (const auto& [type, elements] : by_type) {
    deck << "*ELEMENT, TYPE=" << type << ", ELSET=SOLID\n";
    for (const json* element : elements) {
      deck << element->at("id").get<int>();
      for (const json& n : element->at("nodes")) deck << ", " << n.get<int>();
      deck << "\n";
    }
  }
  const json& material = model.at("materials").at(0);
  if (material.value("elastic", "isotropic") != "isotropic") {
    throw std::invalid_argument("calculix_deck: only isotropic materials are converted");
  }
  const json& row = material.at("table").at(0);
  deck << "*MATERIAL, NAME=M\n*ELASTIC\n" << number(row.at("E")) << ", " << number(row.at("nu")) << "\n";
  deck << "*SOLID SECTION, ELSET=SOLID, MATERIAL=M\n" << number(model.at("analysis").value("thickness", 1.0)) << "\n";
  deck << "*BOUNDARY\n";
  for (const json& c : model.at("constraints")) {
    const int node = c.at("node");
    if (c.contains("r")) deck << node << ", 1, 1, " << number(c.at("r")) << "\n";
    if (c.contains("z")) deck << node << ", 2, 2, " << number(c.at("z")) << "\n";
  }
  deck << "*STEP\n*STATIC\n";
  if (model.contains("loads") && model.at("loads").contains("nodal_forces")) {
    deck << "*CLOAD\n";
    for (const json& f : model.at("loads").at("nodal_forces")) {
      const int node = f.at("node");
      if (f.contains("fr")) deck << node << ", 1, " << number(f.at("fr")) << "\n";
      if (f.contains("fz")) deck << node << ", 2, " << number(f.at("fz")) << "\n";
    }
  }
  if (model.contains("loads") && model.at("loads").contains("pressures")) {
    deck << "*DLOAD\n";
    for (const json& p : model.at("loads").at("pressures")) {
      if (p.value("shear", 0.0) != 0.0) throw std::invalid_argument("calculix_deck: shear tractions are not converted");
      const std::vector<int> edge = p.at("nodes");
      const auto [element, face] = face_of(model, edge.front(), edge.back());
      // Both programs: a positive pressure pushes into the element.
      deck << element << ", P" << face << ", " << number(p.at("normal")) << "\n";
    }
  }
  // Displacements printed to the .dat; nodal stresses (extrapolated and averaged) only to the .frd.
  deck << "*NODE PRINT, NSET=NALL\nU\n*NODE FILE\nS\n*END STEP\n";
  return deck.str();
}

std::optional<CalculixNodes> run_calculix(const json& model) {
  if (!ccx_installed()) return std::nullopt;
  const std::string deck = calculix_deck(model);
  const std::filesystem::path folder = fresh_folder();
  std::ofstream(folder / "model.inp") << deck;
  const std::string command = "cd '" + folder.string() + "' && OMP_NUM_THREADS=1 ccx model >ccx.log 2>&1";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("ccx failed: see " + (folder / "ccx.log").string());
  std::ifstream in(folder / "model.dat");
  const std::string dat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CalculixNodes nodes;
  for (const auto& [node, v] : print_block(dat, "displacements")) {
    if (v.size() >= 2) nodes.u[node] = {v[0], v[1]};
  }
  std::ifstream frd_in(folder / "model.frd");
  const std::string frd((std::istreambuf_iterator<char>(frd_in)), std::istreambuf_iterator<char>());
  // SXX SYY SZZ SXY SYZ SZX.
  for (const auto& [node, v] : frd_block(frd, "STRESS")) {
    if (v.size() >= 4) nodes.sigma[node] = {v[0], v[1], v[2], v[3]};
  }
  if (nodes.u.empty()) throw std::runtime_error("ccx printed no displacements: see " + folder.string());
  std::filesystem::remove_all(folder);
  return nodes;
}

}  // namespace saasgaps::testing
