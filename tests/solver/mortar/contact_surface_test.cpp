// Contact surfaces: chains of boundary edges of solid elements, oriented with the material on the
// left, with outward normals from their elements; and every kind of bad chain refused at its edge.
#include "solver/mortar/contact_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/mortar/surface_geometry.hpp"
#include "support/mesh_builder.hpp"
#include "support/stacked_blocks.hpp"

namespace saasgaps {
namespace {

using testing::add_grid;
using testing::Grid;
using Edges = std::vector<std::array<int, 2>>;

Vec2 at(const Model& m, int i) { return {m.nodes[static_cast<std::size_t>(i)].r, m.nodes[static_cast<std::size_t>(i)].z}; }

struct Block {
  Model model;
  Grid grid;
};

/// A 3 x 2 block on [0, 3] x [0, 2].
Block block() {
  Block b;
  b.model.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  b.grid = add_grid(b.model, 3, 2, [](double s, double t) { return Vec2(3.0 * s, 2.0 * t); }, 0);
  return b;
}

/// The one issue a bad surface raises.
SurfaceEdgeIssue refusal(const Model& m, const Edges& edges) {
  try {
    contact_surface(m, edges);
  } catch (const ContactSurfaceError& e) {
    EXPECT_EQ(e.issues().size(), 1U) << e.what();
    return e.issues().front();
  }
  ADD_FAILURE() << "surface accepted";
  return {};
}

TEST(ContactSurface, OpenChainRunsWithItsMaterialOnTheLeftWhateverTheOrderGiven) {
  const Block b = block();
  const Grid& g = b.grid;
  // The top face, listed shuffled and partly reversed.
  const Edges edges = {{g.at(2, 2), g.at(1, 2)}, {g.at(2, 2), g.at(3, 2)}, {g.at(0, 2), g.at(1, 2)}};
  const ContactSurface s = contact_surface(b.model, edges);
  EXPECT_FALSE(s.closed);
  // Material below: the chain runs right to left (counter-clockwise around the block).
  EXPECT_EQ(s.nodes, (std::vector<int>{g.at(3, 2), g.at(2, 2), g.at(1, 2), g.at(0, 2)}));
  EXPECT_EQ(s.edge, (std::vector<std::size_t>{1, 0, 2}));
  ASSERT_EQ(s.segment_count(), 3U);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(s.normal[k].x(), 0.0);
    EXPECT_DOUBLE_EQ(s.normal[k].y(), 1.0);
    EXPECT_EQ(s.element[k], 3 + (2 - static_cast<int>(k)));  // the top row's elements, right to left
  }
}

TEST(ContactSurface, ClosedChainStartsAtTheFirstEdgeWithOutwardNormals) {
  const Block b = block();
  const Grid& g = b.grid;
  Edges edges = testing::row_edges(g, 0);
  for (const auto& e : testing::column_edges(g, 3)) edges.push_back(e);
  for (const auto& e : testing::row_edges(g, 2)) edges.push_back({e[1], e[0]});
  for (const auto& e : testing::column_edges(g, 0)) edges.push_back(e);
  std::reverse(edges.begin() + 3, edges.end());  // any order
  const ContactSurface s = contact_surface(b.model, edges);
  EXPECT_TRUE(s.closed);
  ASSERT_EQ(s.nodes.size(), 10U);
  ASSERT_EQ(s.segment_count(), 10U);
  EXPECT_EQ(s.edge.front(), 0U);
  EXPECT_EQ(s.nodes.front(), g.at(0, 0));
  const Vec2 centre(1.5, 1.0);
  for (std::size_t k = 0; k < s.segment_count(); ++k) {
    const auto [a, c] = s.segment(k);
    const Vec2 mid = 0.5 * (at(b.model, a) + at(b.model, c));
    EXPECT_GT(s.normal[k].dot(mid - centre), 0.0) << "segment " << k;
    EXPECT_NEAR(s.normal[k].norm(), 1.0, 1e-15);
  }
}

TEST(ContactSurface, ClockwiseElementsGiveTheSameOutwardNormal) {
  Block b = block();
  for (Element& e : b.model.elements) std::reverse(e.nodes.begin(), e.nodes.begin() + 4);
  const Grid& g = b.grid;
  const ContactSurface s = contact_surface(b.model, Edges{{g.at(0, 2), g.at(1, 2)}});
  EXPECT_DOUBLE_EQ(s.normal[0].y(), 1.0);
  EXPECT_EQ(s.nodes, (std::vector<int>{g.at(1, 2), g.at(0, 2)}));
}

TEST(ContactSurface, OneEdgeIsASurface) {
  const Block b = block();
  const Grid& g = b.grid;
  const ContactSurface s = contact_surface(b.model, Edges{{g.at(3, 0), g.at(3, 1)}});
  EXPECT_FALSE(s.closed);
  EXPECT_EQ(s.nodes, (std::vector<int>{g.at(3, 0), g.at(3, 1)}));
  EXPECT_DOUBLE_EQ(s.normal[0].x(), 1.0);
}

TEST(ContactSurface, TrianglesAndRepeatedNodeQuadsHaveTheirSides) {
  Block b = block();
  const Grid& g = b.grid;
  // The top-right quad becomes a triangle stored as a quad with a repeated node.
  Element& e = b.model.elements.back();
  e.nodes = {g.at(2, 1), g.at(3, 1), g.at(3, 2), g.at(3, 2)};
  const ContactSurface s = contact_surface(b.model, Edges{{g.at(3, 1), g.at(3, 2)}});
  EXPECT_EQ(s.element[0], 5);
  // Its diagonal is now a boundary edge (the neighbour's side facing empty space).
  EXPECT_NO_THROW(contact_surface(b.model, Edges{{g.at(2, 1), g.at(3, 2)}}));
}

TEST(ContactSurface, RefusesAnEdgeThatIsNoSide) {
  const Block b = block();
  const Grid& g = b.grid;
  const SurfaceEdgeIssue issue = refusal(b.model, {{g.at(0, 2), g.at(1, 2)}, {g.at(1, 2), g.at(2, 1)}});
  EXPECT_EQ(issue.edge, 1U);
  EXPECT_EQ(issue.problem, SurfaceEdgeProblem::not_a_side);
  EXPECT_NE(issue.detail.find("[10, 7]"), std::string::npos) << issue.detail;  // user ids
}

TEST(ContactSurface, AQuadraticEdgeIsTwoHalvesThroughItsMidSideNode) {
  // A quad8 built in code: its top edge, named by its corners, is a chain of three nodes, corner ->
  // mid-side node -> corner (material on the left), two segments that know they are the halves of one
  // 3-node edge; the mid-side node is never a corner.
  Model m;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  const std::array<Vec2, 8> x{Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1),
                              Vec2(1, 0), Vec2(2, 0.5), Vec2(1, 1.1), Vec2(0, 0.5)};
  Element e;
  e.id = 7;
  e.type = ElementType::quad8;
  e.node_count = 8;
  for (int k = 0; k < 8; ++k) {
    m.nodes.push_back({k + 1, x[static_cast<std::size_t>(k)].x(), x[static_cast<std::size_t>(k)].y()});
    e.nodes[static_cast<std::size_t>(k)] = k;
  }
  m.elements = {e};
  const ContactSurface s = contact_surface(m, Edges{{3, 2}, {2, 1}});
  EXPECT_EQ(s.nodes, (std::vector<int>{1, 5, 2, 6, 3}));
  EXPECT_FALSE(s.closed);
  ASSERT_EQ(s.segment_count(), 4U);
  EXPECT_EQ(s.halves, (std::vector<std::int8_t>{0, 1, 0, 1}));
  EXPECT_EQ(s.edge, (std::vector<std::size_t>{1, 1, 0, 0}));
  EXPECT_EQ(s.edge_positions(3), (std::array<std::size_t, 3>{2, 3, 4}));
  EXPECT_TRUE(s.mid_side(1));
  EXPECT_TRUE(s.mid_side(3));
  EXPECT_FALSE(s.mid_side(2));
  EXPECT_NEAR(s.normal[0].x(), 1.0, 1e-15);              // the right side's chord
  EXPECT_NEAR(s.normal[2].dot(Vec2(0.1, 1).normalized()), 1.0, 1e-15);  // the top's first half, tilted up
  const std::vector<bool> corner = corners(s);
  EXPECT_TRUE(corner[2]);   // the element's corner, where the chain turns by 90 degrees
  EXPECT_FALSE(corner[3]);  // the mid-side node of a bent edge
}

