/// The model reader: a valid document becomes the expected Model, and every rule of the model
/// document (docs/model.md and the decisions in io/model_reader.hpp) has a test that
/// breaks it and checks the exact JSON Pointer and that the detail quotes the offending value.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json/json_pointer.hpp"
#include "io/model/model_reader.hpp"
#include "io/restart/state_codec.hpp"
#include "solver/base/errors.hpp"
#include "support/json_mutation.hpp"
#include "support/text_models.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;
using testing::example_models;
using testing::expect_same_model;
using testing::text_of;

/// A valid model that uses every section: quadrilaterals and a triangle, an isotropic and an
/// orthotropic material with every table, gaps with every setting, every kind of load and an
/// unconnected (but constrained) node 11. Node id k has index k - 1.
json valid_model() {
  return json::parse(R"({
    "schema_version": 1,
    "title": "reader test model",
    "description": "every section",
    "analysis": {"type": "plane_stress", "thickness": 0.5, "reference_temperature": 70},
    "nodes": [
      {"id": 1, "r": 0, "z": 0}, {"id": 2, "r": 1, "z": 0}, {"id": 3, "r": 2, "z": 0},
      {"id": 4, "r": 0, "z": 1}, {"id": 5, "r": 1, "z": 1}, {"id": 6, "r": 2, "z": 1},
      {"id": 7, "r": 0, "z": -0.01}, {"id": 8, "r": 1, "z": -0.01}, {"id": 9, "r": 2, "z": -0.01},
      {"id": 10, "r": 3, "z": 0}, {"id": 11, "r": 5, "z": 5}
    ],
    "materials": [
      {"id": 1, "name": "steel", "density": 0.283, "elastic": "isotropic",
       "table": [{"T": 0, "E": 30e6, "nu": 0.3, "alpha": 6.5e-6},
                 {"T": 1000, "E": 25e6, "nu": 0.32, "alpha": 8e-6}],
       "compression_table": [{"T": 0, "E": 31e6, "nu": 0.3, "alpha": 6.5e-6}],
       "plasticity": {"yield_stress": 40000, "hardening_ratio": 0.1}},
      {"id": 2, "elastic": "orthotropic",
       "table": [{"T": 0, "E1": 20e6, "E2": 10e6, "E3": 10e6, "nu12": 0.25, "nu13": 0.25, "nu23": 0.3,
                  "G12": 5e6, "alpha1": 1e-6, "alpha2": 2e-6, "alpha3": 3e-6}],
       "plasticity": [{"T": 0, "yield_stress": 30000, "hardening_ratio": 0},
                      {"T": 500, "yield_stress": 20000, "hardening_ratio": 0.2}]}
    ],
    "elements": [
      {"id": 1, "nodes": [1, 2, 5, 4], "material": 1},
      {"id": 2, "nodes": [2, 3, 6, 5], "material": 2, "angle": 30},
      {"id": 3, "nodes": [3, 10, 6], "material": 1}
    ],
    "gaps": {
      "initial_modulus": 100, "tensile_schedule": [20, 5, 1], "extrapolation_factor": 0.5,
      "closure_tolerance": 0.1, "shear_ratio": 1e-4, "convergence_test": "strict",
      "elements": [{"id": 11, "nodes": [7, 8, 2, 1], "angle": 90},
                   {"id": 12, "nodes": [8, 9, 3, 2], "angle": 90}]
    },
    "constraints": [
      {"node": 7, "r": 0, "z": 0}, {"node": 8, "z": 0}, {"node": 9, "z": 0}, {"node": 1, "r": 0},
      {"node": 11, "r": 0, "z": 0}
    ],
    "loads": {
      "nodal_forces": [{"node": 6, "fz": -100}, {"node": 5, "fr": 10}],
      "pressures": [{"nodes": [5, 4], "normal": 1000}, {"nodes": [6, 10], "normal": 10, "shear": 2}],
      "temperatures": {"default": 100, "nodal": [{"node": 1, "T": 200}]},
      "body_force": {"accel_r": 0, "accel_z": -386.1}
    },
    "solver": {"max_iterations": 12, "plastic_tolerance": 0.02},
    "output": {"watch_elements": [2], "watch_gaps": [12]}
  })");
}

/// The smallest valid model: one triangle, no optional key anywhere.
json minimal_model() {
  return json::parse(R"({
    "schema_version": 1,
    "title": "minimal",
    "analysis": {"type": "plane_strain"},
    "nodes": [{"id": 1, "r": 0, "z": 0}, {"id": 2, "r": 1, "z": 0}, {"id": 3, "r": 0, "z": 1}],
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 1e6, "nu": 0.25, "alpha": 0}]}],
    "elements": [{"id": 1, "nodes": [1, 2, 3], "material": 1}],
    "constraints": [{"node": 1, "r": 0, "z": 0}, {"node": 2, "z": 0}]
  })");
}

json with(json document, const std::string& pointer, json value) {
  document[json::json_pointer(pointer)] = std::move(value);
  return document;
}

json without(json document, const std::string& pointer) {
  const json::json_pointer p(pointer);
  document[p.parent_pointer()].erase(p.back());
  return document;
}

std::string listing(const std::vector<InputIssue>& issues) {
  std::string text;
  for (const InputIssue& issue : issues) text += "  \"" + issue.pointer + "\": " + issue.detail + "\n";
  return text;
}

std::vector<InputIssue> issues_of_text(const std::string& text) {
  try {
    (void)parse_model(text);
  } catch (const ModelError& e) {
    return e.issues();
  }
  return {};
}

/// The document's text with the root's members in the contract's order (a dump sorts them), so
/// that the streaming reader meets each section after those it depends on.
std::string in_contract_order(const json& document) {
  if (!document.is_object()) return document.dump();
  std::string text = "{";
  for (const char* key : {"schema_version", "title", "description", "units", "analysis", "nodes", "materials",
                          "elements", "gaps", "sets", "constraints", "loads", "solver", "output", "steps", "contact",
                          "thermal"}) {
    if (!document.contains(key)) continue;
    text += (text.size() > 1 ? ",\"" : "\"") + std::string(key) + "\":" + document[key].dump();
  }
  for (auto it = document.begin(); it != document.end(); ++it) {  // unknown keys last
    if (text.find("\"" + it.key() + "\":") == std::string::npos) {
      text += (text.size() > 1 ? ",\"" : "\"") + it.key() + "\":" + it->dump();
    }
  }
  return text + "}";
}

bool same_issues(const std::vector<InputIssue>& a, const std::vector<InputIssue>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].pointer != b[i].pointer || a[i].detail != b[i].detail) return false;
  }
  return true;
}

/// The issues read_model finds in the tree. The streaming reader (parse_model) must find the same,
/// in the same order, in the document's text, whether the sections come in the contract's order
/// (read in one pass) or sorted (sections kept and read once their dependencies are): every rule
/// test below checks both readers.
std::vector<InputIssue> issues_of(const json& document) {
  std::vector<InputIssue> issues;
  try {
    (void)read_model(document);
  } catch (const ModelError& e) {
    issues = e.issues();
  }
  // Text cannot hold inf or nan (a dump writes null): only documents that survive a dump compare.
  if (json::parse(document.dump()) == document) {
    for (const std::string& text : {document.dump(), in_contract_order(document)}) {
      const std::vector<InputIssue> streamed = issues_of_text(text);
      EXPECT_TRUE(same_issues(streamed, issues)) << "read_model:\n"
                                                 << listing(issues) << "parse_model:\n"
                                                 << listing(streamed) << "text: " << text.substr(0, 400);
    }
  }
  return issues;
}

/// Success when some issue is at exactly `pointer` and its detail contains every one of `mentions`.
::testing::AssertionResult has_issue(const std::vector<InputIssue>& issues, const std::string& pointer,
                                     std::initializer_list<std::string> mentions) {
  if (issues.empty()) return ::testing::AssertionFailure() << "the document was accepted";
  for (const InputIssue& issue : issues) {
    if (issue.pointer != pointer) continue;
    bool all = true;
    for (const std::string& m : mentions) all = all && issue.detail.find(m) != std::string::npos;
    if (all) return ::testing::AssertionSuccess();
  }
  std::string wanted;
  for (const std::string& m : mentions) wanted += " [" + m + "]";
  return ::testing::AssertionFailure() << "no issue at \"" << pointer << "\" mentioning" << wanted << "; issues:\n"
                                       << listing(issues);
}

::testing::AssertionResult rejects(const json& document, const std::string& pointer,
                                   std::initializer_list<std::string> mentions) {
  return has_issue(issues_of(document), pointer, mentions);
}

// ------------------------------------------------------------------------------------------------
// JSON Pointers

TEST(JsonPointer, EscapesTildeAndSlashAndAppendsIndices) {
  EXPECT_EQ(escape_token("a/b~c"), "a~1b~0c");
  EXPECT_EQ(escape_token("~1"), "~01");
  EXPECT_EQ(pointer_append("", "nodes"), "/nodes");
  EXPECT_EQ(pointer_append("/nodes", std::size_t{3}), "/nodes/3");
  EXPECT_EQ(pointer_append("/a", ""), "/a/");
  EXPECT_EQ(pointer_append("", "m~n/o"), "/m~0n~1o");
}

// ------------------------------------------------------------------------------------------------
// A valid model

