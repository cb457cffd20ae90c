// The assembly importer: a model imported from a Gmsh mesh and its physical groups equals the model
// written by hand for the same mesh, and every kind of bad assembly gives one error at the pointer
// of the group, pair or file it concerns.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "io/import/adapt_settings.hpp"
#include "io/import/assembly_reader.hpp"
#include "io/import/gap_generator.hpp"
#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/base/errors.hpp"
#include "solver/gaps/gap_faces.hpp"
#include "solver/thermal/thermal_analysis.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path data_dir = fs::path(SAASGAPS_TEST_DATA_DIR);
const fs::path assemblies_dir = fs::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";

json load(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return json::parse(in);
}

std::string text_of(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A scratch directory per test, holding variants of the test mesh.
class Scratch {
 public:
  Scratch() : dir_(fs::temp_directory_path() / ("saasgaps-import-" + std::to_string(::getpid()) + "-" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::create_directories(dir_);
  }
  ~Scratch() { fs::remove_all(dir_); }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  [[nodiscard]] const fs::path& dir() const { return dir_; }
  fs::path write(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name) << content;
    return dir_ / name;
  }

 private:
  fs::path dir_;
};

/// The test mesh's text with `from` replaced by `to` (once; the text must contain it).
std::string two_blocks_with(const std::string& from, const std::string& to) {
  std::string text = text_of(data_dir / "two_blocks.msh");
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Imports `assembly` (relative files in `dir`) expecting exactly one issue; returns it.
InputIssue single_issue(const json& assembly, const fs::path& dir) {
  try {
    (void)io::import_assembly(assembly, dir);
  } catch (const ModelError& e) {
    EXPECT_EQ(e.issues().size(), 1u) << [&] {
      std::string all;
      for (const InputIssue& i : e.issues()) all += i.pointer + ": " + i.detail + "\n";
      return all;
    }();
    if (!e.issues().empty()) return e.issues().front();
  }
  ADD_FAILURE() << "the import succeeded";
  return {};
}

// ---- the same model, imported and hand-written

std::vector<int> node_ids(const Model& m, std::span<const int> nodes) {
  std::vector<int> ids;
  for (int n : nodes) ids.push_back(m.nodes[static_cast<std::size_t>(n)].id);
  return ids;
}

TEST(AssemblyImport, ImportedMshEqualsTheHandWrittenModel) {
  const Model imported = io::read_model(io::import_assembly(load(data_dir / "two_blocks.assembly.json"), data_dir));
  const Model hand = io::read_model(load(data_dir / "two_blocks.model.json"));

  ASSERT_EQ(imported.nodes.size(), hand.nodes.size());
  for (std::size_t n = 0; n < hand.nodes.size(); ++n) {
    EXPECT_EQ(imported.nodes[n].id, hand.nodes[n].id);
    EXPECT_EQ(imported.nodes[n].r, hand.nodes[n].r);
    EXPECT_EQ(imported.nodes[n].z, hand.nodes[n].z);
  }
  // Element 23 is clockwise in the .msh file: the import lists it counter-clockwise.
  ASSERT_EQ(imported.elements.size(), hand.elements.size());
  for (std::size_t e = 0; e < hand.elements.size(); ++e) {
    const Element& a = imported.elements[e];
    const Element& b = hand.elements[e];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(node_ids(imported, a.node_span()), node_ids(hand, b.node_span())) << "element " << b.id;
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.angle_deg, b.angle_deg);
  }
  ASSERT_TRUE(imported.gaps && hand.gaps);
  ASSERT_EQ(imported.gaps->elements.size(), hand.gaps->elements.size());
  for (std::size_t g = 0; g < hand.gaps->elements.size(); ++g) {
    const GapElement& a = imported.gaps->elements[g];
    const GapElement& b = hand.gaps->elements[g];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(node_ids(imported, a.node_span()), node_ids(hand, b.node_span())) << "gap " << b.id;
    EXPECT_NEAR(a.angle_deg, b.angle_deg, 1e-12);
  }
  EXPECT_EQ(imported.gaps->tensile_schedule, hand.gaps->tensile_schedule);

  const auto constraints = [](const Model& m) {
    std::map<int, std::pair<std::optional<double>, std::optional<double>>> by_node;
    for (const Constraint& c : m.constraints) by_node[m.nodes[static_cast<std::size_t>(c.node)].id] = {c.u_r, c.u_z};
    return by_node;
  };
  EXPECT_EQ(constraints(imported), constraints(hand));

  // Pressures: the same edge of the same owning element, in the same direction, the same tractions.
  const auto pressures = [](const Model& m) {
    std::set<std::tuple<int, int, int, double, double>> edges;
    for (const EdgePressure& p : m.loads.pressures) {
      edges.emplace(m.elements[static_cast<std::size_t>(p.element)].id, m.nodes[static_cast<std::size_t>(p.node_a)].id,
                    m.nodes[static_cast<std::size_t>(p.node_b)].id, p.normal, p.shear);
    }
    return edges;
  };
  EXPECT_EQ(pressures(imported), pressures(hand));
  ASSERT_EQ(imported.loads.nodal_forces.size(), 1u);
  EXPECT_EQ(imported.loads.nodal_forces[0].node, hand.loads.nodal_forces[0].node);
  EXPECT_EQ(imported.loads.nodal_forces[0].f_z, hand.loads.nodal_forces[0].f_z);
  EXPECT_EQ(imported.loads.node_temperature, hand.loads.node_temperature);
  EXPECT_EQ(imported.thickness, hand.thickness);
  EXPECT_EQ(imported.solver.max_iterations, hand.solver.max_iterations);
  EXPECT_EQ(imported.output.watch_elements, hand.output.watch_elements);
  EXPECT_EQ(imported.output.watch_gaps, hand.output.watch_gaps);
}

/// The ring fit from ring-fit.geo against the hand-made ring-shrink-fit-plane-strain.json (written
/// by make_ring_model.py): the same nodes (matched by position), elements, gaps with their angles,
/// constraints and temperatures, although Gmsh numbers them differently.
TEST(AssemblyImport, RingFromGeoEqualsTheHandMadeRing) {
  const Model imported =
      io::read_model(io::import_assembly(load(assemblies_dir / "ring-fit.assembly.json"), assemblies_dir));
  const Model hand = io::read_model(load(fs::path(SAASGAPS_EXAMPLES_DIR) / "ring-shrink-fit-plane-strain.json"));
  ASSERT_EQ(imported.nodes.size(), hand.nodes.size());
  // Hand-made node of each imported node, by position (the hand-made file rounds to 1e-9, and
  // Gmsh places the nodes on the arcs to about 1e-7).
  std::vector<int> to_hand(imported.nodes.size(), -1);
  for (std::size_t n = 0; n < imported.nodes.size(); ++n) {
    const Node& a = imported.nodes[n];
    for (std::size_t h = 0; h < hand.nodes.size(); ++h) {
      if (std::hypot(a.r - hand.nodes[h].r, a.z - hand.nodes[h].z) < 1e-6) to_hand[n] = static_cast<int>(h);
    }
    ASSERT_GE(to_hand[n], 0) << "imported node " << a.id << " at (" << a.r << ", " << a.z << ") has no hand-made twin";
  }
  EXPECT_EQ(std::set<int>(to_hand.begin(), to_hand.end()).size(), hand.nodes.size());
  // A cell as the set of its corners in cyclic order, starting from the smallest.
  const auto cycle = [](std::vector<int> c) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
  };
  const auto mapped = [&](std::span<const int> nodes) {
    std::vector<int> c;
    for (int n : nodes) c.push_back(to_hand[static_cast<std::size_t>(n)]);
    return cycle(c);
  };
  const auto own = [&](std::span<const int> nodes) {
    return cycle(std::vector<int>(nodes.begin(), nodes.end()));
  };
  std::set<std::vector<int>> hand_elements, imported_elements;
  for (const Element& e : hand.elements) hand_elements.insert(own(e.node_span()));
  for (const Element& e : imported.elements) imported_elements.insert(mapped(e.node_span()));
  EXPECT_EQ(imported_elements, hand_elements);

  std::map<std::vector<int>, double> hand_gaps, imported_gaps;
  for (const GapElement& g : hand.gaps->elements) hand_gaps[own(g.node_span())] = g.angle_deg;
  for (const GapElement& g : imported.gaps->elements) imported_gaps[mapped(g.node_span())] = g.angle_deg;
  ASSERT_EQ(imported_gaps.size(), hand_gaps.size());
  for (const auto& [corners, angle] : hand_gaps) {
    const auto found = imported_gaps.find(corners);
    ASSERT_NE(found, imported_gaps.end());
    // Gmsh places the nodes of the two arcs at their angles to about 5e-9 rad; across a gap 750
    // times thinner than it is long that turns the pair direction by up to 2e-4 degrees.
    EXPECT_NEAR(found->second, angle, 1e-3);
  }
  std::map<int, std::pair<std::optional<double>, std::optional<double>>> hand_fixed, imported_fixed;
  for (const Constraint& c : hand.constraints) hand_fixed[c.node] = {c.u_r, c.u_z};
  for (const Constraint& c : imported.constraints) imported_fixed[to_hand[static_cast<std::size_t>(c.node)]] = {c.u_r, c.u_z};
  EXPECT_EQ(imported_fixed, hand_fixed);
  for (std::size_t n = 0; n < imported.nodes.size(); ++n) {
    EXPECT_EQ(imported.loads.node_temperature[n], hand.loads.node_temperature[static_cast<std::size_t>(to_hand[n])]);
  }
}

