// The reader on element families: types, integrations, shapes, and what quadratic elements do not
// carry yet (gap elements along their edges), an error at its JSON Pointer naming the element and the
// value; what they do carry (contact surfaces with a conductance in a thermal run); and the same model
// through the text path.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/model/model_reader.hpp"
#include "solver/base/errors.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

/// A quad8 (element 1, 2 x 1) under a saas quad (element 2), 0.01 apart; the quad8 held at its base.
json two_bodies() {
  return json::parse(R"({
    "schema_version": 1, "title": "a quad8 and a saas quad",
    "analysis": {"type": "plane_stress"},
    "nodes": [{"id": 1, "r": 0, "z": 0}, {"id": 2, "r": 2, "z": 0}, {"id": 3, "r": 2, "z": 1}, {"id": 4, "r": 0, "z": 1},
              {"id": 5, "r": 1, "z": 0}, {"id": 6, "r": 2, "z": 0.5}, {"id": 7, "r": 1, "z": 1}, {"id": 8, "r": 0, "z": 0.5},
              {"id": 9, "r": 0, "z": 1.01}, {"id": 10, "r": 2, "z": 1.01}, {"id": 11, "r": 2, "z": 2}, {"id": 12, "r": 0, "z": 2}],
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 1000, "nu": 0.3, "alpha": 1e-5}]}],
    "elements": [{"id": 1, "nodes": [1, 2, 3, 4, 5, 6, 7, 8], "material": 1},
                 {"id": 2, "nodes": [9, 10, 11, 12], "material": 1}],
    "constraints": [{"node": 1, "r": 0, "z": 0}, {"node": 2, "z": 0}, {"node": 5, "z": 0},
                    {"node": 12, "r": 0, "z": -0.02}, {"node": 11, "z": -0.02}],
    "loads": {}
  })");
}

/// The one issue reading `document` gives (a failure when there is none or several).
InputIssue only_issue(const json& document) {
  try {
    (void)read_model(document);
  } catch (const ModelError& e) {
    EXPECT_EQ(e.issues().size(), 1U);
    if (!e.issues().empty()) return e.issues().front();
  }
  ADD_FAILURE() << "read without an issue";
  return {};
}

void expect_issue(const json& document, const std::string& pointer, const std::vector<std::string>& words) {
  const InputIssue issue = only_issue(document);
  EXPECT_EQ(issue.pointer, pointer) << issue.detail;
  for (const std::string& w : words) EXPECT_NE(issue.detail.find(w), std::string::npos) << "no \"" << w << "\" in: " << issue.detail;
  // The text path (the fast scan, then the reporting pass) finds the same issue at the same place.
  try {
    (void)parse_model(document.dump());
    ADD_FAILURE() << "the text path accepted it";
  } catch (const ModelError& e) {
    ASSERT_FALSE(e.issues().empty());
    EXPECT_EQ(e.issues().front().pointer, pointer);
  }
}

TEST(ElementFamilyReader, TypesAndIntegrationsAreRead) {
  json d = two_bodies();
  Model m = read_model(d);
  EXPECT_EQ(m.elements[0].type, ElementType::quad8);
  EXPECT_EQ(m.elements[0].node_count, 8);
  EXPECT_EQ(m.elements[0].integration, Integration::full);
  EXPECT_EQ(m.elements[1].type, ElementType::saas);
  d["elements"][0]["integration"] = "reduced";
  d["elements"][1]["type"] = "quad4i";
  m = read_model(d);
  EXPECT_EQ(m.elements[0].integration, Integration::reduced);
  EXPECT_EQ(m.elements[1].type, ElementType::quad4i);
  EXPECT_EQ(parse_model(d.dump()).elements[1].type, ElementType::quad4i);
}

TEST(ElementFamilyReader, ATypeThatDoesNotFitItsNodesIsAnError) {
  json d = two_bodies();
  d["elements"][0]["type"] = "quad9";
  expect_issue(d, "/elements/0/type", {"quad9", "9 nodes", "lists 8"});
  d = two_bodies();
  d["elements"][1]["integration"] = "reduced";
  expect_issue(d, "/elements/1/integration", {"reduced", "quad8 and quad9 only", "saas"});
}

