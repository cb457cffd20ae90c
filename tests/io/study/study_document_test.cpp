// The study document (io/study/study_document.hpp): points of grid and zip sampling, and every
// kind of bad study an error at its JSON Pointer before anything runs; outputs reduced from a
// result by field name (io/study/study_outputs.hpp); the study result and its CSV.
#include <gtest/gtest.h>

#include <string>

#include "io/model/model_reader.hpp"
#include "io/study/study_document.hpp"
#include "io/study/study_outputs.hpp"
#include "io/study/study_result.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

json block_model() {
  return json::parse(R"({"schema_version": 1, "title": "block", "analysis": {"type": "plane_strain"},
    "nodes": [{"id": 1, "r": 0, "z": 0}, {"id": 2, "r": 1, "z": 0}, {"id": 3, "r": 1, "z": 1}, {"id": 4, "r": 0, "z": 1}],
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 1000.0, "nu": 0.3, "alpha": 0}]}],
    "elements": [{"id": 1, "nodes": [1, 2, 3, 4], "material": 1}],
    "constraints": [{"node": 1, "r": 0, "z": 0}, {"node": 2, "z": 0}],
    "loads": {"pressures": [{"nodes": [3, 4], "normal": 10.0}]}})");
}

json study_of(const std::vector<json>& parameters, const char* sampling = "grid") {
  return {{"schema_version", 1},
          {"title", "t"},
          {"model", block_model()},
          {"parameters", json(parameters)},
          {"sampling", sampling},
          {"outputs", json::array({{{"name", "u"}, {"of", "nodes.u_z"}, {"reduce", "min"}}})}};
}

/// The issues read_study reports, as "pointer: detail" lines.
std::vector<std::string> issues_of(const json& study, std::size_t max_points = default_max_study_points) {
  try {
    (void)read_study(study, max_points);
  } catch (const ModelError& e) {
    std::vector<std::string> out;
    for (const InputIssue& i : e.issues()) out.push_back(i.pointer + ": " + i.detail);
    return out;
  }
  return {};
}

bool has_issue_at(const std::vector<std::string>& issues, const std::string& pointer, const std::string& words) {
  for (const std::string& i : issues) {
    if (i.rfind(pointer + ": ", 0) == 0 && i.find(words) != std::string::npos) return true;
  }
  ADD_FAILURE() << "no issue at " << pointer << " saying \"" << words << "\"; got " << json(issues).dump(1);
  return false;
}

const json p_values = {{"name", "p"}, {"pointer", "/loads/pressures/0/normal"}, {"values", {1, 2, 3}}};
const json e_values = {{"name", "E"}, {"pointer", "/materials/0/table/0/E"}, {"values", {100.0, 200.0}}};

TEST(StudyDocument, GridRunsEveryCombinationLastParameterFastest) {
  const Study s = read_study(study_of({p_values, e_values}));
  ASSERT_EQ(s.point_count(), 6u);
  EXPECT_EQ(s.point_parameters(0), json({{"p", 1}, {"E", 100.0}}));
  EXPECT_EQ(s.point_parameters(1), json({{"p", 1}, {"E", 200.0}}));
  EXPECT_EQ(s.point_parameters(5), json({{"p", 3}, {"E", 200.0}}));
  const json doc = s.point_document(3);
  EXPECT_EQ(doc["loads"]["pressures"][0]["normal"], 2);
  EXPECT_EQ(doc["materials"][0]["table"][0]["E"], 200.0);
  EXPECT_EQ(doc["title"], "block");  // everything else as in the model
}

TEST(StudyDocument, ZipTakesTheKthValuesTogether) {
  json e = e_values;
  e["values"] = {100.0, 200.0, 300.0};
  const Study s = read_study(study_of({p_values, e}, "zip"));
  ASSERT_EQ(s.point_count(), 3u);
  EXPECT_EQ(s.point_parameters(2), json({{"p", 3}, {"E", 300.0}}));
}

TEST(StudyDocument, APointerMayAddAMemberTheModelLeavesToItsDefault) {
  const Study s = read_study(study_of({{{"name", "T"}, {"pointer", "/loads/temperatures"}, {"values", {json::object()}}}}));
  EXPECT_TRUE(s.point_document(0)["loads"].contains("temperatures"));
}