TEST(AssemblyImport, TemperaturesFromCsvByPositionAndFromVtu) {
  const Scratch scratch;
  fs::copy_file(data_dir / "two_blocks.msh", scratch.dir() / "two_blocks.msh");
  json assembly = load(data_dir / "two_blocks.assembly.json");
  assembly["loads"]["temperatures"] = {{"default", 0.0}, {"file", {{"path", "t.csv"}}}};
  scratch.write("t.csv", "# from a thermal code\nx,y,T\n0,0,10\n1,0,11\n2, 2.01, 12.5\n");
  Model m = io::read_model(io::import_assembly(assembly, scratch.dir()));
  EXPECT_EQ(m.loads.node_temperature[0], 10.0);
  EXPECT_EQ(m.loads.node_temperature[1], 11.0);
  EXPECT_EQ(m.loads.node_temperature[11], 12.5);
  EXPECT_EQ(m.loads.node_temperature[5], 0.0);

  // A VTU point field (the two blocks' nodes, ascii points, base64 Float64 values as VTK writes
  // them: the UInt32 byte count and the data encoded separately).
  scratch.write("t.vtu",
                "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">"
                "<UnstructuredGrid><Piece NumberOfPoints=\"2\" NumberOfCells=\"0\"><Points>"
                "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">1 1 0 2 2.01 0</DataArray>"
                "</Points><PointData><DataArray type=\"Float64\" Name=\"temperature\" format=\"binary\">"
                // 16 bytes, then 300.0 and 400.5 as little-endian doubles
                "EAAAAA==AAAAAADAckAAAAAAAAh5QA==</DataArray></PointData></Piece></UnstructuredGrid></VTKFile>\n");
  assembly["loads"]["temperatures"]["file"] = {{"path", "t.vtu"}, {"field", "temperature"}};
  m = io::read_model(io::import_assembly(assembly, scratch.dir()));
  EXPECT_EQ(m.loads.node_temperature[4], 300.0);   // node 5 at (1, 1)
  EXPECT_EQ(m.loads.node_temperature[11], 400.5);  // node 12 at (2, 2.01)
  EXPECT_EQ(m.loads.node_temperature[0], 0.0);

  // A compressed VTU (ParaView's default) is refused with a message that says how to write it.
  scratch.write("z.vtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\" "
                         "compressor=\"vtkZLibDataCompressor\"><UnstructuredGrid/></VTKFile>\n");
  assembly["loads"]["temperatures"]["file"] = {{"path", "z.vtu"}};
  const InputIssue compressed = single_issue(assembly, scratch.dir());
  EXPECT_EQ(compressed.pointer, "/loads/temperatures/file/path");
  EXPECT_NE(compressed.detail.find("is compressed (vtkZLibDataCompressor); write it uncompressed"), std::string::npos)
      << compressed.detail;

  scratch.write("bad.csv", "node,T\n5,20\n99,30\n");
  assembly["loads"]["temperatures"]["file"] = {{"path", "bad.csv"}};
  const InputIssue issue = single_issue(assembly, scratch.dir());
  EXPECT_EQ(issue.pointer, "/loads/temperatures/file/path");
  EXPECT_NE(issue.detail.find("line 3 (node 99)"), std::string::npos) << issue.detail;
}

// ---- one clear error per defect

/// One value of the test assembly changed, and the one issue it must give.
struct BadValue {
  const char* what;
  const char* at;       ///< pointer of the value changed
  json value;
  const char* pointer;  ///< pointer of the issue
  const char* says;     ///< part of its text
};

TEST(AssemblyImport, GroupsMissingMisspeltOrOfTheWrongDimension) {
  const std::vector<BadValue> cases{
      {"missing group", "/constraints/1/group", "symmetry_plane", "/constraints/1/group",
       "no physical group named \"symmetry_plane\" (its named groups: \"corner\" (dimension 0 (point)), "
       "\"bottom\" (dimension 1 (curve))"},
      {"misspelt group", "/regions/1/group", "uper", "/regions/1/group", "did you mean \"upper\"?"},
      {"surface as a pressure curve", "/loads/pressures/0/group", "upper", "/loads/pressures/0/group",
       "\"upper\" has dimension 2 (surface); a pressure needs a curve (dimension 1)"},
      {"surface as a gap face", "/gaps/pairs/0/faces/1", "upper", "/gaps/pairs/0/faces/1",
       "a gap face needs a curve"},
      {"curve as a nodal force point", "/loads/nodal_forces/0/group", "top", "/loads/nodal_forces/0/group",
       "a nodal force needs points"},
      {"a pass-through value keeps its pointer", "/gaps/initial_modulus", -1.0, "/gaps/initial_modulus", "> 0"},
  };
  for (const BadValue& c : cases) {
    json assembly = load(data_dir / "two_blocks.assembly.json");
    assembly[json::json_pointer(c.at)] = c.value;
    const InputIssue issue = single_issue(assembly, data_dir);
    EXPECT_EQ(issue.pointer, c.pointer) << c.what;
    EXPECT_NE(issue.detail.find(c.says), std::string::npos) << c.what << ": " << issue.detail;
  }
}