TEST(ModelReader, ValidModelIsReadWithIdsResolvedToIndices) {
  const Model m = read_model(valid_model());
  EXPECT_EQ(m.title, "reader test model");
  EXPECT_EQ(m.description, "every section");
  EXPECT_EQ(m.analysis, AnalysisType::plane_stress);
  EXPECT_DOUBLE_EQ(m.thickness, 0.5);
  EXPECT_DOUBLE_EQ(m.reference_temperature, 70.0);

  ASSERT_EQ(m.nodes.size(), 11U);
  EXPECT_EQ(m.nodes[10].id, 11);
  EXPECT_DOUBLE_EQ(m.nodes[10].r, 5.0);
  EXPECT_DOUBLE_EQ(m.nodes[6].z, -0.01);

  ASSERT_EQ(m.elements.size(), 3U);
  EXPECT_EQ(m.elements[0].id, 1);
  EXPECT_EQ(m.elements[0].node_count, 4);
  EXPECT_EQ(m.elements[0].nodes, (std::array<int, 9>{0, 1, 4, 3, -1, -1, -1, -1, -1}));
  EXPECT_EQ(m.elements[0].material, 0);
  EXPECT_DOUBLE_EQ(m.elements[0].angle_deg, 0.0);
  EXPECT_EQ(m.elements[1].material, 1);
  EXPECT_DOUBLE_EQ(m.elements[1].angle_deg, 30.0);
  EXPECT_EQ(m.elements[2].node_count, 3);
  EXPECT_EQ(m.elements[2].nodes, (std::array<int, 9>{2, 9, 5, -1, -1, -1, -1, -1, -1}));

  ASSERT_TRUE(m.gaps.has_value());
  const GapSettings& g = *m.gaps;
  EXPECT_DOUBLE_EQ(g.initial_modulus, 100.0);
  EXPECT_EQ(g.tensile_schedule, (std::vector<double>{20.0, 5.0, 1.0}));
  EXPECT_DOUBLE_EQ(g.extrapolation_factor, 0.5);
  EXPECT_DOUBLE_EQ(g.closure_tolerance, 0.1);
  EXPECT_DOUBLE_EQ(g.shear_ratio, 1e-4);
  EXPECT_EQ(g.convergence_test, GapConvergenceTest::strict);
  ASSERT_EQ(g.elements.size(), 2U);
  EXPECT_EQ(g.elements[1].id, 12);
  EXPECT_EQ(g.elements[0].nodes, (std::array<int, 4>{6, 7, 1, 0}));
  EXPECT_DOUBLE_EQ(g.elements[0].angle_deg, 90.0);
  EXPECT_EQ(m.gap_count(), 2U);

  ASSERT_EQ(m.constraints.size(), 5U);
  EXPECT_EQ(m.constraints[0].node, 6);
  EXPECT_EQ(m.constraints[0].u_r, 0.0);
  EXPECT_EQ(m.constraints[0].u_z, 0.0);
  EXPECT_EQ(m.constraints[1].node, 7);
  EXPECT_FALSE(m.constraints[1].u_r.has_value());
  EXPECT_EQ(m.constraints[3].u_r, 0.0);
  EXPECT_FALSE(m.constraints[3].u_z.has_value());

  ASSERT_EQ(m.loads.nodal_forces.size(), 2U);
  EXPECT_EQ(m.loads.nodal_forces[0].node, 5);
  EXPECT_DOUBLE_EQ(m.loads.nodal_forces[0].f_r, 0.0);
  EXPECT_DOUBLE_EQ(m.loads.nodal_forces[0].f_z, -100.0);
  EXPECT_DOUBLE_EQ(m.loads.nodal_forces[1].f_r, 10.0);

  ASSERT_EQ(m.loads.pressures.size(), 2U);
  const EdgePressure& top = m.loads.pressures[0];
  EXPECT_EQ(top.element, 0);
  EXPECT_EQ(top.node_a, 4);  // user order kept: shear acts along a -> b
  EXPECT_EQ(top.node_b, 3);
  EXPECT_DOUBLE_EQ(top.normal, 1000.0);
  EXPECT_DOUBLE_EQ(top.shear, 0.0);
  const EdgePressure& side = m.loads.pressures[1];
  EXPECT_EQ(side.element, 2);
  EXPECT_EQ(side.node_a, 5);
  EXPECT_EQ(side.node_b, 9);
  EXPECT_DOUBLE_EQ(side.shear, 2.0);

  ASSERT_EQ(m.loads.node_temperature.size(), 11U);
  EXPECT_DOUBLE_EQ(m.loads.node_temperature[0], 200.0);
  for (std::size_t i = 1; i < 11; ++i) EXPECT_DOUBLE_EQ(m.loads.node_temperature[i], 100.0) << i;
  EXPECT_DOUBLE_EQ(m.loads.body_force.accel_z, -386.1);
  EXPECT_DOUBLE_EQ(m.loads.body_force.omega, 0.0);

  EXPECT_EQ(m.solver.max_iterations, 12);
  EXPECT_DOUBLE_EQ(m.solver.plastic_tolerance, 0.02);
  EXPECT_EQ(m.output.watch_elements, (std::vector<int>{1}));
  EXPECT_EQ(m.output.watch_gaps, (std::vector<int>{1}));
}

TEST(ModelReader, IsotropicRowsFillEveryDirectionAndTheShearModulus) {
  const Model m = read_model(valid_model());
  const Material& steel = m.materials[0];
  EXPECT_EQ(steel.id, 1);
  EXPECT_EQ(steel.name, "steel");
  EXPECT_DOUBLE_EQ(steel.density, 0.283);
  EXPECT_TRUE(steel.isotropic);
  ASSERT_EQ(steel.table.size(), 2U);
  const PropertyRow& hot = steel.table[1];
  EXPECT_DOUBLE_EQ(hot.T, 1000.0);
  for (const double E : {hot.E1, hot.E2, hot.E3}) EXPECT_DOUBLE_EQ(E, 25e6);
  for (const double nu : {hot.nu12, hot.nu13, hot.nu23}) EXPECT_DOUBLE_EQ(nu, 0.32);
  for (const double alpha : {hot.alpha1, hot.alpha2, hot.alpha3}) EXPECT_DOUBLE_EQ(alpha, 8e-6);
  EXPECT_DOUBLE_EQ(hot.G12, 25e6 / (2.0 * 1.32));
  ASSERT_EQ(steel.compression_table.size(), 1U);
  EXPECT_DOUBLE_EQ(steel.compression_table[0].E3, 31e6);
  ASSERT_EQ(steel.plasticity.size(), 1U);  // the object form: one curve, T = 0
  EXPECT_DOUBLE_EQ(steel.plasticity[0].T, 0.0);
  EXPECT_DOUBLE_EQ(steel.plasticity[0].yield_stress, 40000.0);
  EXPECT_DOUBLE_EQ(steel.plasticity[0].hardening_ratio, 0.1);

  const Material& composite = m.materials[1];
  EXPECT_FALSE(composite.isotropic);
  EXPECT_TRUE(composite.name.empty());
  ASSERT_EQ(composite.table.size(), 1U);
  const PropertyRow& row = composite.table[0];
  EXPECT_DOUBLE_EQ(row.E1, 20e6);
  EXPECT_DOUBLE_EQ(row.E2, 10e6);
  EXPECT_DOUBLE_EQ(row.nu23, 0.3);
  EXPECT_DOUBLE_EQ(row.G12, 5e6);
  EXPECT_DOUBLE_EQ(row.alpha3, 3e-6);
  EXPECT_TRUE(composite.compression_table.empty());
  ASSERT_EQ(composite.plasticity.size(), 2U);
  EXPECT_DOUBLE_EQ(composite.plasticity[1].T, 500.0);
  EXPECT_DOUBLE_EQ(composite.plasticity[1].hardening_ratio, 0.2);
}

TEST(ModelReader, AbsentOptionalKeysTakeTheirDefaults) {
  const Model m = read_model(minimal_model());
  EXPECT_EQ(m.analysis, AnalysisType::plane_strain);
  EXPECT_DOUBLE_EQ(m.thickness, 1.0);
  EXPECT_DOUBLE_EQ(m.reference_temperature, 0.0);
  EXPECT_TRUE(m.description.empty());
  EXPECT_FALSE(m.gaps.has_value());
  EXPECT_DOUBLE_EQ(m.elements[0].angle_deg, 0.0);
  EXPECT_DOUBLE_EQ(m.materials[0].density, 0.0);
  EXPECT_TRUE(m.materials[0].plasticity.empty());
  EXPECT_TRUE(m.loads.nodal_forces.empty());
  EXPECT_TRUE(m.loads.pressures.empty());
  EXPECT_EQ(m.solver.max_iterations, 30);
  EXPECT_DOUBLE_EQ(m.solver.plastic_tolerance, 0.01);
  EXPECT_TRUE(m.output.watch_elements.empty());

  json gaps = valid_model();
  for (const char* key : {"extrapolation_factor", "closure_tolerance", "shear_ratio", "convergence_test"}) {
    gaps["gaps"].erase(key);
  }
  const GapSettings g = *read_model(gaps).gaps;
  EXPECT_DOUBLE_EQ(g.extrapolation_factor, 0.0);
  EXPECT_DOUBLE_EQ(g.closure_tolerance, 0.05);
  EXPECT_DOUBLE_EQ(g.shear_ratio, 1e-6);
  EXPECT_EQ(g.convergence_test, GapConvergenceTest::report);
  EXPECT_EQ(g.method, GapMethod::classic);
  EXPECT_TRUE(read_model(gaps).units.stress.empty());
}

TEST(ModelReader, ReadsTheGapMethodAndTheUnitNames) {
  json doc = with(valid_model(), "/gaps/method", "exact");
  doc["units"] = {{"length", "mm"}, {"force", "N"}, {"stress", "MPa"}, {"temperature", "degC"}};
  const Model m = read_model(doc);
  EXPECT_EQ(m.gaps->method, GapMethod::exact);
  EXPECT_EQ(m.units.length, "mm");
  EXPECT_EQ(m.units.force, "N");
  EXPECT_EQ(m.units.stress, "MPa");
  EXPECT_EQ(m.units.temperature, "degC");

  json some = valid_model();
  some["units"] = {{"stress", "psi"}};
  const Model partial = read_model(some);
  EXPECT_EQ(partial.units.stress, "psi");
  EXPECT_TRUE(partial.units.length.empty());
}

TEST(ModelReader, TemperatureDefaultIsTheReferenceTemperatureSoNoLoadMeansNoThermalStrain) {
  const Model plain = read_model(with(minimal_model(), "/analysis/reference_temperature", 70));
  EXPECT_EQ(plain.loads.node_temperature, (std::vector<double>{70.0, 70.0, 70.0}));
  const Model nodal_only =
      read_model(with(with(minimal_model(), "/analysis/reference_temperature", 70), "/loads",
                      json::parse(R"({"temperatures": {"nodal": [{"node": 2, "T": 300}]}})")));
  EXPECT_EQ(nodal_only.loads.node_temperature, (std::vector<double>{70.0, 300.0, 70.0}));
}

TEST(ModelReader, ANodeNoElementUsesIsNotAnError) {
  // Node 11 of the valid model is used by no element (only constrained): the solver judges it.
  const Model m = read_model(valid_model());
  EXPECT_EQ(m.nodes.back().id, 11);
  EXPECT_NO_THROW((void)read_model(with(minimal_model(), "/nodes/3", json::parse(R"({"id": 4, "r": 9, "z": 9})"))));
}

TEST(ModelReader, ParseModelReadsText) {
  const Model m = parse_model(valid_model().dump(2));
  EXPECT_EQ(m.elements.size(), 3U);
}

// ------------------------------------------------------------------------------------------------
// Document structure

TEST(ModelReaderRules, DocumentMustBeAnObject) {
  EXPECT_TRUE(rejects(json::array({1, 2}), "", {"object", "[1, 2]"}));
  EXPECT_TRUE(rejects(json(nullptr), "", {"null"}));
}

