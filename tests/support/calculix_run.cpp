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
  deck << "*NODE PRINT, NSET=NALL\nU\n*NODE PRINT, NSET=NALL\nS\n*END STEP\n";
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
  // ccx prints sxx syy szz sxy sxz syz.
  for (const auto& [node, v] : print_block(dat, "stresses")) {
    if (v.size() >= 4) nodes.sigma[node] = {v[0], v[1], v[2], v[3]};
  }
  if (nodes.u.empty()) throw std::runtime_error("ccx printed no displacements: see " + folder.string());
  std::filesystem::remove_all(folder);
  return nodes;
}

}  // namespace saasgaps::testing