TEST(AssemblyImport, StepsNameGroupsAndEveryGroupUsedBecomesANamedSet) {
  json assembly = load(data_dir / "two_blocks.assembly.json");
  assembly["steps"] = json::parse(R"([{"name": "hold", "increments": 2},
      {"name": "lift", "constraints": [{"group": "top", "z": 0.001}],
       "loads": {"pressures": [{"group": "top", "normal": 50.0}]}}])");
  const json model = io::import_assembly(assembly, data_dir);
  // One set per named group used, under its name: points and curves give nodes, curves edges,
  // surfaces elements.
  for (const char* name : {"bottom", "left", "corner", "top", "lower_top", "upper_bottom"}) {
    EXPECT_TRUE(model["sets"]["nodes"].contains(name)) << name;
  }
  EXPECT_TRUE(model["sets"]["edges"].contains("top"));
  EXPECT_FALSE(model["sets"]["edges"].contains("corner"));
  EXPECT_TRUE(model["sets"]["elements"].contains("upper"));
  ASSERT_EQ(model["steps"].size(), 2U);
  EXPECT_EQ(model["steps"][0], (json{{"name", "hold"}, {"increments", 2}}));
  EXPECT_EQ(model["steps"][1]["constraints"][0], (json{{"set", "top"}, {"z", 0.001}}));
  EXPECT_EQ(model["steps"][1]["loads"]["pressures"].size(), model["sets"]["edges"]["top"].size());
  const Model m = io::read_model(model);
  ASSERT_EQ(m.reaction_groups.size(), 1U);
  EXPECT_EQ(m.reaction_groups[0].name, "top");
  EXPECT_EQ(m.reaction_groups[0].nodes.size(), model["sets"]["nodes"]["top"].size());

  // A misspelt group in a step is the step's error, at its pointer.
  assembly["steps"][1]["constraints"][0]["group"] = "tpo";
  const InputIssue issue = single_issue(assembly, data_dir);
  EXPECT_EQ(issue.pointer, "/steps/1/constraints/0/group");
  EXPECT_NE(issue.detail.find("did you mean \"top\"?"), std::string::npos) << issue.detail;
  // A model reader's finding on a step keeps the step's pointer.
  assembly["steps"][1]["constraints"][0]["group"] = "top";
  assembly["steps"][1]["increments"] = 0;
  EXPECT_EQ(single_issue(assembly, data_dir).pointer, "/steps/1/increments");
}

TEST(AssemblyImport, FacesWhoseNodesDoNotFaceEachOther) {
  const Scratch scratch;
  scratch.write("two_blocks.msh", two_blocks_with("8 1 1.01 0", "8 1.4 1.01 0"));
  const InputIssue issue = single_issue(load(data_dir / "two_blocks.assembly.json"), scratch.dir());
  EXPECT_EQ(issue.pointer, "/gaps/pairs/0");
  EXPECT_NE(issue.detail.find("between \"lower_top\" and \"upper_bottom\""), std::string::npos) << issue.detail;
  EXPECT_NE(issue.detail.find("node 5 at (1, 1) faces (1, 1.01)"), std::string::npos) << issue.detail;
  EXPECT_NE(issue.detail.find("nearest node 8 at (1.4, 1.01)"), std::string::npos) << issue.detail;
}

TEST(AssemblyImport, ZeroClearanceNamesThePair) {
  const Scratch scratch;
  std::string text = text_of(data_dir / "two_blocks.msh");
  for (const char* node : {"7 0 1.01 0", "8 1 1.01 0", "9 2 1.01 0"}) {
    std::string moved = node;
    moved.replace(moved.find("1.01"), 4, "1");
    text.replace(text.find(node), std::string(node).size(), moved);
  }
  scratch.write("two_blocks.msh", text);
  const InputIssue issue = single_issue(load(data_dir / "two_blocks.assembly.json"), scratch.dir());
  EXPECT_EQ(issue.pointer, "/gaps/pairs/0");
  EXPECT_NE(issue.detail.find("between \"lower_top\" and \"upper_bottom\": zero clearance"), std::string::npos)
      << issue.detail;
  EXPECT_NE(issue.detail.find("node 4 at (0, 1) and node 7"), std::string::npos) << issue.detail;
}

// ---- exact face pairs: contact surfaces

/// The two-block assembly with gaps.method "exact" (and without what concerns gap elements).
json exact_two_blocks() {
  json assembly = load(data_dir / "two_blocks.assembly.json");
  assembly["gaps"]["method"] = "exact";
  assembly["gaps"]["pairs"][0].erase("first_id");
  assembly["output"].erase("watch_gaps");
  return assembly;
}

/// (node ids of each edge) of a contact surface.
std::vector<std::vector<int>> surface_edges(const Model& m, std::size_t surface) {
  std::vector<std::vector<int>> edges;
  for (const auto& [a, b] : m.contact->surfaces[surface].edges) {
    edges.push_back({m.nodes[static_cast<std::size_t>(a)].id, m.nodes[static_cast<std::size_t>(b)].id});
  }
  return edges;
}

TEST(AssemblyImport, ExactFacePairsBecomeContactSurfacesAtAnyClearance) {
  const Scratch scratch;
  // The upper block's bottom nodes 7, 8, 9 at z = 1.01 (a clearance), 1 (touching), 0.99 (an
  // interference), and with node 8 moved along the face (the faces' nodes no longer face each other).
  const std::vector<std::pair<std::string, std::string>> variants{
      {"8 1 1.01 0", "8 1 1.01 0"}, {"1.01 0", "1 0"}, {"1.01 0", "0.99 0"}, {"8 1 1.01 0", "8 1.4 1.01 0"}};
  for (const auto& [from, to] : variants) {
    std::string text = text_of(data_dir / "two_blocks.msh");
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
    scratch.write("two_blocks.msh", text);
    const Model m = io::read_model(io::import_assembly(exact_two_blocks(), scratch.dir()));
    EXPECT_FALSE(m.gaps) << to;  // no gap elements, so no gaps block
    ASSERT_TRUE(m.contact) << to;
    ASSERT_EQ(m.contact->surfaces.size(), 2u);
    EXPECT_EQ(m.contact->surfaces[0].name, "lower_top");
    EXPECT_EQ(m.contact->surfaces[1].name, "upper_bottom");
    EXPECT_EQ(surface_edges(m, 0), (std::vector<std::vector<int>>{{4, 5}, {5, 6}}));
    EXPECT_EQ(surface_edges(m, 1), (std::vector<std::vector<int>>{{7, 8}, {8, 9}}));
    ASSERT_EQ(m.contact->pairs.size(), 1u);
    EXPECT_EQ(m.contact->pairs[0].surfaces, (std::array<int, 2>{0, 1}));
  }
  // The classic method still generates gap elements (ImportedMshEqualsTheHandWrittenModel); a face
  // used by two pairs is one surface.
  json twice = exact_two_blocks();
  twice["gaps"]["pairs"].push_back({{"faces", {"upper_bottom", "top"}}});
  const Model m = io::read_model(io::import_assembly(twice, data_dir));
  ASSERT_TRUE(m.contact);
  EXPECT_EQ(m.contact->surfaces.size(), 3u);
  ASSERT_EQ(m.contact->pairs.size(), 2u);
  EXPECT_EQ(m.contact->pairs[1].surfaces, (std::array<int, 2>{1, 2}));
}