TEST(ContactSurface, RefusesAnEdgeOfTwoElements) {
  const Block b = block();
  const Grid& g = b.grid;
  const SurfaceEdgeIssue issue = refusal(b.model, {{g.at(1, 1), g.at(2, 1)}});
  EXPECT_EQ(issue.edge, 0U);
  EXPECT_EQ(issue.problem, SurfaceEdgeProblem::interior);
  EXPECT_NE(issue.detail.find("elements 2 and 5"), std::string::npos) << issue.detail;
}

TEST(ContactSurface, RefusesAnEdgeListedTwice) {
  const Block b = block();
  const Grid& g = b.grid;
  const SurfaceEdgeIssue issue =
      refusal(b.model, {{g.at(0, 2), g.at(1, 2)}, {g.at(1, 2), g.at(2, 2)}, {g.at(1, 2), g.at(0, 2)}});
  EXPECT_EQ(issue.edge, 2U);
  EXPECT_EQ(issue.problem, SurfaceEdgeProblem::repeated);
}

TEST(ContactSurface, RefusesADegenerateEdgeAndAnEmptySurface) {
  const Block b = block();
  EXPECT_EQ(refusal(b.model, {{3, 3}}).problem, SurfaceEdgeProblem::degenerate);
  EXPECT_EQ(refusal(b.model, {}).problem, SurfaceEdgeProblem::empty);
}