TEST(ElementFamilyReader, MidSideNodesOutOfOrderOrOffTheirEdgeAreAnError) {
  json d = two_bodies();
  d["elements"][0]["nodes"] = json::array({1, 2, 3, 4, 6, 5, 7, 8});
  expect_issue(d, "/elements/0/nodes", {"[1, 2, 3, 4, 6, 5, 7, 8]", "mid-side node 5", "order of the edges"});
  d = two_bodies();
  d["nodes"][4]["r"] = 1.8;  // node 5 at 0.9 of its chord
  expect_issue(d, "/elements/0/nodes", {"mid-side node 5", "0.9"});
}

TEST(ElementFamilyReader, AnInvertedQuadraticElementIsAnError) {
  json d = two_bodies();
  d["elements"][0]["nodes"] = json::array({1, 4, 3, 2, 8, 7, 6, 5});  // clockwise
  expect_issue(d, "/elements/0/nodes", {"[1, 4, 3, 2, 8, 7, 6, 5]", "clockwise", "corner area -2"});
}

TEST(ElementFamilyReader, AGapAlongAQuadraticEdgePointsToContactSurfaces) {
  json d = two_bodies();
  d["gaps"] = json::parse(R"({"initial_modulus": 1e-3, "tensile_schedule": [1e-3],
                               "elements": [{"id": 3, "nodes": [4, 3, 10, 9], "angle": 90}]})");
  expect_issue(d, "/gaps/elements/0/nodes", {"gap element 3", "[4, 3]", "element 1 (quad8)", "mid-side node 7", "contact surfaces"});
}

TEST(ElementFamilyReader, AContactSurfaceOnAQuadraticElementMayNameItsMidSideNode) {
  json d = two_bodies();
  d["contact"] = json::parse(R"({"surfaces": [{"name": "top", "edges": [[3, 4]]}, {"name": "under", "edges": [[9, 10]]}],
                                 "pairs": [{"surfaces": ["top", "under"]}]})");
  const Model corners = read_model(d);
  d["contact"]["surfaces"][0]["edges"][0] = json::array({3, 7, 4});
  const Model named = read_model(d);
  ASSERT_TRUE(named.contact);
  EXPECT_EQ(named.contact->surfaces[0].edges, corners.contact->surfaces[0].edges);

  d["contact"]["surfaces"][0]["edges"][0] = json::array({3, 6, 4});
  expect_issue(d, "/contact/surfaces/0/edges/0", {"[3, 6, 4]", "not the mid-side node of element 1", "node 7"});
  d["contact"]["surfaces"][0]["edges"][0] = json::array({3, 7, 4});
  d["contact"]["surfaces"][1]["edges"][0] = json::array({9, 3, 10});  // the saas element's straight edge
  expect_issue(d, "/contact/surfaces/1/edges/0", {"element 2", "straight edge"});
}

TEST(ElementFamilyReader, HeatConductionOnQuadraticElementsReadsItsEdgesThroughTheirMidSideNodes) {
  json d = two_bodies();
  d["materials"][0]["table"][0]["k"] = 1.0;
  d["thermal"] = json::parse(R"({"type": "steady", "boundary": [{"edges": [[1, 2]], "temperature": 100},
                                                               {"edges": [[3, 4]], "film": 2, "ambient": 20}]})");
  const Model m = read_model(d);
  ASSERT_TRUE(m.thermal);
  ASSERT_EQ(m.thermal->boundary.size(), 2U);
  EXPECT_EQ(m.thermal->boundary[0].edges[0].element, 0);  // the quad8's edge 1-5-2
  EXPECT_EQ(m.thermal->boundary[1].edges[0].element, 0);
}