TEST(AssemblyImport, ExactFacePairErrorsAtTheirPointers) {
  struct BadPair {
    const char* what;
    json pair;
    const char* pointer;
    const char* says;
  };
  const std::vector<BadPair> cases{
      {"first_id", {{"faces", {"lower_top", "upper_bottom"}}, {"first_id", 100}}, "/gaps/pairs/0/first_id",
       "becomes contact surfaces"},
      {"tolerance", {{"faces", {"lower_top", "upper_bottom"}}, {"tolerance", 0.2}}, "/gaps/pairs/0/tolerance",
       "becomes contact surfaces"},
      {"a face with itself", {{"faces", {"lower_top", "lower_top"}}}, "/gaps/pairs/0/faces/1", "paired with itself"},
      {"an unknown group", {{"faces", {"lower_top", "uper_bottom"}}}, "/gaps/pairs/0/faces/1", "did you mean"},
      {"a surface group", {{"faces", {"lower", "upper_bottom"}}}, "/gaps/pairs/0/faces/0", "a curve (dimension 1)"},
      // "left" runs up both blocks' sides: two pieces, not one chain (the model reader's finding).
      {"not a chain", {{"faces", {"left", "upper_bottom"}}}, "/gaps/pairs/0/faces/0", "/contact/surfaces/0/edges/"},
      {"three faces", {{"faces", {"lower_top", "upper_bottom", "top"}}}, "/gaps/pairs/0/faces", "two curve groups"},
  };
  for (const BadPair& c : cases) {
    json assembly = exact_two_blocks();
    assembly["gaps"]["pairs"][0] = c.pair;
    const InputIssue issue = single_issue(assembly, data_dir);
    EXPECT_EQ(issue.pointer, c.pointer) << c.what << ": " << issue.detail;
    EXPECT_NE(issue.detail.find(c.says), std::string::npos) << c.what << ": " << issue.detail;
  }
}

// ---- heat conduction by physical group

/// The two-block assembly with exact contact, a material per block and a thermal section by group
/// instead of loads.temperatures.
json thermal_two_blocks() {
  json assembly = exact_two_blocks();
  assembly["materials"][0]["table"][0]["k"] = 2.0;
  json upper_material = assembly["materials"][0];
  upper_material["id"] = 2;
  assembly["materials"].push_back(upper_material);
  assembly["regions"][1]["material"] = 2;
  assembly["loads"].erase("temperatures");
  assembly["gaps"]["pairs"][0]["conductance"] = {{"closed", 5.0}, {"gas_conductivity", 0.01}};
  assembly["thermal"] = {
      {"type", "steady"},
      {"boundary", {{{"group", "bottom"}, {"temperature", 20.0}},
                    {{"group", "top"}, {"flux", 3.0}},
                    {{"group", "left"}, {"film", 0.5}, {"ambient", 70.0}}}},
      {"sources", {{{"group", "upper"}, {"power_density", 1.5}}, {{"material", 1}, {"power_density", -0.5}}}}};
  return assembly;
}

/// (node ids of each edge) of a thermal boundary entry.
std::vector<std::vector<int>> thermal_edges(const Model& m, std::size_t entry) {
  std::vector<std::vector<int>> edges;
  for (const ThermalEdge& e : m.thermal->boundary[entry].edges) {
    edges.push_back({m.nodes[static_cast<std::size_t>(e.node_a)].id, m.nodes[static_cast<std::size_t>(e.node_b)].id});
  }
  return edges;
}

TEST(AssemblyImport, ThermalConditionsAndSourcesByPhysicalGroup) {
  const json model = io::import_assembly(thermal_two_blocks(), data_dir);
  const Model m = io::read_model(model);
  ASSERT_TRUE(m.thermal);
  EXPECT_EQ(m.thermal->type, ThermalType::steady);
  ASSERT_EQ(m.thermal->boundary.size(), 3u);
  // Each entry keeps its index, kind and values; its edges are the group's line elements, each in
  // the counter-clockwise order of the element that owns it.
  EXPECT_EQ(m.thermal->boundary[0].kind, ThermalBoundary::Kind::temperature);
  EXPECT_EQ(m.thermal->boundary[0].value, 20.0);
  EXPECT_EQ(thermal_edges(m, 0), (std::vector<std::vector<int>>{{1, 2}, {2, 3}}));
  EXPECT_EQ(m.thermal->boundary[1].kind, ThermalBoundary::Kind::flux);
  EXPECT_EQ(m.thermal->boundary[1].value, 3.0);
  EXPECT_EQ(thermal_edges(m, 1), (std::vector<std::vector<int>>{{11, 10}, {12, 11}}));
  EXPECT_EQ(m.thermal->boundary[2].kind, ThermalBoundary::Kind::film);
  EXPECT_EQ(m.thermal->boundary[2].value, 0.5);
  EXPECT_EQ(m.thermal->boundary[2].ambient, 70.0);
  EXPECT_EQ(thermal_edges(m, 2).size(), 2u);  // "left": one edge of each block
  for (const ThermalEdge& e : m.thermal->boundary[2].edges) {
    EXPECT_EQ(m.nodes[static_cast<std::size_t>(e.node_a)].r, 0.0);
    EXPECT_EQ(m.nodes[static_cast<std::size_t>(e.node_b)].r, 0.0);
  }
  // The source on the upper block's surface group heats its material (2); the one by id passes through.
  ASSERT_EQ(m.thermal->sources.size(), 2u);
  EXPECT_EQ(m.materials[static_cast<std::size_t>(m.thermal->sources[0].material)].id, 2);
  EXPECT_EQ(m.thermal->sources[0].power_density, 1.5);
  EXPECT_EQ(m.materials[static_cast<std::size_t>(m.thermal->sources[1].material)].id, 1);
  EXPECT_EQ(m.thermal->sources[1].power_density, -0.5);
  // The exact face pair carries its conductance to the contact pair.
  ASSERT_TRUE(m.contact && m.contact->pairs.size() == 1);
  ASSERT_TRUE(m.contact->pairs[0].conductance);
  EXPECT_EQ(model["contact"]["pairs"][0]["conductance"], (json{{"closed", 5.0}, {"gas_conductivity", 0.01}}));
  EXPECT_FALSE(model.contains("loads") && model["loads"].contains("temperatures"));
}