TEST(ModelReaderRules, UnknownKeysAreErrorsAtTheirOwnPointer) {
  EXPECT_TRUE(rejects(with(valid_model(), "/extra", 1), "/extra", {"\"extra\"", "schema_version"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/nodes/0/x", 1), "/nodes/0/x", {"\"x\"", "id, r, z"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/body_force/g", 1), "/loads/body_force/g", {"\"g\""}));
  // Pointer tokens are escaped (RFC 6901).
  EXPECT_TRUE(rejects(with(valid_model(), "/analysis/a~1b~0c", 1), "/analysis/a~1b~0c", {"\"a/b~c\""}));
}

TEST(ModelReaderRules, MissingRequiredKeysAreReportedAtTheParent) {
  EXPECT_TRUE(rejects(without(valid_model(), "/title"), "", {"missing", "\"title\""}));
  EXPECT_TRUE(rejects(without(valid_model(), "/constraints"), "", {"\"constraints\""}));
  EXPECT_TRUE(rejects(without(valid_model(), "/nodes/2/z"), "/nodes/2", {"\"z\""}));
  EXPECT_TRUE(rejects(without(valid_model(), "/materials/0/table/0/alpha"), "/materials/0/table/0", {"\"alpha\""}));
  EXPECT_TRUE(rejects(without(valid_model(), "/gaps/initial_modulus"), "/gaps", {"\"initial_modulus\""}));
}

TEST(ModelReaderRules, SchemaVersionMustBeTheInteger1) {
  EXPECT_TRUE(rejects(with(valid_model(), "/schema_version", 2), "/schema_version", {"2"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/schema_version", 1.0), "/schema_version", {"1.0"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/schema_version", "1"), "/schema_version", {"\"1\""}));
}

TEST(ModelReaderRules, TitleAndDescriptionAreStrings) {
  EXPECT_TRUE(rejects(with(valid_model(), "/title", 5), "/title", {"string", "5"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/description", nullptr), "/description", {"null"}));
}

TEST(ModelReaderRules, NodesMaterialsAndElementsMustBeNonEmptyArrays) {
  EXPECT_TRUE(rejects(with(valid_model(), "/nodes", json::array()), "/nodes", {"empty"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials", json::object()), "/materials", {"array", "{}"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/elements", json::array()), "/elements", {"empty"}));
}

// ------------------------------------------------------------------------------------------------
// analysis

TEST(ModelReaderRules, AnalysisTypeIsOneOfThree) {
  EXPECT_TRUE(rejects(with(valid_model(), "/analysis/type", "plane"), "/analysis/type",
                      {"\"plane\"", "plane_stress, plane_strain, axisymmetric"}));
}

TEST(ModelReaderRules, ThicknessIsPositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/analysis/thickness", 0), "/analysis/thickness", {"thickness = 0", "> 0"}));
}

TEST(ModelReaderRules, ThicknessIsOnlyForPlaneAnalyses) {
  const json axisymmetric = with(valid_model(), "/analysis/type", "axisymmetric");
  EXPECT_TRUE(rejects(axisymmetric, "/analysis/thickness", {"0.5", "plane"}));
  EXPECT_NO_THROW((void)read_model(without(axisymmetric, "/analysis/thickness")));
}

TEST(ModelReaderRules, ReferenceTemperatureIsANumber) {
  EXPECT_TRUE(rejects(with(valid_model(), "/analysis/reference_temperature", "70F"),
                      "/analysis/reference_temperature", {"\"70F\""}));
}

// ------------------------------------------------------------------------------------------------
// ids and references

TEST(ModelReaderRules, IdsArePositiveJsonIntegers) {
  const json model = valid_model();
  EXPECT_TRUE(rejects(with(model, "/nodes/0/id", 0), "/nodes/0/id", {"id = 0", "1 <= id"}));
  EXPECT_TRUE(rejects(with(model, "/nodes/0/id", -3), "/nodes/0/id", {"-3"}));
  EXPECT_TRUE(rejects(with(model, "/nodes/0/id", 1.5), "/nodes/0/id", {"integer", "1.5"}));
  EXPECT_TRUE(rejects(with(model, "/nodes/0/id", 1.0), "/nodes/0/id", {"integer", "1.0", "write 1"}));
  EXPECT_TRUE(rejects(with(model, "/nodes/0/id", "1"), "/nodes/0/id", {"\"1\""}));
  EXPECT_TRUE(rejects(with(model, "/nodes/0/id", true), "/nodes/0/id", {"true"}));
  EXPECT_TRUE(rejects(with(model, "/materials/1/id", 2147483648U), "/materials/1/id", {"2147483648"}));
  EXPECT_TRUE(rejects(with(model, "/elements/0/id", 18446744073709551615U), "/elements/0/id",
                      {"18446744073709551615"}));
}

TEST(ModelReaderRules, NodeIdsAreUnique) {
  EXPECT_TRUE(rejects(with(valid_model(), "/nodes/1/id", 1), "/nodes/1/id", {"node id 1", "/nodes/0"}));
}

TEST(ModelReaderRules, ElementIdsAreUniqueAcrossElementsAndGapElements) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/1/id", 1), "/elements/1/id", {"element id 1", "/elements/0"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/elements/0/id", 3), "/gaps/elements/0/id",
                      {"element id 3", "/elements/2"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/elements/1/id", 11), "/gaps/elements/1/id",
                      {"element id 11", "/gaps/elements/0"}));
}

TEST(ModelReaderRules, MaterialIdsAreUnique) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/id", 1), "/materials/1/id", {"material id 1", "/materials/0"}));
}

TEST(ModelReaderRules, ElementNodesMustBeDefined) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/nodes/2", 99), "/elements/0/nodes/2", {"node 99"}));
}

TEST(ModelReaderRules, ElementMaterialMustBeDefined) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/material", 9), "/elements/0/material", {"material 9"}));
}

TEST(ModelReaderRules, GapElementNodesMustBeDefined) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/elements/1/nodes/0", 99), "/gaps/elements/1/nodes/0", {"99"}));
}

TEST(ModelReaderRules, ConstraintNodeMustBeDefined) {
  EXPECT_TRUE(rejects(with(valid_model(), "/constraints/0/node", 99), "/constraints/0/node", {"99"}));
}

TEST(ModelReaderRules, NodalForceNodeMustBeDefined) {
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/nodal_forces/1/node", 99), "/loads/nodal_forces/1/node", {"99"}));
}

TEST(ModelReaderRules, TemperatureNodeMustBeDefined) {
  EXPECT_TRUE(
      rejects(with(valid_model(), "/loads/temperatures/nodal/0/node", 99), "/loads/temperatures/nodal/0/node", {"99"}));
}

TEST(ModelReaderRules, WatchElementsAreSolidElementIds) {
  EXPECT_TRUE(rejects(with(valid_model(), "/output/watch_elements/0", 99), "/output/watch_elements/0", {"99"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/output/watch_elements/0", 11), "/output/watch_elements/0",
                      {"11", "gap element", "watch_gaps"}));
}

TEST(ModelReaderRules, WatchGapsAreGapElementIds) {
  EXPECT_TRUE(rejects(with(valid_model(), "/output/watch_gaps/0", 2), "/output/watch_gaps/0",
                      {"2", "solid element", "watch_elements"}));
  EXPECT_TRUE(rejects(with(minimal_model(), "/output", json::parse(R"({"watch_gaps": [5]})")), "/output/watch_gaps/0",
                      {"5"}));
}

TEST(ModelReaderRules, WatchListsDoNotRepeatAnId) {
  EXPECT_TRUE(rejects(with(valid_model(), "/output/watch_elements/1", 2), "/output/watch_elements/1",
                      {"2", "/output/watch_elements/0"}));
}

// ------------------------------------------------------------------------------------------------
// elements and gap elements

TEST(ModelReaderRules, ElementsHaveTheNodeCountOfAFamily) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/nodes", json::array({1, 2})), "/elements/0/nodes",
                      {"[1, 2]", "3, 4, 6, 8 or 9 nodes"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/nodes", json::array({1, 2, 5, 4, 3})), "/elements/0/nodes",
                      {"[1, 2, 5, 4, 3]"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/elements/0/nodes", json::array({7, 8})), "/gaps/elements/0/nodes",
                      {"[7, 8]"}));
}

TEST(ModelReaderRules, ElementNodesAreDistinct) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/nodes", json::array({1, 2, 2, 4})), "/elements/0/nodes/2",
                      {"node 2", "[1, 2, 2, 4]", "distinct"}));
}

TEST(ModelReaderRules, ClockwiseElementIsAnErrorNotFlipped) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/nodes", json::array({4, 5, 2, 1})), "/elements/0/nodes",
                      {"[4, 5, 2, 1]", "clockwise", "signed area -1.0", "[1, 2, 5, 4]"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/2/nodes", json::array({3, 6, 10})), "/elements/2/nodes",
                      {"[3, 6, 10]", "clockwise", "-0.5"}));
}

TEST(ModelReaderRules, TriangleNeedsPositiveArea) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/2/nodes", json::array({1, 2, 3})), "/elements/2/nodes",
                      {"[1, 2, 3]", "collinear"}));
}

TEST(ModelReaderRules, QuadrilateralMustBeConvexEnoughForTheSaasElement) {
  // Corners 3 and 4 swapped: a bow tie.
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/0/nodes", json::array({1, 2, 4, 5})), "/elements/0/nodes",
                      {"[1, 2, 4, 5]", "convex", "centre"}));
  // A dart: node 5 pulled in towards node 1 leaves a triangle around the centre with negative area.
  json dart = with(valid_model(), "/nodes/4/r", 0.1);
  dart["nodes"][4]["z"] = 0.1;
  EXPECT_TRUE(rejects(dart, "/elements/0/nodes", {"[1, 2, 5, 4]", "convex"}));
}

TEST(ModelReaderRules, ElementAngleIsAnOptionalNumber) {
  EXPECT_TRUE(rejects(with(valid_model(), "/elements/1/angle", "30"), "/elements/1/angle", {"\"30\""}));
}

TEST(ModelReaderRules, GapElementAngleIsRequired) {
  EXPECT_TRUE(rejects(without(valid_model(), "/gaps/elements/0/angle"), "/gaps/elements/0", {"\"angle\""}));
}

TEST(ModelReaderRules, GapElementsMustBeCounterClockwise) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/elements/0/nodes", json::array({1, 2, 8, 7})),
                      "/gaps/elements/0/nodes", {"[1, 2, 8, 7]", "clockwise"}));
}

TEST(ModelReaderRules, AxisymmetricNodesHaveNonNegativeRadius) {
  json model = without(with(valid_model(), "/analysis/type", "axisymmetric"), "/analysis/thickness");
  EXPECT_NO_THROW((void)read_model(model));
  model["nodes"][10]["r"] = -1;
  EXPECT_TRUE(rejects(model, "/nodes/10/r", {"r = -1", "r >= 0"}));
  // Plane analyses may use any r.
  EXPECT_NO_THROW((void)read_model(with(valid_model(), "/nodes/10/r", -1)));
}