TEST(ContactSurface, ReportsEveryBadEdgeAtOnce) {
  const Block b = block();
  const Grid& g = b.grid;
  try {
    contact_surface(b.model, Edges{{g.at(0, 2), g.at(1, 2)}, {g.at(1, 1), g.at(2, 1)}, {g.at(0, 0), g.at(1, 1)}});
    FAIL() << "accepted";
  } catch (const ContactSurfaceError& e) {
    ASSERT_EQ(e.issues().size(), 2U);
    EXPECT_EQ(e.issues()[0].edge, 1U);
    EXPECT_EQ(e.issues()[0].problem, SurfaceEdgeProblem::interior);
    EXPECT_EQ(e.issues()[1].edge, 2U);
    EXPECT_EQ(e.issues()[1].problem, SurfaceEdgeProblem::not_a_side);
  }
}

/// Block A on [0, 1]^2 and block B on [1, 2] x [1, 2]: they share node (1, 1) only.
struct TwoBodies {
  Model model;
  Grid a, b;
};

TwoBodies corner_to_corner(double b_z0) {
  TwoBodies t;
  t.model.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  t.a = add_grid(t.model, 1, 1, [](double s, double u) { return Vec2(s, u); }, 0);
  t.b = add_grid(t.model, 1, 1, [&](double s, double u) { return Vec2(1.0 + s, b_z0 + u); }, 0);
  // Merge B's node at (1, b_z0 or b_z0 + 1) into A's corner there.
  const int shared_a = b_z0 > 0.0 ? t.a.at(1, 1) : t.a.at(1, 0);
  const int shared_b = b_z0 > 0.0 ? t.b.at(0, 0) : t.b.at(0, 1);
  for (Element& e : t.model.elements) std::replace(e.nodes.begin(), e.nodes.end(), shared_b, shared_a);
  t.b.nodes[static_cast<std::size_t>(b_z0 > 0.0 ? 0 : 2)] = shared_a;
  return t;
}