TEST(AssemblyImport, ThermalErrorsAtTheirPointers) {
  const std::vector<BadValue> cases{
      {"an unknown group", "/thermal/boundary/1/group", "topp", "/thermal/boundary/1/group", "did you mean \"top\"?"},
      {"a surface as a boundary", "/thermal/boundary/0/group", "lower", "/thermal/boundary/0/group",
       "a thermal boundary condition needs a curve (dimension 1)"},
      {"a point as a boundary", "/thermal/boundary/0/group", "corner", "/thermal/boundary/0/group",
       "has dimension 0 (point)"},
      {"edges beside the group", "/thermal/boundary/0/edges", json{{1, 2}}, "/thermal/boundary/0/edges",
       "remove edges"},
      {"a curve as a source", "/thermal/sources/0/group", "top", "/thermal/sources/0/group",
       "a heat source needs a surface (dimension 2)"},
      {"a group holding part of a material", "/regions/1/material", 1, "/thermal/sources/0/group",
       "is material 1 too, and group \"upper\" does not hold it"},
      {"a material heated twice", "/thermal/sources/1/material", 2, "/thermal/sources/1/material",
       "already heated by /thermal/sources/0"},
      {"group and material", "/thermal/sources/0/material", 2, "/thermal/sources/0", "exactly one of them"},
      {"an unknown material", "/thermal/sources/1/material", 7, "/thermal/sources/1/material", "not the id"},
      // The values pass through: the model reader's findings keep their pointers.
      {"a negative film", "/thermal/boundary/2/film", -0.5, "/thermal/boundary/2/film", "film"},
      {"two kinds", "/thermal/boundary/1/temperature", 5.0, "/thermal/boundary/1", "exactly one of"},
      {"a transient key in a steady run", "/thermal/end_time", 2.0, "/thermal/end_time", "transient"},
      {"a source's power", "/thermal/sources/0/power_density", "hot", "/thermal/sources/0/power_density", ""},
      {"a pair's conductance", "/gaps/pairs/0/conductance/closed", -1.0, "/gaps/pairs/0/conductance/closed", ""},
      {"temperatures given too", "/loads/temperatures", json{{"default", 70.0}}, "/loads/temperatures",
       "computed by /thermal"},
  };
  for (const BadValue& c : cases) {
    json assembly = thermal_two_blocks();
    assembly[json::json_pointer(c.at)] = c.value;
    const InputIssue issue = single_issue(assembly, data_dir);
    EXPECT_EQ(issue.pointer, c.pointer) << c.what << ": " << issue.detail;
    EXPECT_NE(issue.detail.find(c.says), std::string::npos) << c.what << ": " << issue.detail;
  }
  // A classic face pair makes gap elements, which conduct by gaps.conductance, not by the pair's.
  json classic = load(data_dir / "two_blocks.assembly.json");
  classic["gaps"]["pairs"][0]["conductance"] = 1.0;
  const InputIssue conductance = single_issue(classic, data_dir);
  EXPECT_EQ(conductance.pointer, "/gaps/pairs/0/conductance");
  EXPECT_NE(conductance.detail.find("gaps.conductance"), std::string::npos) << conductance.detail;
}

TEST(AssemblyImport, AFileThatIsNotAMesh) {
  const Scratch scratch;
  scratch.write("two_blocks.msh", "{\"this\": \"is JSON, not a mesh\"}\n");
  const InputIssue issue = single_issue(load(data_dir / "two_blocks.assembly.json"), scratch.dir());
  EXPECT_EQ(issue.pointer, "/mesh");
  EXPECT_NE(issue.detail.find("Gmsh cannot read"), std::string::npos) << issue.detail;

  const InputIssue missing = single_issue(load(data_dir / "two_blocks.assembly.json"), scratch.dir() / "elsewhere");
  EXPECT_EQ(missing.pointer, "/mesh");
  EXPECT_NE(missing.detail.find("does not exist"), std::string::npos) << missing.detail;
}

TEST(AssemblyImport, AMeshOutsideThePlaneZ0) {
  const Scratch scratch;
  scratch.write("two_blocks.msh", two_blocks_with("11 1 2.01 0", "11 1 2.01 0.25"));
  const InputIssue issue = single_issue(load(data_dir / "two_blocks.assembly.json"), scratch.dir());
  EXPECT_EQ(issue.pointer, "/mesh");
  EXPECT_NE(issue.detail.find("outside the plane z = 0, first node 11 at (1, 2.01, 0.25)"), std::string::npos)
      << issue.detail;
}

TEST(AssemblyImport, ThirdOrderElementsAreRejectedByName) {
  const Scratch scratch;
  scratch.write("square.geo",
                "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};\n"
                "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
                "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\n"
                "Physical Surface(\"body\") = {1}; Physical Curve(\"base\") = {1};\n"
                "Mesh.ElementOrder = 3;\n");
  json assembly = load(data_dir / "two_blocks.assembly.json");
  assembly["mesh"] = "square.geo";
  const InputIssue issue = single_issue(assembly, scratch.dir());
  EXPECT_EQ(issue.pointer, "/mesh");
  EXPECT_NE(issue.detail.find("\"Triangle 10\""), std::string::npos) << issue.detail;
  EXPECT_NE(issue.detail.find("Mesh.ElementOrder = 1 or 2"), std::string::npos) << issue.detail;
}

// ---- second-order meshes

/// A Gmsh 2.2 mesh of two second-order cells side by side on [0, 2] x [0, 1] (quad8: Gmsh type 16,
/// quad9: 10, or tri6: 9, two triangles a cell), node (I, J) at (I / 2, J / 2) with tag 1 + I + 5 J;
/// the second cell's elements listed clockwise (as Gmsh writes a surface whose normal is -z). Physical
/// groups: surface "body", 3-node lines (type 8) "bottom" (y = 0), "top" (y = 1), "left" (x = 0).
std::string second_order_msh(const std::string& family) {
  const auto tag = [](int I, int J) { return 1 + I + 5 * J; };
  const bool centres = family != "quad8";
  std::ostringstream nodes;
  int node_count = 0;
  for (int J = 0; J <= 2; ++J) {
    for (int I = 0; I <= 4; ++I) {
      if (!centres && I % 2 == 1 && J % 2 == 1) continue;
      nodes << tag(I, J) << ' ' << I / 2.0 << ' ' << J / 2.0 << " 0\n";
      ++node_count;
    }
  }
  std::vector<std::string> elements;
  const auto line = [&](int phys, int entity, int a, int b, int m) {
    elements.push_back("8 2 " + std::to_string(phys) + ' ' + std::to_string(entity) + ' ' + std::to_string(a) + ' ' +
                       std::to_string(b) + ' ' + std::to_string(m));
  };
  for (int k = 0; k < 2; ++k) line(2, 1, tag(2 * k, 0), tag(2 * k + 2, 0), tag(2 * k + 1, 0));
  for (int k = 0; k < 2; ++k) line(3, 3, tag(2 * k + 2, 2), tag(2 * k, 2), tag(2 * k + 1, 2));
  line(4, 4, tag(0, 2), tag(0, 0), tag(0, 1));
  const auto cell = [&](std::vector<int> nodes_of, int type) {
    std::string text = std::to_string(type) + " 2 1 1";
    for (const int n : nodes_of) text += ' ' + std::to_string(n);
    elements.push_back(text);
  };
  for (int c = 0; c < 2; ++c) {
    const int I = 2 * c;
    const int c0 = tag(I, 0), c1 = tag(I + 2, 0), c2 = tag(I + 2, 2), c3 = tag(I, 2);
    const int m01 = tag(I + 1, 0), m12 = tag(I + 2, 1), m23 = tag(I + 1, 2), m30 = tag(I, 1), centre = tag(I + 1, 1);
    const bool reversed = c == 1;
    if (family == "tri6") {
      cell(reversed ? std::vector<int>{c0, c2, c1, centre, m12, m01} : std::vector<int>{c0, c1, c2, m01, m12, centre}, 9);
      cell(reversed ? std::vector<int>{c0, c3, c2, m30, m23, centre} : std::vector<int>{c0, c2, c3, centre, m23, m30}, 9);
      continue;
    }
    std::vector<int> q = reversed ? std::vector<int>{c0, c3, c2, c1, m30, m23, m12, m01}
                                  : std::vector<int>{c0, c1, c2, c3, m01, m12, m23, m30};
    if (family == "quad9") q.push_back(centre);
    cell(q, family == "quad9" ? 10 : 16);
  }
  std::ostringstream text;
  text << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n2 1 \"body\"\n1 2 \"bottom\"\n1 3 \"top\"\n"
       << "1 4 \"left\"\n$EndPhysicalNames\n$Nodes\n" << node_count << '\n' << nodes.str() << "$EndNodes\n$Elements\n"
       << elements.size() << '\n';
  for (std::size_t e = 0; e < elements.size(); ++e) text << e + 1 << ' ' << elements[e] << '\n';
  text << "$EndElements\n";
  return text.str();
}