TEST(ModelReaderRules, NumbersAreFinite) {
  // nlohmann's parser refuses 1e400 (out of range of a double): it is reported at its pointer.
  std::string text = valid_model().dump();
  const std::string node = R"({"id":2,"r":1,"z":0})";
  text.replace(text.find(node), node.size(), R"({"id":2,"r":1e400,"z":0})");
  EXPECT_TRUE(has_issue(issues_of_text(text), "/nodes/1/r", {"1e400", "finite"}));
  // A document built in memory can hold inf and nan.
  EXPECT_TRUE(rejects(with(valid_model(), "/nodes/1/r", std::numeric_limits<double>::infinity()), "/nodes/1/r",
                      {"inf", "finite"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/normal", std::nan("")), "/loads/pressures/0/normal",
                      {"nan"}));
}

// ------------------------------------------------------------------------------------------------
// materials

TEST(ModelReaderRules, ElasticIsIsotropicOrOrthotropic) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/elastic", "anisotropic"), "/materials/0/elastic",
                      {"\"anisotropic\"", "isotropic, orthotropic"}));
}

TEST(ModelReaderRules, TableIsNotEmpty) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table", json::array()), "/materials/0/table", {"empty"}));
}

TEST(ModelReaderRules, TableRowsAreInStrictlyIncreasingT) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/1/T", -50), "/materials/0/table/1/T",
                      {"T = -50", "T = 0", "increasing"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/1/T", 0), "/materials/0/table/1/T", {"T = 0"}));
  // The order is judged even when another value of the earlier row is bad.
  const auto issues = issues_of(with(with(valid_model(), "/materials/0/table/0/nu", 0.7), "/materials/0/table/1/T", -5));
  EXPECT_TRUE(has_issue(issues, "/materials/0/table/0/nu", {"0.7"}));
  EXPECT_TRUE(has_issue(issues, "/materials/0/table/1/T", {"T = -5", "T = 0"}));
}

TEST(ModelReaderRules, IsotropicRowsHaveExactlyTEnuAlpha) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/0/E1", 1), "/materials/0/table/0/E1",
                      {"\"E1\"", "T, E, nu, alpha"}));
}

TEST(ModelReaderRules, YoungsModulusIsPositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/1/E", 0), "/materials/0/table/1/E", {"E = 0", "1e-30 <= E <= 1e+30"}));
  // Beyond the arithmetic of the material law: an error at the modulus, not "not restrained" from
  // the factorization of a stiffness that overflowed (issue 22).
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/1/E", 1e300), "/materials/0/table/1/E",
                      {"E = 1e+300", "1e-30 <= E <= 1e+30", "overflow"}));
}

TEST(ModelReaderRules, IsotropicPoissonRatioIsBetweenMinus1AndHalf) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/0/nu", 0.5), "/materials/0/table/0/nu",
                      {"nu = 0.5", "-1 < nu < 0.5"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/table/0/nu", -1), "/materials/0/table/0/nu", {"nu = -1"}));
  EXPECT_NO_THROW((void)read_model(with(valid_model(), "/materials/0/table/0/nu", 0.49)));
}

TEST(ModelReaderRules, OrthotropicRowsHaveTheirElevenKeys) {
  EXPECT_TRUE(rejects(without(valid_model(), "/materials/1/table/0/G12"), "/materials/1/table/0", {"\"G12\""}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/table/0/E", 1), "/materials/1/table/0/E", {"\"E\""}));
}

TEST(ModelReaderRules, OrthotropicModuliArePositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/table/0/E2", -1), "/materials/1/table/0/E2", {"E2 = -1"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/table/0/G12", 0), "/materials/1/table/0/G12", {"G12 = 0"}));
}

TEST(ModelReaderRules, OrthotropicComplianceIsPositiveDefinite) {
  // nu12^2 = 2.25 > E1/E2 = 2.
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/table/0/nu12", 1.5), "/materials/1/table/0",
                      {"positive definite", "nu12 = 1.5"}));
}

TEST(ModelReaderRules, CompressionTableHasTheSameRowsAndMayBeEmpty) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/compression_table/0/E1", 1),
                      "/materials/0/compression_table/0/E1", {"\"E1\""}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/compression_table/0/nu", 0.6),
                      "/materials/0/compression_table/0/nu", {"0.6"}));
  const Model m = read_model(with(valid_model(), "/materials/0/compression_table", json::array()));
  EXPECT_TRUE(m.materials[0].compression_table.empty());
}

TEST(ModelReaderRules, DensityIsNonNegative) {
  EXPECT_TRUE(
      rejects(with(valid_model(), "/materials/0/density", -1), "/materials/0/density", {"density = -1", ">= 0"}));
}

TEST(ModelReaderRules, MaterialNameIsAString) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/name", 5), "/materials/0/name", {"5"}));
}

TEST(ModelReaderRules, PlasticityCurveHasPositiveYieldAndHardeningBelow1) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/plasticity/yield_stress", 0),
                      "/materials/0/plasticity/yield_stress", {"yield_stress = 0"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/plasticity/hardening_ratio", 1),
                      "/materials/0/plasticity/hardening_ratio", {"hardening_ratio = 1", "0 <= hardening_ratio < 1"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/plasticity/hardening_ratio", -0.1),
                      "/materials/0/plasticity/hardening_ratio", {"-0.1"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/plasticity/T", 0), "/materials/0/plasticity/T", {"\"T\""}));
}

TEST(ModelReaderRules, PlasticityTableIsNonEmptyAndSortedByT) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/plasticity", json::array()), "/materials/1/plasticity",
                      {"empty"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/plasticity/1/T", -5), "/materials/1/plasticity/1/T",
                      {"T = -5"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/1/plasticity/1/hardening_ratio", 1.5),
                      "/materials/1/plasticity/1/hardening_ratio", {"1.5"}));
}

TEST(ModelReaderRules, PlasticityIsAnObjectOrAnArray) {
  EXPECT_TRUE(rejects(with(valid_model(), "/materials/0/plasticity", "bilinear"), "/materials/0/plasticity",
                      {"\"bilinear\"", "object", "array"}));
}

// ------------------------------------------------------------------------------------------------
// gaps

TEST(ModelReaderRules, GapInitialModulusIsPositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/initial_modulus", 0), "/gaps/initial_modulus", {"initial_modulus = 0"}));
}

TEST(ModelReaderRules, TensileScheduleIsNonEmptyAndPositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/tensile_schedule", json::array()), "/gaps/tensile_schedule",
                      {"empty"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/tensile_schedule/1", -5), "/gaps/tensile_schedule/1", {"-5", "> 0"}));
}

TEST(ModelReaderRules, ExtrapolationFactorIsInZeroToOne) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/extrapolation_factor", 1), "/gaps/extrapolation_factor",
                      {"extrapolation_factor = 1", "0 <= extrapolation_factor < 1"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/extrapolation_factor", -0.1), "/gaps/extrapolation_factor", {"-0.1"}));
  EXPECT_NO_THROW((void)read_model(with(valid_model(), "/gaps/extrapolation_factor", 0)));
}

TEST(ModelReaderRules, ClosureToleranceIsBetweenZeroAndOne) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/closure_tolerance", 0), "/gaps/closure_tolerance", {"0 <"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/closure_tolerance", 1), "/gaps/closure_tolerance", {"= 1"}));
}

TEST(ModelReaderRules, ShearRatioIsPositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/shear_ratio", 0), "/gaps/shear_ratio", {"shear_ratio = 0"}));
}

TEST(ModelReaderRules, ConvergenceTestIsReportOrStrict) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/convergence_test", "lenient"), "/gaps/convergence_test",
                      {"\"lenient\"", "report, strict"}));
}

TEST(ModelReaderRules, GapMethodIsClassicOrExact) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/method", "penalty"), "/gaps/method", {"\"penalty\"", "classic, exact"}));
}

TEST(ModelReaderRules, UnitsAreNamedByNonEmptyStrings) {
  json doc = valid_model();
  doc["units"] = {{"stress", ""}};
  EXPECT_TRUE(rejects(doc, "/units/stress", {"non-empty"}));
  doc["units"] = {{"length", 1}};
  EXPECT_TRUE(rejects(doc, "/units/length", {"string"}));
  doc["units"] = {{"time", "s"}};
  EXPECT_TRUE(rejects(doc, "/units/time", {"time"}));
  doc["units"] = "psi";
  EXPECT_TRUE(rejects(doc, "/units", {}));
}

TEST(ModelReaderRules, GapElementsAreNonEmpty) {
  EXPECT_TRUE(rejects(with(valid_model(), "/gaps/elements", json::array()), "/gaps/elements", {"empty"}));
}

TEST(ModelReaderRules, AGapsMAxisRunsAcrossItsLongSidesInBothMethods) {
  // Gap 11 is a horizontal strip 1 long and 0.01 thick (nodes 7-8 below, 1-2 above), M at 90 degrees.
  for (const char* method : {"classic", "exact"}) {
    const json doc = with(valid_model(), "/gaps/method", method);
    // angle 0 crosses the strip's 0.01 ends, one of them shared with gap 12: along the gap.
    EXPECT_TRUE(rejects(with(doc, "/gaps/elements/0/angle", 0), "/gaps/elements/0/angle",
                        {"angle 0 does not run across gap element 11: M crosses nodes 8-2 and 7-1",
                         "its edge 8-2 is also an edge of another gap element", "faces are nodes 7-8 and 1-2",
                         "angle 90 (or that plus or minus 180)"}))
        << method;
    // 45 degrees crosses no pair of opposite edges within 30 degrees.
    EXPECT_TRUE(rejects(with(doc, "/gaps/elements/1/angle", 45), "/gaps/elements/1/angle",
                        {"angle 45", "gap element 12", "within 30 degrees of perpendicular"}))
        << method;
    // Either way across, and up to 30 degrees off, is across.
    for (double angle : {-90.0, 270.0, 90.0 + 29.0}) {
      EXPECT_NO_THROW((void)read_model(with(doc, "/gaps/elements/0/angle", angle))) << method << " " << angle;
    }
  }
}

// ------------------------------------------------------------------------------------------------
// constraints

TEST(ModelReaderRules, ConstraintsMustNotBeEmpty) {
  EXPECT_TRUE(rejects(with(valid_model(), "/constraints", json::array()), "/constraints", {"rigid body"}));
}

TEST(ModelReaderRules, AConstraintPrescribesROrZ) {
  EXPECT_TRUE(rejects(with(valid_model(), "/constraints/3", json::parse(R"({"node": 1})")), "/constraints/3",
                      {"node 1", "neither r nor z"}));
}

TEST(ModelReaderRules, AComponentIsConstrainedOnce) {
  EXPECT_TRUE(rejects(with(valid_model(), "/constraints/5", json::parse(R"({"node": 8, "r": 0, "z": 0.5})")),
                      "/constraints/5/z", {"z of node 8", "/constraints/1/z"}));
}