TEST(ElementFamilyReader, AThermalEdgeMayNameItsMidSideNode) {
  json d = two_bodies();
  d["materials"][0]["table"][0]["k"] = 1.0;
  d["thermal"] = json::parse(R"({"type": "steady", "boundary": [{"edges": [[1, 5, 2]], "temperature": 100},
                                                               {"edges": [[3, 7, 4]], "flux": 2},
                                                               {"edges": [[11, 12]], "film": 2, "ambient": 20}]})");
  const Model named = read_model(d);
  d["thermal"]["boundary"][0]["edges"][0] = json::array({1, 2});
  d["thermal"]["boundary"][1]["edges"][0] = json::array({3, 4});
  const Model corners = read_model(d);
  ASSERT_TRUE(named.thermal && corners.thermal);
  for (std::size_t k = 0; k < 2; ++k) {
    const ThermalEdge& a = named.thermal->boundary[k].edges[0];
    const ThermalEdge& b = corners.thermal->boundary[k].edges[0];
    EXPECT_EQ(a.element, b.element);
    EXPECT_EQ(a.node_a, b.node_a);
    EXPECT_EQ(a.node_b, b.node_b);
  }
  // A middle node that is not the edge's mid-side node, and a straight edge named with three nodes.
  d["thermal"]["boundary"][0]["edges"][0] = json::array({1, 6, 2});
  expect_issue(d, "/thermal/boundary/0/edges/0", {"[1, 6, 2]", "element 1", "node 5"});
  d["thermal"]["boundary"][0]["edges"][0] = json::array({1, 2});
  d["thermal"]["boundary"][2]["edges"][0] = json::array({11, 9, 12});
  expect_issue(d, "/thermal/boundary/2/edges/0", {"element 2", "straight edge"});
  d["thermal"]["boundary"][2]["edges"][0] = json::array({11, 12, 3, 4});
  expect_issue(d, "/thermal/boundary/2/edges/0", {"[a, m, b]"});
}

TEST(ElementFamilyReader, ConductanceAcrossAQuadraticContactSurfaceIsRead) {
  json d = two_bodies();
  d["materials"][0]["table"][0]["k"] = 1.0;
  d["thermal"] = json::parse(R"({"type": "steady", "boundary": [{"edges": [[1, 2]], "temperature": 100}]})");
  d["contact"] = json::parse(R"({"surfaces": [{"name": "top", "edges": [[3, 4]]}, {"name": "under", "edges": [[9, 10]]}],
                                 "pairs": [{"surfaces": ["top", "under"], "conductance": {"closed": 5}}]})");
  const Model m = read_model(d);
  ASSERT_TRUE(m.contact && m.thermal);
  ASSERT_TRUE(m.contact->pairs[0].conductance.has_value());
  EXPECT_EQ(m.contact->pairs[0].conductance->closed[0].h, 5.0);
  EXPECT_EQ(m.contact->surfaces[0].edges.size(), 1U);  // the quad8's edge 3-7-4, by its corners
}

TEST(ElementFamilyReader, APressureEdgeMayNameItsMidSideNode) {
  json d = two_bodies();
  d["loads"]["pressures"] = json::parse(R"([{"nodes": [3, 4], "normal": 5}])");
  const Model corners = read_model(d);
  d["loads"]["pressures"][0]["nodes"] = json::array({3, 7, 4});
  const Model named = read_model(d);
  ASSERT_EQ(named.loads.pressures.size(), 1U);
  EXPECT_EQ(named.loads.pressures[0].element, corners.loads.pressures[0].element);
  EXPECT_EQ(named.loads.pressures[0].node_a, corners.loads.pressures[0].node_a);
  EXPECT_EQ(named.loads.pressures[0].node_b, corners.loads.pressures[0].node_b);

  d["loads"]["pressures"][0]["nodes"] = json::array({3, 6, 4});
  expect_issue(d, "/loads/pressures/0/nodes", {"[3, 6, 4]", "not the mid-side node of element 1", "node 7"});
  d["loads"]["pressures"][0]["nodes"] = json::array({11, 3, 12});  // the saas element's straight edge
  expect_issue(d, "/loads/pressures/0/nodes", {"[11, 3, 12]", "element 2", "straight edge of a saas element"});
}

}  // namespace
}  // namespace saasgaps::io