json second_order_assembly() {
  return json::parse(R"({
    "schema_version": 1, "title": "two second-order cells", "mesh": "cells.msh",
    "analysis": {"type": "plane_stress", "thickness": 1.0},
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 1000.0, "nu": 0.25, "alpha": 1e-5, "k": 2.0}]}],
    "regions": [{"group": "body", "material": 1}],
    "constraints": [{"group": "bottom", "z": 0.0}, {"group": "left", "r": 0.0}],
    "loads": {"pressures": [{"group": "top", "normal": 10.0}]},
    "thermal": {"type": "steady", "boundary": [{"group": "bottom", "temperature": 100.0},
                                               {"group": "top", "film": 4.0, "ambient": 20.0}]}
  })");
}

TEST(AssemblyImport, SecondOrderMshKeepsItsMidSideNodesAndTurnsClockwiseCellsWithThem) {
  for (const std::string family : {"quad8", "quad9", "tri6"}) {
    const Scratch scratch;
    scratch.write("cells.msh", second_order_msh(family));
    const json model = io::import_assembly(second_order_assembly(), scratch.dir());
    const auto tag = [](int I, int J) { return 1 + I + 5 * J; };
    // The second cell, clockwise in the file, counter-clockwise in the model: corners and mid-sides.
    const json& elements = model["elements"];
    if (family == "tri6") {
      ASSERT_EQ(elements.size(), 4u);
      EXPECT_EQ(elements[2]["nodes"], json({tag(2, 0), tag(4, 0), tag(4, 2), tag(3, 0), tag(4, 1), tag(3, 1)}));
      EXPECT_EQ(elements[3]["nodes"], json({tag(2, 0), tag(4, 2), tag(2, 2), tag(3, 1), tag(3, 2), tag(2, 1)}));
    } else {
      ASSERT_EQ(elements.size(), 2u);
      json expected = {tag(2, 0), tag(4, 0), tag(4, 2), tag(2, 2), tag(3, 0), tag(4, 1), tag(3, 2), tag(2, 1)};
      if (family == "quad9") expected.push_back(tag(3, 1));
      EXPECT_EQ(elements[1]["nodes"], expected) << family;
    }
    // The constraint on the curve "left" holds its mid-side node too.
    std::set<int> held_r;
    for (const json& c : model["constraints"]) {
      if (c.contains("r")) held_r.insert(c["node"].get<int>());
    }
    EXPECT_EQ(held_r, (std::set<int>{tag(0, 0), tag(0, 1), tag(0, 2)})) << family;
    // It reads, conducts and solves: the bottom (held at 100, mid-side nodes too) and the film on top.
    const Model m = io::read_model(model);
    const Solution s = solve_with_heat(m);
    ASSERT_TRUE(s.thermal.has_value()) << family;
    EXPECT_EQ(s.status, RunStatus::converged) << family;
    // The closed form of the slab 0 < y < 1: T = 100 + g y, -k g = h (100 + g - 20), g = -h 80 / (k + h).
    const double g = -4.0 * 80.0 / (2.0 + 4.0);
    for (std::size_t n = 0; n < m.nodes.size(); ++n) EXPECT_NEAR(s.thermal->T[n], 100.0 + g * m.nodes[n].z, 1e-9) << family;
  }
}

TEST(AssemblyImport, OrderAppliesToGeoFilesOnlyAndAGeoMayAskItself) {
  const Scratch scratch;
  scratch.write("cells.msh", second_order_msh("quad8"));
  json assembly = second_order_assembly();
  assembly["order"] = 2;
  const InputIssue issue = single_issue(assembly, scratch.dir());
  EXPECT_EQ(issue.pointer, "/order");
  EXPECT_NE(issue.detail.find("applies to a .geo"), std::string::npos) << issue.detail;
  assembly["order"] = 3;
  assembly["mesh"] = "square.geo";
  scratch.write("square.geo",
                "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};\n"
                "Point(4) = {0, 1, 0, 0.5};\n"
                "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                "Physical Surface(\"body\") = {1}; Physical Curve(\"bottom\") = {1}; Physical Curve(\"top\") = {3};\n"
                "Physical Curve(\"left\") = {4};\n"
                "Mesh.ElementOrder = 2;\n");
  EXPECT_EQ(single_issue(assembly, scratch.dir()).pointer, "/order");
  // The .geo's own Mesh.ElementOrder = 2: triangles of 6 nodes; "order": 1 overrides it.
  assembly.erase("order");
  const json six = io::import_assembly(assembly, scratch.dir());
  for (const json& e : six["elements"]) EXPECT_EQ(e["nodes"].size(), 6u);
  assembly["order"] = 1;
  const json three = io::import_assembly(assembly, scratch.dir());
  for (const json& e : three["elements"]) EXPECT_EQ(e["nodes"].size(), 3u);
}

TEST(AssemblyImport, GapsOnQuadraticEdgesAreRefusedAndContactSurfacesImported) {
  // Two quad8 blocks, [0, 1] x [0, 1] and [0, 1] x [1.1, 2.1], facing across 3-node lines.
  const Scratch scratch;
  scratch.write("blocks.msh",
                "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n6\n1 1 \"lower_top\"\n1 2 \"upper_bottom\"\n"
                "1 3 \"base\"\n1 6 \"upper_top\"\n2 4 \"lower\"\n2 5 \"upper\"\n$EndPhysicalNames\n$Nodes\n16\n"
                "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0 0\n6 1 0.5 0\n7 0.5 1 0\n8 0 0.5 0\n"
                "11 0 1.1 0\n12 1 1.1 0\n13 1 2.1 0\n14 0 2.1 0\n15 0.5 1.1 0\n16 1 1.6 0\n17 0.5 2.1 0\n18 0 1.6 0\n"
                "$EndNodes\n$Elements\n6\n1 8 2 1 1 3 4 7\n2 8 2 2 2 11 12 15\n3 8 2 3 3 1 2 5\n4 8 2 6 4 13 14 17\n"
                "5 16 2 4 1 1 2 3 4 5 6 7 8\n6 16 2 5 2 11 12 13 14 15 16 17 18\n$EndElements\n");
  json assembly = json::parse(R"({
    "schema_version": 1, "title": "two quad8 blocks", "mesh": "blocks.msh",
    "analysis": {"type": "plane_stress", "thickness": 1.0},
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 1000.0, "nu": 0.25, "alpha": 0}]}],
    "regions": [{"group": "lower", "material": 1}, {"group": "upper", "material": 1}],
    "constraints": [{"group": "base", "r": 0.0, "z": 0.0}, {"group": "upper_top", "r": 0.0, "z": -0.2}],
    "gaps": {"initial_modulus": 100.0, "tensile_schedule": [1.0],
             "pairs": [{"faces": ["lower_top", "upper_bottom"]}]}
  })");
  const InputIssue gap = single_issue(assembly, scratch.dir());
  EXPECT_EQ(gap.pointer.rfind("/gaps/pairs/0", 0), 0u) << gap.pointer << ": " << gap.detail;
  EXPECT_NE(gap.detail.find("contact surfaces"), std::string::npos) << gap.detail;
  // With exact gaps the pair becomes contact surfaces, which run on quadratic edges: each face one
  // 3-node edge, its mid-side node included, and the upper block pressed onto the lower one.
  assembly["gaps"]["method"] = "exact";
  const Model model = io::read_model(io::import_assembly(assembly, scratch.dir()));
  ASSERT_TRUE(model.contact);
  ASSERT_EQ(model.contact->surfaces.size(), 2u);
  for (const SurfaceDefinition& surface : model.contact->surfaces) EXPECT_EQ(surface.edges.size(), 1u) << surface.name;
  const Solution solved = solve(model);
  ASSERT_EQ(solved.status, RunStatus::converged) << solved.message;
  ASSERT_EQ(solved.contact.size(), 1u);
  double largest = 0.0;
  for (const auto& point : solved.contact[0].points) largest = std::max(largest, point.pressure);
  EXPECT_GT(largest, 0.0) << "the blocks touch: 0.2 pressed across a 0.1 gap";
}