// ------------------------------------------------------------------------------------------------
// loads

TEST(ModelReaderRules, PressureHasTwoDistinctNodes) {
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/nodes", json::array({4, 5, 6, 1})),
                      "/loads/pressures/0/nodes", {"[4, 5, 6, 1]", "2 nodes"}));
  // Three name a quadratic edge's mid-side node (element_family_reader_test.cpp); here 4 and 6 are
  // no edge.
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/nodes", json::array({4, 5, 6})),
                      "/loads/pressures/0/nodes", {"[4, 5, 6]", "end nodes"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/nodes", json::array({4, 4})),
                      "/loads/pressures/0/nodes/1", {"node 4", "[4, 4]"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/nodes/1", 99), "/loads/pressures/0/nodes/1", {"99"}));
}

TEST(ModelReaderRules, PressureEdgeMustBelongToASolidElement) {
  // A diagonal is no edge at all.
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/nodes", json::array({1, 5})),
                      "/loads/pressures/0/nodes", {"[1, 5]", "no solid element"}));
  // Edge 7-8 belongs to gap element 11 only: gaps carry no pressure.
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/1/nodes", json::array({8, 7})),
                      "/loads/pressures/1/nodes", {"[8, 7]", "gap elements carry no pressure"}));
  // Edge 2-3 is shared by solid element 2 and gap element 12: the solid one owns it.
  EXPECT_NO_THROW((void)read_model(with(valid_model(), "/loads/pressures/1/nodes", json::array({2, 3}))));
}

TEST(ModelReaderRules, PressureEdgeOfTwoElementsIsAnError) {
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/nodes", json::array({5, 2})),
                      "/loads/pressures/0/nodes", {"[5, 2]", "elements 1 and 2"}));
}

TEST(ModelReaderRules, PressureValuesAreNumbers) {
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/pressures/0/shear", "0"), "/loads/pressures/0/shear", {"\"0\""}));
}

TEST(ModelReaderRules, ANodeHasOneTemperature) {
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/temperatures/nodal/1", json::parse(R"({"node": 1, "T": 300})")),
                      "/loads/temperatures/nodal/1/node", {"node 1", "/loads/temperatures/nodal/0"}));
}

TEST(ModelReaderRules, OmegaOnlyForAxisymmetricAnalyses) {
  EXPECT_TRUE(rejects(with(valid_model(), "/loads/body_force/omega", 10), "/loads/body_force/omega",
                      {"omega = 10", "plane_stress"}));
  EXPECT_NO_THROW((void)read_model(with(valid_model(), "/loads/body_force/omega", 0)));
  json spinning = without(with(valid_model(), "/analysis/type", "axisymmetric"), "/analysis/thickness");
  spinning["loads"]["body_force"]["omega"] = 10;
  EXPECT_DOUBLE_EQ(read_model(spinning).loads.body_force.omega, 10.0);
}

TEST(ModelReaderRules, BodyForceValuesAreNumbers) {
  EXPECT_TRUE(
      rejects(with(valid_model(), "/loads/body_force/accel_z", nullptr), "/loads/body_force/accel_z", {"null"}));
}

// ------------------------------------------------------------------------------------------------
// solver and output

TEST(ModelReaderRules, MaxIterationsIsAnIntegerOfAtLeast1) {
  EXPECT_TRUE(rejects(with(valid_model(), "/solver/max_iterations", 0), "/solver/max_iterations",
                      {"max_iterations = 0"}));
  EXPECT_TRUE(rejects(with(valid_model(), "/solver/max_iterations", 2.5), "/solver/max_iterations",
                      {"integer", "2.5"}));
}

TEST(ModelReaderRules, PlasticToleranceIsPositive) {
  EXPECT_TRUE(rejects(with(valid_model(), "/solver/plastic_tolerance", 0), "/solver/plastic_tolerance",
                      {"plastic_tolerance = 0"}));
}

TEST(ModelReaderRules, WatchListsAreArrays) {
  EXPECT_TRUE(rejects(with(valid_model(), "/output/watch_gaps", 12), "/output/watch_gaps", {"array", "12"}));
}

// ------------------------------------------------------------------------------------------------
// Text

TEST(ModelReaderRules, InvalidJsonIsOneIssueAtTheRootWithTheBytePosition) {
  const auto issues = issues_of_text(R"({"schema_version": 1,})");
  ASSERT_EQ(issues.size(), 1U) << listing(issues);
  EXPECT_TRUE(has_issue(issues, "", {"not valid JSON", "byte 22"}));
}

TEST(ModelReaderRules, RepeatedKeysAreErrors) {
  std::string text = valid_model().dump();
  const std::string node = R"({"id":3,"r":2,"z":0})";
  text.replace(text.find(node), node.size(), R"({"id":3,"r":2,"z":0,"r":2})");
  const auto issues = issues_of_text(text);
  EXPECT_TRUE(has_issue(issues, "/nodes/2/r", {"\"r\"", "more than once"}));
  ASSERT_EQ(issues.size(), 1U) << listing(issues);
}

TEST(ModelReader, StreamedDigestIsTheDigestOfTheTree) {
  json orthotropic_only = valid_model();
  orthotropic_only["title"] = "another title";  // title, description and output do not count
  for (const json& document : {valid_model(), minimal_model(), orthotropic_only}) {
    for (const std::string& text : {document.dump(), document.dump(2), in_contract_order(document)}) {
      std::string digest;
      (void)parse_model(text, &digest);
      EXPECT_EQ(digest, model_digest(document));
    }
  }
  EXPECT_EQ(model_digest(orthotropic_only), model_digest(valid_model()));
  EXPECT_NE(model_digest(with(valid_model(), "/nodes/0/r", 0.5)), model_digest(valid_model()));
}

TEST(ModelReaderRules, ParseDocumentRejectsWhatTheTextAloneShows) {
  EXPECT_EQ(parse_document(R"({"a": [1, 2]})"), json::parse(R"({"a": [1, 2]})"));
  const auto issues_of_document = [](const std::string& text) {
    try {
      (void)parse_document(text);
    } catch (const ModelError& e) {
      return e.issues();
    }
    return std::vector<InputIssue>{};
  };
  EXPECT_TRUE(has_issue(issues_of_document(R"({"a": {"b": 1, "b": 2}})"), "/a/b", {"\"b\""}));
  EXPECT_TRUE(has_issue(issues_of_document(R"({"a": [0, {"c": [1, -1e999]}]})"), "/a/1/c/1", {"-1e999"}));
  EXPECT_TRUE(has_issue(issues_of_document("[1"), "", {"byte 3", "end of input"}));
}

// ------------------------------------------------------------------------------------------------
// Every issue, and no crash

TEST(ModelReader, ReportsEveryIndependentIssue) {
  json model = valid_model();
  model["nodes"][0]["r"] = "x";
  model["materials"][0]["table"][0]["nu"] = 0.7;
  model["elements"][2]["material"] = 42;
  model["gaps"]["extrapolation_factor"] = 1;
  model["loads"]["pressures"][0]["nodes"] = json::array({1, 5});
  const auto issues = issues_of(model);
  EXPECT_TRUE(has_issue(issues, "/nodes/0/r", {"\"x\""}));
  EXPECT_TRUE(has_issue(issues, "/materials/0/table/0/nu", {"0.7"}));
  EXPECT_TRUE(has_issue(issues, "/elements/2/material", {"42"}));
  EXPECT_TRUE(has_issue(issues, "/gaps/extrapolation_factor", {"1"}));
  EXPECT_TRUE(has_issue(issues, "/loads/pressures/0/nodes", {"[1, 5]"}));
  EXPECT_EQ(issues.size(), 5U) << "no issue should follow from another:\n" << listing(issues);
}

/// Every value of the document, as a pointer (the root is "").
void collect_pointers(const json& value, const std::string& pointer, std::vector<std::string>& out) {
  out.push_back(pointer);
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) collect_pointers(*it, pointer_append(pointer, it.key()), out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) collect_pointers(value[i], pointer_append(pointer, i), out);
  }
}

bool same_kind(const json& a, const json& b) {
  return a.is_number() == b.is_number() && (a.is_number() || a.type() == b.type());
}

TEST(ModelReader, AnyValueOfTheWrongTypeAnywhereIsAModelErrorNeverACrash) {
  const json model = valid_model();
  std::vector<std::string> pointers;
  collect_pointers(model, "", pointers);
  const std::vector<json> replacements{nullptr,
                                       "text",
                                       json::array({1, 2}),
                                       json::object({{"x", 1}}),
                                       std::numeric_limits<double>::infinity(),
                                       true,
                                       -1,
                                       0,
                                       json::array()};
  int rejected = 0;
  for (const std::string& pointer : pointers) {
    const json original = model[json::json_pointer(pointer)];
    for (const json& replacement : replacements) {
      const json document = with(model, pointer, replacement);
      (void)issues_of(document);  // the streaming reader agrees with the tree reader
      try {
        (void)read_model(document);
        // Accepted: only a value of the same kind can be valid where the original was.
        EXPECT_TRUE(same_kind(original, replacement))
            << pointer << " = " << replacement.dump() << " was accepted in place of " << original.dump();
      } catch (const ModelError& e) {
        ++rejected;
        EXPECT_FALSE(e.issues().empty()) << pointer;
      } catch (const std::exception& e) {
        ADD_FAILURE() << pointer << " = " << replacement.dump() << " threw " << e.what();
      }
    }
    // Removing the key (or the item) must not crash either.
    if (!pointer.empty()) {
      const json::json_pointer p(pointer);
      json document = model;
      json& parent = document[p.parent_pointer()];
      if (parent.is_object()) {
        parent.erase(p.back());
      } else {
        parent.erase(std::stoul(p.back()));
      }
      (void)issues_of(document);
      try {
        (void)read_model(document);
      } catch (const ModelError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << "removing " << pointer << " threw " << e.what();
      }
    }
  }
  EXPECT_GT(rejected, 1000);
}

TEST(ModelReader, TruncatedTextIsAModelError) {
  const std::string text = valid_model().dump();
  for (std::size_t n = 0; n < text.size(); ++n) {
    EXPECT_THROW((void)parse_model(text.substr(0, n)), ModelError) << n;
  }
}