TEST(ContactSurface, RefusesABranch) {
  const TwoBodies t = corner_to_corner(1.0);
  // A's top, A's right side and B's bottom all meet at the shared node.
  const SurfaceEdgeIssue issue = refusal(
      t.model, {{t.a.at(0, 1), t.a.at(1, 1)}, {t.a.at(1, 0), t.a.at(1, 1)}, {t.b.at(0, 0), t.b.at(1, 0)}});
  EXPECT_EQ(issue.edge, 2U);
  EXPECT_EQ(issue.problem, SurfaceEdgeProblem::branch);
}

TEST(ContactSurface, RefusesAChainWithMaterialOnBothSides) {
  // B on [1, 2] x [-1, 0]: A's bottom (material above) continues into B's top (material below).
  const TwoBodies t = corner_to_corner(-1.0);
  const SurfaceEdgeIssue issue = refusal(t.model, {{t.a.at(0, 0), t.a.at(1, 0)}, {t.b.at(0, 1), t.b.at(1, 1)}});
  EXPECT_EQ(issue.edge, 1U);
  EXPECT_EQ(issue.problem, SurfaceEdgeProblem::opposite_side);
}

TEST(ContactSurface, RefusesTwoChains) {
  const Block b = block();
  const Grid& g = b.grid;
  const SurfaceEdgeIssue issue = refusal(b.model, {{g.at(0, 2), g.at(1, 2)}, {g.at(0, 0), g.at(1, 0)}});
  EXPECT_EQ(issue.edge, 1U);
  EXPECT_EQ(issue.problem, SurfaceEdgeProblem::disconnected);
}

TEST(ContactSurface, NodalNormalsAreRadialOnAGradedArc) {
  // A quarter annulus, outer face graded. Chord s of angle alpha_s has its normal at its mid angle and
  // length 2 R sin(alpha_s / 2), so the 1 / L weights cancel the two normals' tangential parts,
  // sin(alpha_s / 2) / (2 R sin(alpha_s / 2)) each: the nodal normal is radial exactly.
  Model m;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  const Grid g = add_grid(
      m, 10, 1,
      [](double s, double t) {
        const double angle = 0.5 * std::numbers::pi * std::pow(s, 1.5);
        const double radius = 2.0 - t;  // t = 0 on the outer face: counter-clockwise
        return Vec2(radius * std::cos(angle), radius * std::sin(angle));
      },
      0);
  const ContactSurface s = contact_surface(m, testing::row_edges(g, 0));
  const std::vector<Vec2> n = nodal_normals(s, m.nodes);
  for (std::size_t j = 1; j + 1 < n.size(); ++j) {  // inner nodes (the ends take their segment's)
    const Vec2 radial = at(m, s.nodes[j]).normalized();
    EXPECT_NEAR(radial.dot(n[j]), 1.0, 1e-15) << "node " << j;
    EXPECT_NEAR(radial.x() * n[j].y() - radial.y() * n[j].x(), 0.0, 1e-14) << "node " << j;
  }
}

TEST(ContactSurface, NodalNormalAtACornerOfEqualSegmentsIsTheBisector) {
  const Block b = block();
  const Grid& g = b.grid;
  Edges edges = testing::row_edges(g, 2);
  for (const auto& e : testing::column_edges(g, 3)) edges.push_back(e);
  const ContactSurface s = contact_surface(b.model, edges);
  const std::vector<Vec2> n = nodal_normals(s, b.model.nodes);
  const auto corner = std::find(s.nodes.begin(), s.nodes.end(), g.at(3, 2)) - s.nodes.begin();
  EXPECT_NEAR(n[static_cast<std::size_t>(corner)].x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(n[static_cast<std::size_t>(corner)].y(), std::sqrt(0.5), 1e-15);
}

}  // namespace
}  // namespace saasgaps