TEST(StudyDocument, BadStudiesAreErrorsAtTheirPointers) {
  json unresolved = p_values;
  unresolved["pointer"] = "/loads/pressures/4/normal";
  has_issue_at(issues_of(study_of({unresolved})), "/parameters/0/pointer", "is not one of its indices");
  unresolved["pointer"] = "/load/pressures/0/normal";
  has_issue_at(issues_of(study_of({unresolved})), "/parameters/0/pointer", "has no member \"load\"");
  unresolved["pointer"] = "loads";
  has_issue_at(issues_of(study_of({unresolved})), "/parameters/0/pointer", "is not a JSON Pointer");

  json wrong_type = p_values;
  wrong_type["values"] = {1, "two", 3};
  has_issue_at(issues_of(study_of({wrong_type})), "/parameters/0/values/1", "wrong type: the string \"two\"");

  json empty = p_values;
  empty["values"] = json::array();
  has_issue_at(issues_of(study_of({empty})), "/parameters/0/values", "must not be empty");

  has_issue_at(issues_of(study_of({p_values, e_values}, "zip")), "/parameters/1/values", "zip sampling");
  has_issue_at(issues_of(study_of({p_values, e_values}), 5), "/parameters", "6 points, more than the limit of 5");
  json many = p_values;
  many["values"] = json::array();
  for (int i = 0; i < 100000; ++i) many["values"].push_back(i);
  json many_e = many, many_shear = many;
  many_e["name"] = "E";
  many_e["pointer"] = "/materials/0/table/0/E";
  many_shear["name"] = "shear";
  many_shear["pointer"] = "/loads/pressures/0/shear";
  has_issue_at(issues_of(study_of({many, many_e, many_shear})), "/parameters",
               "1000000000000000 points, more than the limit of 10000");

  json unknown_field = study_of({p_values});
  unknown_field["outputs"][0]["of"] = "nodes.u_theta";
  has_issue_at(issues_of(unknown_field), "/outputs/0/of", "unknown result field \"nodes.u_theta\"");
  unknown_field["outputs"][0]["of"] = "stresses.max";
  has_issue_at(issues_of(unknown_field), "/outputs/0/of", "SECTION one of nodes, elements");
  json unknown_reducer = study_of({p_values});
  unknown_reducer["outputs"][0]["reduce"] = "median";
  has_issue_at(issues_of(unknown_reducer), "/outputs/0/reduce", "reduce must be");

  json clash = study_of({p_values});
  clash["outputs"][0]["name"] = "p";
  has_issue_at(issues_of(clash), "/outputs/0/name", "taken by a parameter");
  has_issue_at(issues_of(study_of({p_values, p_values})), "/parameters/1/name", "used twice");
  json selection = study_of({p_values});
  selection["outputs"][0]["elements"] = {1};
  has_issue_at(issues_of(selection), "/outputs/0", "applies to elements.* only");
  json set_selection = study_of({p_values});
  set_selection["outputs"][0]["set"] = "pushed";
  has_issue_at(issues_of(set_selection), "/outputs/0", "applies to set_reactions.* only");
  set_selection["outputs"][0]["of"] = "set_reactions.fz";
  set_selection["outputs"][0]["nodes"] = {1};
  has_issue_at(issues_of(set_selection), "/outputs/0", "at most one of");
  set_selection["outputs"][0].erase("nodes");
  set_selection["outputs"][0]["set"] = 3;
  has_issue_at(issues_of(set_selection), "/outputs/0/set", "");
  json both = study_of({p_values});
  both["assembly"] = json::object();
  has_issue_at(issues_of(both), "", "not both");
  json typo = study_of({p_values});
  typo["sampler"] = "grid";
  has_issue_at(issues_of(typo), "/sampler", "unknown key");
}

TEST(StudyDocument, AValueTheModelReaderRefusesFailsItsPointAlone) {
  json e = e_values;
  e["values"] = {100.0, -1.0};
  const Study s = read_study(study_of({e}));
  EXPECT_EQ(point_issues(s, 0), "");
  const std::string why = point_issues(s, 1);
  EXPECT_NE(why.find("parameter \"E\" = -1.0 (/parameters/0/values/1): /materials/0/table/0/E: E = -1"), std::string::npos)
      << why;
}