TEST(ModelReader, HugeAndDeepInputsAreModelErrors) {
  json many = valid_model();
  many["nodes"] = json::array();
  for (int i = 0; i < 100000; ++i) many["nodes"].push_back(nullptr);
  EXPECT_GE(issues_of(many).size(), 100000U);

  std::string deep = valid_model().dump();
  const std::string title = R"("reader test model")";
  deep.replace(deep.find(title), title.size(), std::string(100000, '[') + std::string(100000, ']'));
  // Deeper than io::max_json_depth: refused where the limit is hit (io/json_limits.hpp, issue 17).
  std::string limit_pointer = "/title";
  for (int k = 0; k < 63; ++k) limit_pointer += "/0";
  const auto issues = issues_of_text(deep);
  EXPECT_TRUE(has_issue(issues, limit_pointer, {"deeper than 64 levels"}));

  const std::string long_title(1000000, 'x');
  const auto long_issues = issues_of(with(valid_model(), "/nodes/0/r", long_title));
  ASSERT_EQ(long_issues.size(), 1U);
  EXPECT_LT(long_issues[0].detail.size(), 300U);

  EXPECT_THROW((void)parse_model(std::string("\xff\xfe garbage")), ModelError);
  EXPECT_THROW((void)parse_model(""), ModelError);
}

// ------------------------------------------------------------------------------------------------
// The streaming reader (simdjson's tape, io/simd_model_reader.hpp) against the tree reader on every
// example, on a corpus of mutated examples, and on text simdjson refuses

TEST(ModelReader, EveryExampleReadsFromTextAsFromItsTree) {
  const auto paths = example_models();
  ASSERT_GE(paths.size(), 10U);
  for (const auto& path : paths) {
    SCOPED_TRACE(path.filename().string());
    const std::string text = text_of(path);
    const json document = json::parse(text);
    EXPECT_TRUE(issues_of(document).empty());  // and the text of its dump and in contract order agree
    std::string digest;
    const Model streamed = parse_model(text, &digest);
    expect_same_model(streamed, read_model(document));
    EXPECT_EQ(digest, model_digest(document));
    EXPECT_EQ(parse_model(document.dump(2), &digest).nodes.size(), streamed.nodes.size());
    EXPECT_EQ(digest, model_digest(document));
  }
}

TEST(ModelReader, MutatedExamplesGiveTheIssuesOfTheTreeReader) {
  std::vector<json> seeds;
  for (const auto& path : example_models()) {
    const json document = json::parse(text_of(path));
    if (document.dump().size() < 200000) seeds.push_back(document);  // small ones: 600 mutations stay quick
  }
  ASSERT_GE(seeds.size(), 5U);
  std::mt19937 random(1976);
  int refused = 0;
  for (int k = 0; k < 600; ++k) {
    const json document = testing::mutate(seeds[static_cast<std::size_t>(k) % seeds.size()], random);
    // issues_of compares parse_model on the dump and in contract order with read_model.
    if (!issues_of(document).empty()) ++refused;
  }
  EXPECT_GT(refused, 300);
}

TEST(ModelReaderRules, TextTheFastParserRefusesIsJudgedAsBefore) {
  const std::string text = in_contract_order(valid_model());
  // A byte order mark: nlohmann's parser skips it, so the model reads.
  std::string digest;
  EXPECT_EQ(parse_model("\xEF\xBB\xBF" + text, &digest).nodes.size(), 11U);
  EXPECT_EQ(digest, model_digest(valid_model()));
  // An integer beyond 64 bits is a double to nlohmann: an id "must be an integer", as in the tree.
  std::string big = text;
  const std::string node = R"({"id":2,"r":1,"z":0})";
  big.replace(big.find(node), node.size(), R"({"id":18446744073709551616,"r":1,"z":0})");
  std::vector<InputIssue> tree_issues;
  try {
    (void)read_model(json::parse(big));
  } catch (const ModelError& e) {
    tree_issues = e.issues();
  }
  EXPECT_TRUE(has_issue(tree_issues, "/nodes/1/id", {"must be an integer"}));
  EXPECT_TRUE(same_issues(issues_of_text(big), tree_issues)) << listing(issues_of_text(big));
  // Keys spelled with escapes are the same keys.
  std::string escaped = text;
  escaped.replace(escaped.find(node), node.size(), R"({"\u0069d":2,"r":1,"z":0})");
  EXPECT_NO_THROW((void)parse_model(escaped, &digest));
  EXPECT_EQ(digest, model_digest(valid_model()));
}

TEST(ModelReaderRules, RepeatedKeysAreFoundInEverySection) {
  std::string text = in_contract_order(valid_model());
  const std::string material = R"("density":0.283)";
  text.replace(text.find(material), material.size(), R"("density":0.283,"density":0.3)");
  text.insert(text.size() - 1, R"(,"extra":{"a":1,"a":2},"solver":{})");
  const auto issues = issues_of_text(text);
  EXPECT_TRUE(has_issue(issues, "/materials/0/density", {"\"density\"", "more than once"})) << listing(issues);
  EXPECT_TRUE(has_issue(issues, "/extra/a", {"\"a\"", "more than once"})) << listing(issues);
  EXPECT_TRUE(has_issue(issues, "/extra", {"unknown key"})) << listing(issues);
  EXPECT_TRUE(has_issue(issues, "/solver", {"\"solver\"", "more than once"})) << listing(issues);
  EXPECT_EQ(issues.size(), 4U) << listing(issues);
}

// ------------------------------------------------------------------------------------------------
// Load steps (the spec's third round): read into Model::steps, bad input at its pointer

json with_steps() {
  json m = valid_model();
  m["steps"] = json::parse(R"([
    {"name": "fit"},
    {"name": "push", "increments": 20,
     "loads": {"nodal_forces": [{"node": 6, "fz": -50}], "pressures": [{"nodes": [5, 4], "normal": 7}]},
     "constraints": [{"node": 5, "z": -0.002}, {"node": 7, "r": 0.001}]}
  ])");
  return m;
}

TEST(ModelReader, StepsAreReadWithTheirLoadsAndConstraints) {
  const Model m = read_model(with_steps());
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_EQ(m.steps[0].name, "fit");
  EXPECT_EQ(m.steps[0].increments, 1);
  EXPECT_FALSE(m.steps[0].loads.has_value());  // keeps the top-level loads
  EXPECT_TRUE(m.steps[0].constraints.empty());
  const Step& push = m.steps[1];
  EXPECT_EQ(push.increments, 20);
  ASSERT_TRUE(push.loads.has_value());
  ASSERT_EQ(push.loads->nodal_forces.size(), 1u);
  EXPECT_EQ(push.loads->nodal_forces[0].node, 5);
  EXPECT_EQ(push.loads->nodal_forces[0].f_z, -50.0);
  ASSERT_EQ(push.loads->pressures.size(), 1u);
  EXPECT_EQ(push.loads->pressures[0].element, 0);
  // What a step's loads omit is absent: no temperature load means the stress-free temperature.
  EXPECT_EQ(push.loads->node_temperature, std::vector<double>(11, 70.0));
  ASSERT_EQ(push.constraints.size(), 2u);
  EXPECT_EQ(push.constraints[0].node, 4);
  EXPECT_EQ(push.constraints[0].u_z, -0.002);
  EXPECT_FALSE(push.constraints[0].u_r.has_value());
  EXPECT_EQ(push.constraints[1].u_r, 0.001);
  // A model without steps has none.
  EXPECT_TRUE(read_model(valid_model()).steps.empty());
}

TEST(ModelReaderRules, StepsAreANonEmptyArrayOfNamedSteps) {
  EXPECT_TRUE(rejects(with(valid_model(), "/steps", json::array()), "/steps", {"steps"}));
  EXPECT_TRUE(rejects(without(with_steps(), "/steps/0/name"), "/steps/0", {"name"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/0/name", ""), "/steps/0/name", {"non-empty"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/name", "fit"), "/steps/1/name", {"\"fit\"", "/steps/0"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/0/repeat", 2), "/steps/0/repeat", {"repeat"}));
}

TEST(ModelReaderRules, StepIncrementsAreAtLeastOne) {
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/increments", 0), "/steps/1/increments", {"0"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/increments", 2.5), "/steps/1/increments", {"2.5"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/increments", 100001), "/steps/1/increments", {"100001"}));
}

TEST(ModelReaderRules, StepConstraintsNameDefinedNodesEachComponentOnce) {
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/constraints/0/node", 99), "/steps/1/constraints/0/node", {"99"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/constraints/1", json{{"node", 5}, {"z", 0.0}}),
                      "/steps/1/constraints/1/z", {"/steps/1/constraints/0/z"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/constraints/0", json{{"node", 5}}), "/steps/1/constraints/0",
                      {"neither r nor z"}));
  // A component a step prescribes may be one the top-level constraints also prescribe.
  EXPECT_NO_THROW(read_model(with(with_steps(), "/steps/1/constraints/1", json{{"node", 8}, {"z", 0.001}})));
}

TEST(ModelReaderRules, StepLoadsFollowTheRulesOfTheTopLevelLoads) {
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/loads/nodal_forces/0/node", 99),
                      "/steps/1/loads/nodal_forces/0/node", {"99"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/loads/pressures/0/nodes", json{1, 3}),
                      "/steps/1/loads/pressures/0/nodes", {"no solid element has the edge"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/loads/body_force", json{{"omega", 3}}),
                      "/steps/1/loads/body_force/omega", {"axisymmetric"}));
  EXPECT_TRUE(rejects(with(with_steps(), "/steps/1/loads/wind", 1), "/steps/1/loads/wind", {"wind"}));
}

TEST(ModelReader, StepsChangeTheModelDigestAndAModelWithoutThemKeepsIts) {
  const json plain = valid_model();
  EXPECT_NE(model_digest(with_steps()), model_digest(plain));
  std::string digest;
  (void)parse_model(with_steps().dump(), &digest);
  EXPECT_EQ(digest, model_digest(with_steps()));
}

// ------------------------------------------------------------------------------------------------
// Contact surfaces (the spec's third round): read into Model::contact, bad input at its pointer

json with_contact() {
  json m = valid_model();
  m["contact"] = json::parse(R"({
    "surfaces": [{"name": "top", "edges": [[5, 4], [6, 5]]}, {"name": "bottom", "edges": [[1, 2], [3, 2]]}],
    "pairs": [{"surfaces": ["top", "bottom"], "friction": 0,
               "conductance": {"closed": [{"p": 0, "h": 1}, {"p": 1000, "h": 8}], "gas_conductivity": 2e-4}},
              {"surfaces": ["bottom", "top"], "conductance": {"closed": 5}}]
  })");
  return m;
}