TEST(AssemblyImport, SecondOrderGeoQuarterRingHasItsMidSideNodesOnTheCirclesAndLamesBore) {
  // a = 1, b = 2, 4 quad8 through the wall, 8 round; Gmsh places second-order nodes on the arcs.
  const Scratch scratch;
  scratch.write("ring.geo",
                "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {2, 0, 0}; Point(4) = {0, 2, 0};\n"
                "Point(5) = {0, 1, 0};\n"
                "Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};\n"
                "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                "Transfinite Curve {1, 3} = 5; Transfinite Curve {2, 4} = 9; Transfinite Surface {1};\n"
                "Recombine Surface {1};\n"
                "Mesh.SecondOrderIncomplete = 1;\n"
                "Physical Surface(\"ring\") = {1}; Physical Curve(\"x_axis\") = {1}; Physical Curve(\"y_axis\") = {3};\n"
                "Physical Curve(\"bore\") = {4}; Physical Curve(\"outside\") = {2};\n");
  const double p = 100.0, E = 1000.0, nu = 0.3, a = 1.0, b = 2.0;
  json assembly = json::parse(R"({
    "schema_version": 1, "title": "Lame quarter ring", "mesh": "ring.geo", "order": 2,
    "analysis": {"type": "plane_strain"},
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 1000.0, "nu": 0.3, "alpha": 0}]}],
    "regions": [{"group": "ring", "material": 1}],
    "constraints": [{"group": "x_axis", "z": 0.0}, {"group": "y_axis", "r": 0.0}],
    "loads": {"pressures": [{"group": "bore", "normal": 100.0}]}
  })");
  const json model = io::import_assembly(assembly, scratch.dir());
  for (const json& e : model["elements"]) ASSERT_EQ(e["nodes"].size(), 8u);
  // The sandbox still applies: a second-order geometry that runs a program is refused.
  scratch.write("escape.geo", text_of(scratch.dir() / "ring.geo") + "SystemCall \"touch /tmp/x\";\n");
  json escape = assembly;
  escape["mesh"] = "escape.geo";
  const InputIssue refused = single_issue(escape, scratch.dir());
  EXPECT_EQ(refused.pointer, "/mesh");
  EXPECT_NE(refused.detail.find("sandbox"), std::string::npos) << refused.detail;
  const Model m = io::read_model(model);
  double worst_on_circle = 0.0;
  int on_circles = 0;
  for (const Node& n : m.nodes) {
    const double r = std::hypot(n.r, n.z);
    for (const double R : {a, b}) {
      if (std::abs(r - R) < 1e-6) {
        worst_on_circle = std::max(worst_on_circle, std::abs(r - R) / R);
        ++on_circles;
      }
    }
  }
  EXPECT_EQ(on_circles, 2 * 17);  // 8 elements round: 17 nodes on each arc, mid-side nodes among them
  EXPECT_LT(worst_on_circle, 1e-12);
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const double A = p * a * a / (b * b - a * a), B = p * a * a * b * b / (b * b - a * a);
  const double u_exact = (1.0 + nu) / E * ((1.0 - 2.0 * nu) * A * a + B / a);
  double worst = 0.0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const double r = std::hypot(m.nodes[n].r, m.nodes[n].z);
    if (std::abs(r - a) > 1e-9) continue;
    const double u_r = (s.nodes[n].u_r * m.nodes[n].r + s.nodes[n].u_z * m.nodes[n].z) / r;
    worst = std::max(worst, std::abs(u_r / u_exact - 1.0));
  }
  std::printf("Lame quarter ring, 4 x 8 imported quad8: bore u_r within %.3e of Lame\n", worst);
  EXPECT_LT(worst, 2.5e-4);  // observed 1.54e-4 (4 x 8 quad8, the load consistent on the curved bore)
}

// ---- the gap geometry alone

TEST(GapGenerator, ChainsMustBeOneOpenCurve) {
  const std::vector<int> ids{10, 11, 12, 13};
  const std::vector<std::array<int, 2>> open{{2, 1}, {0, 1}, {2, 3}};
  EXPECT_EQ(io::order_chain(open, ids).nodes, (std::vector<int>{0, 1, 2, 3}));  // from the smaller end id
  const std::vector<std::array<int, 2>> closed{{0, 1}, {1, 2}, {2, 0}};
  EXPECT_NE(io::order_chain(closed, ids).problem.find("closed curve"), std::string::npos);
  const std::vector<std::array<int, 2>> branched{{0, 1}, {1, 2}, {1, 3}};
  EXPECT_NE(io::order_chain(branched, ids).problem.find("branches at node 11"), std::string::npos);
  const std::vector<std::array<int, 2>> broken{{0, 1}, {2, 3}};
  EXPECT_NE(io::order_chain(broken, ids).problem.find("one connected curve"), std::string::npos);
}

/// Two faces of a slanted gap: y = x (A, below) and y = x + c (B); M normal to them, at 135 degrees
/// here because A's outward normal points up-left.
TEST(GapGenerator, SlantedFacesPairAlongTheNormal) {
  const Vec2 up_left = Vec2(-1, 1).normalized();
  std::vector<Vec2> x;
  for (int k = 0; k < 4; ++k) x.emplace_back(k, k);
  for (int k = 0; k < 4; ++k) x.push_back(Vec2(k, k) + 0.01 * up_left);  // clearance 0.01 along the normal
  const std::vector<int> ids{1, 2, 3, 4, 11, 12, 13, 14};
  io::FaceChain a, b;
  a.nodes = {0, 1, 2, 3};
  b.nodes = {7, 6, 5, 4};  // the other way round
  a.outward.assign(3, up_left);
  b.outward.assign(3, -up_left);
  const io::GapGeneration g = io::generate_gaps(a, b, x, ids, 0.1);
  ASSERT_TRUE(g.problems.empty()) << g.problems.front();
  ASSERT_EQ(g.gaps.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(g.gaps[k].angle_deg, 135.0, 1e-9);
    double twice_area = 0.0;
    for (std::size_t i = 0; i < 4; ++i) {
      const Vec2& p = x[static_cast<std::size_t>(g.gaps[k].nodes[i])];
      const Vec2& q = x[static_cast<std::size_t>(g.gaps[k].nodes[(i + 1) % 4])];
      twice_area += p.x() * q.y() - q.x() * p.y();
    }
    EXPECT_GT(twice_area, 0.0);  // counter-clockwise
  }
  EXPECT_EQ(g.pairs.front(), (std::pair<int, int>{0, 4}));

  // A face with one node fewer: the unmatched node of B is named.
  b.nodes = {7, 6, 5};
  b.outward.assign(2, -up_left);
  const io::GapGeneration fewer = io::generate_gaps(a, b, x, ids, 0.1);
  ASSERT_FALSE(fewer.problems.empty());
  EXPECT_NE(fewer.problems.front().find("node 1 at (0, 0)"), std::string::npos) << fewer.problems.front();
}