const json result = json::parse(R"({"status": "converged",
  "nodes": [{"id": 1, "u_r": 0.5, "u_z": -1}, {"id": 2, "u_r": 1.5, "u_z": -3}, {"id": 3, "u_r": -2, "u_z": 0}],
  "elements": [{"id": 7, "sigma_z": 10, "yield": true}, {"id": 8, "sigma_z": 30, "yield": false}],
  "contact": [{"surfaces": ["a", "b"], "force": {"fr": 1, "fz": 2}, "points": [{"pressure": 5}, {"pressure": 7}]},
              {"surfaces": ["c", "d"], "force": {"fr": 3, "fz": 4}, "points": [{"pressure": 11}]}],
  "reaction_sum": {"fr": 0.25, "fz": -6},
  "reactions": [{"node": 1, "fr": 1, "fz": 2}, {"node": 2, "fr": 3, "fz": 4}],
  "set_reactions": [{"set": "pushed", "fr": 0.5, "fz": 1474.3}, {"set": "support", "fr": -0.5, "fz": -1474.3}]})");

double reduced(const char* of, Reducer r, const json& selection = json::object()) {
  StudyOutput o;
  o.name = "x";
  o.of = of;
  o.reduce = r;
  if (selection.contains("elements")) o.elements = selection["elements"].get<std::vector<int>>();
  if (selection.contains("nodes")) o.nodes = selection["nodes"].get<std::vector<int>>();
  if (selection.contains("pair")) o.pair = selection["pair"].get<std::vector<std::string>>();
  if (selection.contains("set")) o.set = selection["set"].get<std::string>();
  return reduce_output(result, o);
}

TEST(StudyOutputs, FieldsReducedByName) {
  EXPECT_EQ(reduced("nodes.u_r", Reducer::max), 1.5);
  EXPECT_EQ(reduced("nodes.u_r", Reducer::min), -2);
  EXPECT_EQ(reduced("nodes.u_r", Reducer::sum), 0.0);
  EXPECT_EQ(reduced("nodes.u_z", Reducer::mean, {{"nodes", {1, 2}}}), -2);
  EXPECT_EQ(reduced("elements.sigma_z", Reducer::max, {{"elements", {7}}}), 10);
  EXPECT_EQ(reduced("contact.pressure", Reducer::max), 11);
  EXPECT_EQ(reduced("contact.pressure", Reducer::max, {{"pair", {"a", "b"}}}), 7);
  EXPECT_EQ(reduced("contact.force.fz", Reducer::sum), 6);
  EXPECT_EQ(reduced("reaction_sum.fz", Reducer::sum), -6);
  EXPECT_EQ(reduced("reactions.fz", Reducer::sum, {{"nodes", {2}}}), 4);
  // A named set's summed reactions: the push-out force of the pushed face.
  EXPECT_EQ(reduced("set_reactions.fz", Reducer::sum, {{"set", "pushed"}}), 1474.3);
  EXPECT_EQ(reduced("set_reactions.fz", Reducer::max), 1474.3);
  EXPECT_THROW(reduced("set_reactions.fz", Reducer::sum, {{"set", "push"}}), OutputError);
  // A known field the result does not have (nodes.effective before recovered stresses, an empty
  // selection) is the point's error, named.
  EXPECT_THROW(reduced("nodes.effective", Reducer::max), OutputError);
  EXPECT_THROW(reduced("error_estimate.relative", Reducer::max), OutputError);
  EXPECT_THROW(reduced("nodes.u_r", Reducer::max, {{"nodes", {99}}}), OutputError);
}

TEST(StudyResult, StatusCountsTheConvergedPointsAndTheCsvHasAColumnEach) {
  const Study s = read_study(study_of({p_values}));
  std::vector<PointOutcome> points(3);
  for (std::size_t i = 0; i < 3; ++i) {
    points[i].index = i;
    points[i].status = "converged";
    points[i].outputs["u"] = -0.5 * static_cast<double>(i + 1);
  }
  points[1].status = "failed";
  points[1].message = "E, \"bad\"";
  points[1].outputs = json::object();
  points[2].cached = true;
  points[2].job = 12;
  const json r = study_result_json(s, points, 1);
  EXPECT_EQ(r["status"], "partial");
  EXPECT_EQ(r["message"], "2 of 3 points converged, 1 did not (point 1 failed: E, \"bad\")");
  EXPECT_EQ(r["converged"], 2);
  EXPECT_EQ(r["cached"], 1);
  EXPECT_EQ(r["points"][2]["job"], 12);
  EXPECT_EQ(r["points"][2]["parameters"], json({{"p", 3}}));
  EXPECT_EQ(study_csv(s, points),
            "index,p,status,cached,job,u\n0,1,converged,false,,-0.5\n1,2,failed,false,,\n2,3,converged,true,12,-1.5\n");
}

}  // namespace
}  // namespace saasgaps::io