TEST(ModelReader, ContactSurfacesAndPairsAreRead) {
  const Model m = read_model(with_contact());
  ASSERT_TRUE(m.contact.has_value());
  ASSERT_EQ(m.contact->surfaces.size(), 2u);
  EXPECT_EQ(m.contact->surfaces[0].name, "top");
  const std::vector<std::array<int, 2>> top{{4, 3}, {5, 4}};  // node id k has index k - 1
  EXPECT_EQ(m.contact->surfaces[0].edges, top);
  ASSERT_EQ(m.contact->pairs.size(), 2u);
  EXPECT_EQ(m.contact->pairs[0].surfaces, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(m.contact->pairs[1].surfaces, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(m.contact->pairs[0].friction, 0.0);
  ASSERT_TRUE(m.contact->pairs[0].conductance.has_value());
  ASSERT_EQ(m.contact->pairs[0].conductance->closed.size(), 2u);
  EXPECT_EQ(m.contact->pairs[0].conductance->closed[1].p, 1000.0);
  EXPECT_EQ(m.contact->pairs[0].conductance->closed[1].h, 8.0);
  EXPECT_EQ(m.contact->pairs[0].conductance->gas_conductivity, 2e-4);
  // A number is a one-row table (held constant beyond its ends).
  ASSERT_EQ(m.contact->pairs[1].conductance->closed.size(), 1u);
  EXPECT_EQ(m.contact->pairs[1].conductance->closed[0].h, 5.0);
  EXPECT_EQ(m.contact->pairs[1].conductance->gas_conductivity, 0.0);
  EXPECT_FALSE(read_model(valid_model()).contact.has_value());
}

TEST(ModelReaderRules, ContactSurfaceEdgesAreBoundaryEdgesOfOneSolidElementInOneChain) {
  // 2-5 is the side elements 1 and 2 share; 1-5 a diagonal of element 1; 4-5 and 2-3 are not joined.
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges/1", json{2, 5}), "/contact/surfaces/0/edges/1",
                      {"not a boundary edge", "elements 1 and 2"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/1/edges/0", json{1, 5}), "/contact/surfaces/1/edges/0",
                      {"not a side of any solid element"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges/1", json{2, 3}), "/contact/surfaces/0/edges/1",
                      {"not connected"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges/1", json{4, 5}), "/contact/surfaces/0/edges/1",
                      {"same edge as edge 0"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges/1", json{5, 5}), "/contact/surfaces/0/edges/1",
                      {"same node"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges/0", json{5, 99}), "/contact/surfaces/0/edges/0/1",
                      {"99"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges/0", json{5}), "/contact/surfaces/0/edges/0",
                      {"two node ids"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/0/edges", json::array()), "/contact/surfaces/0/edges",
                      {"edges"}));
}

TEST(ModelReaderRules, ContactSurfaceNamesAreUniqueAndPairsNameTwoOfThem) {
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/1/name", "top"), "/contact/surfaces/1/name",
                      {"\"top\"", "/contact/surfaces/0"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/surfaces/1/name", ""), "/contact/surfaces/1/name", {"non-empty"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/surfaces/1", "side"), "/contact/pairs/0/surfaces/1",
                      {"\"side\"", "not defined"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/surfaces/1", "top"), "/contact/pairs/0/surfaces/1",
                      {"two different surfaces", "itself"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/surfaces", json{"top"}), "/contact/pairs/0/surfaces",
                      {"two surfaces"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/surfaces/0", 3), "/contact/pairs/0/surfaces/0",
                      {"string"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs", json::array()), "/contact/pairs", {"pairs"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/extra", 1), "/contact/extra", {"extra"}));
}

TEST(ModelReaderRules, FrictionIsANonNegativeNumberWithoutExactGapsAndConductanceIsChecked) {
  EXPECT_EQ(read_model(with(with_contact(), "/contact/pairs/0/friction", 0.15)).contact->pairs[0].friction, 0.15);
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/friction", -1), "/contact/pairs/0/friction", {"-1"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/friction", "0.2"), "/contact/pairs/0/friction",
                      {"\"0.2\""}));
  // Exact gaps solve the surfaces frictionless with their node pairs: friction is refused there.
  json exact = with(with(with_contact(), "/gaps/method", "exact"), "/contact/pairs/1/friction", 0.3);
  EXPECT_TRUE(rejects(exact, "/contact/pairs/1/friction", {"0.3", "\"classic\""}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/conductance/closed/1/p", 0),
                      "/contact/pairs/0/conductance/closed/1/p", {"increasing"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/conductance/closed/0/h", -1),
                      "/contact/pairs/0/conductance/closed/0/h", {"-1"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/1/conductance/closed", -5),
                      "/contact/pairs/1/conductance/closed", {"-5"}));
  EXPECT_TRUE(rejects(with(with_contact(), "/contact/pairs/0/conductance/gas_conductivity", "x"),
                      "/contact/pairs/0/conductance/gas_conductivity", {"gas_conductivity"}));
}

TEST(ModelReader, ContactChangesTheModelDigest) {
  EXPECT_NE(model_digest(with_contact()), model_digest(valid_model()));
}

// ------------------------------------------------------------------------------------------------
// Heat conduction (thermal section, k and c, gap conductance)

/// The minimal model with conductivity and a steady thermal section: edge 1-2 held at 500, a film
/// on edge 2-3, a source in material 1.
json with_thermal() {
  json m = with(minimal_model(), "/materials/0/table/0/k", 2.5);
  return with(m, "/thermal", json::parse(R"({
    "type": "steady",
    "boundary": [{"edges": [[1, 2]], "temperature": 500},
                 {"edges": [[3, 2]], "film": 0.5, "ambient": 70},
                 {"edges": [[3, 1]], "flux": 4}],
    "sources": [{"material": 1, "power_density": 1.5}]
  })"));
}

json transient(json m) {
  m = with(m, "/thermal/type", "transient");
  m = with(m, "/materials/0/table/0/c", 0.2);
  m = with(m, "/materials/0/density", 0.1);
  m = with(m, "/thermal/initial_temperature", 70);
  m = with(m, "/thermal/time_step", 0.5);
  return with(m, "/thermal/end_time", 10);
}

TEST(ModelReader, ThermalSectionAndConductivityAreRead) {
  const Model m = read_model(with_thermal());
  ASSERT_TRUE(m.thermal.has_value());
  EXPECT_TRUE(m.materials[0].conducts);
  EXPECT_FALSE(m.materials[0].stores_heat);
  EXPECT_EQ(m.materials[0].table[0].k1, 2.5);
  EXPECT_EQ(m.materials[0].table[0].k3, 2.5);
  ASSERT_EQ(m.thermal->boundary.size(), 3u);
  EXPECT_EQ(m.thermal->boundary[0].kind, ThermalBoundary::Kind::temperature);
  EXPECT_EQ(m.thermal->boundary[0].value, 500.0);
  EXPECT_EQ(m.thermal->boundary[1].kind, ThermalBoundary::Kind::film);
  EXPECT_EQ(m.thermal->boundary[1].ambient, 70.0);
  ASSERT_EQ(m.thermal->boundary[1].edges.size(), 1u);
  EXPECT_EQ(m.thermal->boundary[1].edges[0].node_a, 2);  // node id 3 is index 2
  EXPECT_EQ(m.thermal->boundary[2].kind, ThermalBoundary::Kind::flux);
  ASSERT_EQ(m.thermal->sources.size(), 1u);
  EXPECT_EQ(m.thermal->sources[0].power_density, 1.5);
  const Model t = read_model(transient(with_thermal()));
  EXPECT_EQ(t.thermal->type, ThermalType::transient);
  EXPECT_EQ(t.thermal->output_times, std::vector<double>{10.0});  // default: the end
  EXPECT_TRUE(t.materials[0].stores_heat);
  // Without thermal a model reads as before.
  EXPECT_FALSE(read_model(minimal_model()).thermal.has_value());
}

TEST(ModelReaderRules, ThermalExcludesGivenTemperatures) {
  EXPECT_TRUE(rejects(with(with_thermal(), "/loads", json::parse(R"({"temperatures": {"default": 90}})")),
                      "/loads/temperatures", {"/thermal", "remove one"}));
}

TEST(ModelReaderRules, ThermalNeedsPositiveConductivityInEveryRow) {
  EXPECT_TRUE(rejects(without(with_thermal(), "/materials/0/table/0/k"), "/materials/0/table",
                      {"material 1", "no conductivity"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/materials/0/table/0/k", -1.0), "/materials/0/table/0/k", {"-1", "> 0"}));
  json two_rows = with(with_thermal(), "/materials/0/table/1", json{{"T", 100}, {"E", 1e6}, {"nu", 0.25}, {"alpha", 0}});
  EXPECT_TRUE(rejects(two_rows, "/materials/0/table/1", {"every row"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/materials/0/compression_table",
                           json::parse(R"([{"T": 0, "E": 1e6, "nu": 0.25, "alpha": 0, "k": 3}])")),
                      "/materials/0/compression_table/0/k", {"belongs in table"}));
}

TEST(ModelReaderRules, TransientNeedsSpecificHeatAndDensity) {
  EXPECT_TRUE(rejects(without(transient(with_thermal()), "/materials/0/table/0/c"), "/materials/0/table",
                      {"specific heat"}));
  EXPECT_TRUE(rejects(without(transient(with_thermal()), "/materials/0/density"), "/materials/0", {"density"}));
  EXPECT_TRUE(rejects(without(transient(with_thermal()), "/thermal/time_step"), "/thermal", {"time_step"}));
  EXPECT_TRUE(rejects(with(transient(with_thermal()), "/thermal/output_times", json{5, 3}), "/thermal/output_times/1",
                      {"strictly increasing"}));
  EXPECT_TRUE(rejects(with(transient(with_thermal()), "/thermal/output_times", json{12}), "/thermal/output_times/0",
                      {"after end_time"}));
  // A step that does not divide the output times is not an error: the run lands on each exactly.
  EXPECT_NO_THROW((void)read_model(with(transient(with_thermal()), "/thermal/output_times", json{0.7, 5.75})));
}

TEST(ModelReaderRules, SteadyThermalNeedsATemperatureOrAFilm) {
  json flux_only = with(with_thermal(), "/thermal/boundary", json::parse(R"([{"edges": [[3, 1]], "flux": 4}])"));
  EXPECT_TRUE(rejects(flux_only, "/thermal/boundary", {"singular"}));
  EXPECT_TRUE(rejects(without(with_thermal(), "/thermal/boundary"), "/thermal", {"singular"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/time_step", 1), "/thermal/time_step", {"transient"}));
}

TEST(ModelReaderRules, ThermalBoundaryEntriesAreWellFormed) {
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/boundary/0/flux", 3), "/thermal/boundary/0", {"exactly one"}));
  EXPECT_TRUE(rejects(without(with_thermal(), "/thermal/boundary/1/ambient"), "/thermal/boundary/1", {"ambient"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/boundary/0/ambient", 3), "/thermal/boundary/0/ambient",
                      {"film"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/boundary/0/edges/0", json{1, 9}),
                      "/thermal/boundary/0/edges/0/1", {"9"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/boundary/2/temperature", 20.0), "/thermal/boundary/2",
                      {"exactly one"}));
  json clash = with(with_thermal(), "/thermal/boundary/2", json::parse(R"({"edges": [[3, 1]], "temperature": 20})"));
  EXPECT_TRUE(rejects(clash, "/thermal/boundary/2/temperature", {"already held at 500"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/sources/0/material", 7), "/thermal/sources/0/material", {"7"}));
}

TEST(ModelReaderRules, RadiationNeedsEmissivityAmbientAndTheStefanBoltzmannConstant) {
  const json radiating = with(with_thermal(), "/thermal/boundary/1",
                              json::parse(R"({"edges": [[3, 2]], "emissivity": 0.8, "ambient": 300,
                                              "stefan_boltzmann": 5.670374e-8})"));
  const Model read = read_model(radiating);
  const ThermalBoundary& b = read.thermal->boundary[1];
  EXPECT_EQ(b.kind, ThermalBoundary::Kind::radiation);
  EXPECT_DOUBLE_EQ(b.value, 0.8 * 5.670374e-8);
  EXPECT_EQ(b.ambient, 300.0);
  EXPECT_TRUE(rejects(without(radiating, "/thermal/boundary/1/stefan_boltzmann"), "/thermal/boundary/1",
                      {"stefan_boltzmann", "5.670374e-8"}));
  EXPECT_TRUE(rejects(without(radiating, "/thermal/boundary/1/ambient"), "/thermal/boundary/1", {"ambient", "T^4"}));
  EXPECT_TRUE(rejects(with(radiating, "/thermal/boundary/1/emissivity", 1.5), "/thermal/boundary/1/emissivity",
                      {"1.5"}));
  EXPECT_TRUE(rejects(with(radiating, "/thermal/boundary/1/ambient", -10), "/thermal/boundary/1/ambient", {"-10"}));
  EXPECT_TRUE(rejects(with(radiating, "/thermal/boundary/1/stefan_boltzmann", 0), "/thermal/boundary/1/stefan_boltzmann",
                      {"0"}));
  EXPECT_TRUE(rejects(with(with_thermal(), "/thermal/boundary/2/stefan_boltzmann", 1e-8),
                      "/thermal/boundary/2/stefan_boltzmann", {"radiation"}));
  EXPECT_TRUE(rejects(with(radiating, "/thermal/boundary/1/film", 2), "/thermal/boundary/1", {"exactly one"}));
  // Radiation holds the level of a steady run as a film does.
  json only_radiation = radiating;  // the radiation and a flux left
  only_radiation["thermal"]["boundary"].erase(0);
  ASSERT_EQ(only_radiation["thermal"]["boundary"].size(), 2u);
  EXPECT_NO_THROW((void)read_model(only_radiation));
}

TEST(ModelReaderRules, ContactConductanceIsReadInTransientRunsToo) {
  json m = transient(with_thermal());
  m["contact"] = json::parse(R"({
    "surfaces": [{"name": "left", "edges": [[1, 2]]}, {"name": "right", "edges": [[3, 2]]}],
    "pairs": [{"surfaces": ["left", "right"], "conductance": {"closed": 2}},
              {"surfaces": ["right", "left"], "conductance": {"closed": 5, "gas_conductivity": 1e-4}}]
  })");
  const Model read = read_model(m);
  ASSERT_TRUE(read.contact.has_value());
  ASSERT_TRUE(read.contact->pairs[1].conductance.has_value());
  EXPECT_EQ(read.contact->pairs[1].conductance->gas_conductivity, 1e-4);
  EXPECT_EQ(read.thermal->type, ThermalType::transient);
}

TEST(ModelReaderRules, GapConductanceIsANumberOrATableOverPressure) {
  json m = valid_model();
  m = with(m, "/gaps/conductance", json::parse(R"({"closed": [{"p": 0, "h": 1}, {"p": 1000, "h": 8}],
                                                   "gas_conductivity": 0.0002})"));
  const Model read = read_model(m);
  ASSERT_TRUE(read.gaps->conductance.has_value());
  EXPECT_EQ(read.gaps->conductance->closed.size(), 2u);
  EXPECT_EQ(read.gaps->conductance->gas_conductivity, 0.0002);
  EXPECT_TRUE(rejects(with(m, "/gaps/conductance/closed/1/p", 0), "/gaps/conductance/closed/1/p", {"increasing"}));
  EXPECT_TRUE(rejects(with(m, "/gaps/conductance/closed", -2), "/gaps/conductance/closed", {"-2"}));
  EXPECT_EQ(read_model(with(m, "/gaps/conductance/closed", 5.0)).gaps->conductance->closed[0].h, 5.0);
  json thermal = with(m, "/loads", json::object());
  for (std::size_t i = 0; i < thermal["materials"].size(); ++i) {
    for (json& row : thermal["materials"][i]["table"]) row[thermal["materials"][i]["elastic"] == "isotropic" ? "k" : "k1"] = 1.0;
  }
  // Transient runs conduct across the gaps too (solver/transient_coupling.hpp).
  for (json& material : thermal["materials"]) {
    material["density"] = 0.1;
    for (json& row : material["table"]) {
      row["c"] = 0.2;
      if (material["elastic"] != "isotropic") row["k2"] = row["k3"] = 1.0;
    }
  }
  const Model transient_run = read_model(transient(with(thermal, "/thermal", json{{"type", "steady"}})));
  ASSERT_TRUE(transient_run.gaps->conductance.has_value());
  EXPECT_EQ(transient_run.thermal->type, ThermalType::transient);
}

// ------------------------------------------------------------------------------------------------
// Named sets (docs/model.md, "Named sets")

/// valid_model() with its bottom row of nodes and its top edge as sets that a constraint and a
/// pressure name, and an element set.
json model_with_sets() {
  json m = valid_model();
  m["sets"] = json::parse(R"({"nodes": {"base": [7, 8, 9], "corner": [7]},
                              "edges": {"top": [[5, 4]]},
                              "elements": {"left": [1, 11]}})");
  m["constraints"] = json::parse(R"([{"set": "base", "z": 0}, {"node": 7, "r": 0}, {"node": 1, "r": 0},
                                     {"node": 11, "r": 0, "z": 0}])");
  m["loads"]["pressures"][0] = json::parse(R"({"set": "top", "normal": 1000})");
  return m;
}

/// node index -> (u_r, u_z) of a model's constraints, merged.
std::map<int, std::pair<std::optional<double>, std::optional<double>>> prescribed(const std::vector<Constraint>& list) {
  std::map<int, std::pair<std::optional<double>, std::optional<double>>> out;
  for (const Constraint& c : list) {
    if (c.u_r) out[c.node].first = c.u_r;
    if (c.u_z) out[c.node].second = c.u_z;
  }
  return out;
}

TEST(ModelReaderSets, SetConstraintsAndPressuresExpandToWhatTheirNodesWouldGive) {
  const Model plain = read_model(valid_model());
  const Model named = read_model(model_with_sets());
  EXPECT_TRUE(issues_of(model_with_sets()).empty());  // the streaming readers agree (issues_of checks)
  EXPECT_EQ(prescribed(named.constraints), prescribed(plain.constraints));
  ASSERT_EQ(named.loads.pressures.size(), plain.loads.pressures.size());
  EXPECT_EQ(named.loads.pressures[0].element, plain.loads.pressures[0].element);
  EXPECT_EQ(named.loads.pressures[0].normal, 1000.0);
  // Only the node set a constraint names is a reaction group; nodes by index, ascending.
  ASSERT_EQ(named.reaction_groups.size(), 1u);
  EXPECT_EQ(named.reaction_groups[0].name, "base");
  EXPECT_EQ(named.reaction_groups[0].nodes, (std::vector<int>{6, 7, 8}));
  EXPECT_TRUE(plain.reaction_groups.empty());
  // A step's constraint may name a set too, and its group joins the list once.
  json stepped = model_with_sets();
  stepped["steps"] = json::parse(R"([{"name": "down", "constraints": [{"set": "base", "z": -0.01}, {"set": "corner", "r": 0.001}]}])");
  const Model read = read_model(stepped);
  ASSERT_EQ(read.reaction_groups.size(), 2u);
  EXPECT_EQ(read.reaction_groups[1].name, "corner");
  EXPECT_EQ(read.steps[0].constraints.size(), 4u);
}

TEST(ModelReaderSets, ErrorsNameTheSetAndItsPointer) {
  const json m = model_with_sets();
  EXPECT_TRUE(rejects(with(m, "/constraints/0/set", "bse"), "/constraints/0/set",
                      {"unknown node set \"bse\"", "\"base\"", "\"corner\""}));
  EXPECT_TRUE(rejects(with(m, "/steps", json::parse(R"([{"name": "a", "constraints": [{"set": "pushed", "z": 0.1}]}])")),
                      "/steps/0/constraints/0/set", {"unknown node set \"pushed\""}));
  EXPECT_TRUE(rejects(with(m, "/loads/pressures/0/set", "bottom"), "/loads/pressures/0/set", {"unknown edge set \"bottom\"", "\"top\""}));
  EXPECT_TRUE(rejects(with(m, "/sets/nodes/base/1", 99), "/sets/nodes/base/1", {"99"}));
  EXPECT_TRUE(rejects(with(m, "/sets/nodes/base/2", 7), "/sets/nodes/base/2", {"already in set \"base\""}));
  EXPECT_TRUE(rejects(with(m, "/sets/nodes/base", json::array()), "/sets/nodes/base", {"non-empty"}));
  EXPECT_TRUE(rejects(with(m, "/sets/edges/top/0", json{5, 1}), "/sets/edges/top/0", {"[5, 1]", "set \"top\""}));
  EXPECT_TRUE(rejects(with(m, "/sets/edges/top/0", json{2, 5}), "/loads/pressures/0/set", {"two solid elements"}));
  EXPECT_TRUE(rejects(with(m, "/sets/elements/left/0", 42), "/sets/elements/left/0", {"42"}));
  EXPECT_TRUE(rejects(with(m, "/sets/shapes", json::object()), "/sets/shapes", {"unknown key"}));
  // Two sets that share a node may give it the same value, not another one.
  json shared = with(m, "/sets/nodes/left_side", json{7, 4});
  shared["constraints"].push_back(json::parse(R"({"set": "left_side", "z": 0})"));
  shared["constraints"][1] = json::parse(R"({"node": 1, "r": 0})");
  shared["constraints"][2] = json::parse(R"({"node": 7, "r": 0})");
  EXPECT_TRUE(issues_of(shared).empty());
  shared["constraints"][4]["z"] = 0.5;
  EXPECT_TRUE(rejects(shared, "/constraints/4/z", {"node 7", "set \"left_side\"", "/constraints/0/z", "another value"}));
  // A node's own constraint after a set's is prescribed twice, as for two nodes.
  EXPECT_TRUE(rejects(with(m, "/constraints/1", json::parse(R"({"node": 8, "z": 0})")), "/constraints/1/z",
                      {"already prescribed at /constraints/0/z"}));
}

}  // namespace
}  // namespace saasgaps::io