/// Generated angles pass the model reader's rule (solver/gap_faces.hpp), whatever the clearance; a
/// pairing whose facing nodes are offset along the faces far more than the clearance would turn M
/// along the faces, and is a problem of the generation naming the nodes.
TEST(GapGenerator, GeneratedAnglesRunAcrossTheGapOrTheNodesAreNamed) {
  const auto faces = [](double clearance, double offset, std::vector<Vec2>& x) {
    x.clear();
    for (int k = 0; k < 3; ++k) x.emplace_back(k, 0.0);                  // A: z = 0, 1 between nodes
    for (int k = 0; k < 3; ++k) x.emplace_back(k + offset, clearance);   // B above it
  };
  const std::vector<int> ids{1, 2, 3, 11, 12, 13};
  io::FaceChain a, b;
  a.nodes = {0, 1, 2};
  b.nodes = {3, 4, 5};
  a.outward.assign(2, Vec2(0, 1));
  b.outward.assign(2, Vec2(0, -1));
  std::vector<Vec2> x;
  for (double clearance : {0.01, 1.0, 3.0}) {  // thin, square and wider than long: all across
    faces(clearance, 0.0, x);
    const io::GapGeneration g = io::generate_gaps(a, b, x, ids, 0.1);
    ASSERT_TRUE(g.problems.empty()) << g.problems.front();
    for (const io::GeneratedGap& gap : g.gaps) {
      std::array<Vec2, 4> corners{};
      for (std::size_t i = 0; i < 4; ++i) corners[i] = x[static_cast<std::size_t>(gap.nodes[i])];
      EXPECT_TRUE(runs_across(gap_faces(corners, 4, gap.angle_deg)));
      EXPECT_NEAR(gap.angle_deg, 90.0, 1e-9);
    }
  }
  // Offset 0.09 (within the 0.1 tolerance) across a clearance of 0.01: M at 6.3 degrees, along the faces.
  faces(0.01, 0.09, x);
  const io::GapGeneration sheared = io::generate_gaps(a, b, x, ids, 0.1);
  ASSERT_EQ(sheared.problems.size(), 2U);
  EXPECT_TRUE(sheared.gaps.empty());
  EXPECT_NE(sheared.problems.front().find("between nodes 1-2 and 11-12 would have its M axis (6.3"), std::string::npos)
      << sheared.problems.front();
  EXPECT_NE(sheared.problems.front().find("more than 30 degrees off perpendicular to its faces"), std::string::npos)
      << sheared.problems.front();
}

// ---- adapt: the settings of the adaptive loop, each bad value at its pointer

TEST(AssemblyImport, AdaptSettingsAreReadFromAGeoAssembly) {
  json a = load(assemblies_dir / "ring-fit.assembly.json");
  a["adapt"] = {{"target_error", 0.05}};
  EXPECT_NO_THROW((void)io::import_assembly(a, assemblies_dir));
  const auto none = [](const std::string& p, std::string d) { ADD_FAILURE() << p << ": " << d; };
  const auto s = io::read_adapt_settings(a, none);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->target_error, 0.05);
  EXPECT_EQ(s->max_cycles, 6);
  EXPECT_EQ(s->max_nodes, 200000U);
  a["adapt"] = {{"target_error", 0.01}, {"max_cycles", 3}, {"max_nodes", 5000}};
  const auto t = io::read_adapt_settings(a, none);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->max_cycles, 3);
  EXPECT_EQ(t->max_nodes, 5000U);
  EXPECT_FALSE(io::read_adapt_settings(load(assemblies_dir / "ring-fit.assembly.json"), none));
}

TEST(AssemblyImport, BadAdaptSettingsAreReportedAtTheirPointers) {
  const json ring = load(assemblies_dir / "ring-fit.assembly.json");
  const auto issue = [&](const json& adapt) {
    json a = ring;
    a["adapt"] = adapt;
    return single_issue(a, assemblies_dir);
  };
  struct Case {
    json adapt;
    const char* pointer;
    const char* words;
  };
  const std::vector<Case> cases = {
      {{{"target_error", 0.0}}, "/adapt/target_error", "target_error = 0.0 is out of range: need 0 < target_error < 1"},
      {{{"target_error", -0.1}}, "/adapt/target_error", "out of range"},
      {{{"target_error", 1.0}}, "/adapt/target_error", "target_error = 1.0 is out of range"},
      {{{"target_error", "1%"}}, "/adapt/target_error", "target_error must be a number"},
      {{{"max_cycles", 3}}, "/adapt", "\"target_error\""},
      {{{"target_error", 0.02}, {"max_cycles", 0}}, "/adapt/max_cycles", "max_cycles = 0 is out of range: need 1 <= max_cycles <= 50"},
      {{{"target_error", 0.02}, {"max_cycles", 1000000}}, "/adapt/max_cycles", "max_cycles = 1000000 is out of range"},
      {{{"target_error", 0.02}, {"max_cycles", 2.5}}, "/adapt/max_cycles", "max_cycles must be an integer, got the number 2.5"},
      {{{"target_error", 0.02}, {"max_nodes", 10}}, "/adapt/max_nodes", "max_nodes = 10 is out of range: need 100 <= max_nodes"},
      // The ring's first mesh has 450 nodes: a limit below it leaves nothing to refine.
      {{{"target_error", 0.02}, {"max_nodes", 300}}, "/adapt/max_nodes", "fewer than the first mesh's 450 nodes"},
      {{{"target_error", 0.02}, {"cycles", 3}}, "/adapt/cycles", "unknown key \"cycles\""},
      {json(0.02), "/adapt", "expected an object"},
  };
  for (const Case& c : cases) {
    const InputIssue i = issue(c.adapt);
    EXPECT_EQ(i.pointer, c.pointer) << c.adapt.dump();
    EXPECT_NE(i.detail.find(c.words), std::string::npos) << c.adapt.dump() << ": " << i.detail;
  }
}

TEST(AssemblyImport, AdaptWithAMshMeshHasNothingToRemesh) {
  json a = load(data_dir / "two_blocks.assembly.json");
  a["adapt"] = {{"target_error", 0.02}};
  const InputIssue i = single_issue(a, data_dir);
  EXPECT_EQ(i.pointer, "/adapt");
  EXPECT_NE(i.detail.find("\"two_blocks.msh\" is not a Gmsh geometry (.geo): a .msh mesh has nothing to re-mesh"),
            std::string::npos)
      << i.detail;
}

}  // namespace
}  // namespace saasgaps
