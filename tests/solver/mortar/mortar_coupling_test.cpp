// Mortar coupling of two contact surfaces: the dual basis (plane and with the axisymmetric 2 pi r
// weight), consistency (sum_k M_jk = D_j) on non-matching graded meshes, exact rigid-motion gaps,
// initial gaps of flat and curved interfaces, and the rows of a chain with a corner.
#include "solver/mortar/mortar_coupling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "solver/mortar/dual_basis.hpp"
#include "support/mesh_builder.hpp"
#include "support/stacked_blocks.hpp"

namespace saasgaps {
namespace {

using testing::add_grid;
using testing::BlockFace;
using testing::Grid;
using Edges = std::vector<std::array<int, 2>>;

constexpr double pi = std::numbers::pi;

Vec2 at(const Model& m, int i) { return {m.nodes[static_cast<std::size_t>(i)].r, m.nodes[static_cast<std::size_t>(i)].z}; }

SurfaceMeasure measure_of(const Model& m) { return {m.analysis, m.thickness}; }

MortarRows rows_of(const Model& m, const Edges& slave, const Edges& master) {
  return mortar_rows(m.nodes, measure_of(m), contact_surface(m, slave), contact_surface(m, master));
}

/// Simpson's rule on [lo, hi]: exact for the cubics psi N w of a straight segment.
template <class F>
double simpson(double lo, double hi, F&& f) {
  return (hi - lo) / 6.0 * (f(lo) + 4.0 * f(0.5 * (lo + hi)) + f(hi));
}

struct DualCase {
  const char* name;
  AnalysisType analysis;
  Vec2 x1, x2;
  std::vector<ParameterInterval> covered;
};

TEST(MortarDualBasis, IsBiorthogonalWithTheWeightIncluded) {
  const std::vector<DualCase> cases = {
      {"plane, whole", AnalysisType::plane_stress, {1.0, 0.5}, {2.5, 1.1}, {{0.0, 1.0}}},
      {"axisymmetric, whole", AnalysisType::axisymmetric, {1.0, 0.5}, {2.5, 1.1}, {{0.0, 1.0}}},
      {"axisymmetric, from the axis", AnalysisType::axisymmetric, {0.0, 0.0}, {1.2, 0.3}, {{0.0, 1.0}}},
      {"axisymmetric, towards the axis", AnalysisType::axisymmetric, {1.2, 0.3}, {0.0, 0.0}, {{0.0, 1.0}}},
      {"plane, partly covered", AnalysisType::plane_strain, {1.0, 0.5}, {2.5, 1.1}, {{0.2, 0.7}}},
      {"axisymmetric, two pieces", AnalysisType::axisymmetric, {0.5, 2.0}, {3.0, 1.0}, {{0.0, 0.3}, {0.5, 0.9}}},
  };
  for (const DualCase& c : cases) {
    SCOPED_TRACE(c.name);
    const SurfaceMeasure measure{c.analysis, 0.4};
    const DualBasis basis = dual_basis(c.x1, c.x2, c.covered, measure);
    const double length = (c.x2 - c.x1).norm();
    auto N = [](int k, double xi) { return k == 0 ? 1.0 - xi : xi; };
    auto psi = [&](int i, double xi) { return basis.A(i, 0) * (1.0 - xi) + basis.A(i, 1) * xi; };
    auto dA = [&](double xi) { return length * measure.weight((1.0 - xi) * c.x1.x() + xi * c.x2.x()); };
    for (int i = 0; i < 2; ++i) {
      double d = 0.0;
      for (const ParameterInterval& p : c.covered) {
        d += simpson(p.lo, p.hi, [&](double xi) { return N(i, xi) * dA(xi); });
      }
      EXPECT_NEAR(basis.d[i], d, 1e-15 * d);
      for (int k = 0; k < 2; ++k) {
        double product = 0.0;
        for (const ParameterInterval& p : c.covered) {
          product += simpson(p.lo, p.hi, [&](double xi) { return psi(i, xi) * N(k, xi) * dA(xi); });
        }
        EXPECT_NEAR(product, i == k ? d : 0.0, 1e-14 * d) << "psi_" << i << " N_" << k;
      }
    }
    for (const double xi : {0.0, 0.37, 1.0}) EXPECT_NEAR(psi(0, xi) + psi(1, xi), 1.0, 1e-14);
  }
}

TEST(MortarDualBasis, MatchesTheClosedForms) {
  const DualBasis plane =
      dual_basis({0.0, 0.0}, {0.3, 0.4}, std::vector<ParameterInterval>{{0.0, 1.0}}, {AnalysisType::plane_stress, 2.0});
  EXPECT_NEAR(plane.A(0, 0), 2.0, 1e-14);
  EXPECT_NEAR(plane.A(0, 1), -1.0, 1e-14);
  EXPECT_NEAR(plane.A(1, 0), -1.0, 1e-14);
  EXPECT_NEAR(plane.A(1, 1), 2.0, 1e-14);
  EXPECT_NEAR(plane.d[0], 0.5 * 0.5 * 2.0, 1e-15);

  for (const auto& [r1, r2] : {std::pair{1.0, 3.0}, std::pair{0.0, 2.0}, std::pair{5.0, 0.5}}) {
    const DualBasis axi =
        dual_basis({r1, 0.0}, {r2, 0.0}, std::vector<ParameterInterval>{{0.0, 1.0}}, {AnalysisType::axisymmetric, 1.0});
    const double q = r1 * r1 + 4.0 * r1 * r2 + r2 * r2;
    EXPECT_NEAR(axi.A(0, 0), (2 * r1 + r2) * (r1 + 3 * r2) / q, 1e-14);
    EXPECT_NEAR(axi.A(0, 1), -(2 * r1 + r2) * (r1 + r2) / q, 1e-14);
    EXPECT_NEAR(axi.A(1, 0), -(r1 + 2 * r2) * (r1 + r2) / q, 1e-14);
    EXPECT_NEAR(axi.A(1, 1), (r1 + 2 * r2) * (3 * r1 + r2) / q, 1e-14);
    const double length = std::abs(r2 - r1);
    EXPECT_NEAR(axi.d[0], 2.0 * pi * length * (2 * r1 + r2) / 6.0, 1e-13);
  }
}

/// The master nodes whose segments overlap node j's support on the slave face (r ranges, open).
std::vector<int> overlapping_master_nodes(const Model& m, const Edges& slave, const Edges& master, int j) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const auto& e : slave) {
    if (e[0] != j && e[1] != j) continue;
    for (const int n : e) {
      lo = std::min(lo, at(m, n).x());
      hi = std::max(hi, at(m, n).x());
    }
  }
  std::vector<int> nodes;
  for (const auto& e : master) {
    const double a = std::min(at(m, e[0]).x(), at(m, e[1]).x());
    const double b = std::max(at(m, e[0]).x(), at(m, e[1]).x());
    if (std::min(b, hi) - std::max(a, lo) > 1e-12) {
      nodes.push_back(e[0]);
      nodes.push_back(e[1]);
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

struct Interface {
  const char* name;
  AnalysisType analysis;
  bool slave_below;  // the 5-segment face is the slave
};

const std::vector<Interface> interfaces = {
    {"plane, 5 on 7", AnalysisType::plane_stress, true},
    {"plane, 7 on 5", AnalysisType::plane_strain, false},
    {"axisymmetric, 5 on 7", AnalysisType::axisymmetric, true},
    {"axisymmetric, 7 on 5", AnalysisType::axisymmetric, false},
};

testing::StackedBlocks graded_blocks(AnalysisType analysis, double gap) {
  return testing::stacked_blocks(analysis, 1.0, 2.0, 1.0, gap, BlockFace{5, 1.3}, BlockFace{7, 0.75}, 2);
}

TEST(MortarRows, AreConsistentOnNonMatchingGradedMeshes) {
  for (const Interface& f : interfaces) {
    SCOPED_TRACE(f.name);
    const testing::StackedBlocks b = graded_blocks(f.analysis, 0.0);
    const Edges& slave = f.slave_below ? b.lower_top : b.upper_bottom;
    const Edges& master = f.slave_below ? b.upper_bottom : b.lower_top;
    const MortarRows rows = rows_of(b.model, slave, master);
    ASSERT_EQ(rows.size(), slave.size() + 1);
    double area = 0.0;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const double D = rows.weight[r];
      area += D;
      EXPECT_EQ(rows.node[rows.start[r]], rows.slave_node[r]);
      EXPECT_DOUBLE_EQ(rows.mortar[rows.start[r]], -D);
      double sum = 0.0;  // sum_k M_jk - D_j
      std::vector<int> masters;
      for (std::size_t e = rows.start[r]; e < rows.start[r + 1]; ++e) {
        sum += rows.mortar[e];
        // Flat: the normal field is n_j throughout. A's neighbours are entries with a scalar weight
        // of 0 (biorthogonality) and, here, no coefficient either.
        EXPECT_NEAR((rows.coefficient[e] - rows.mortar[e] * rows.normal[r]).norm(), 0.0, 1e-15 * D);
        const bool on_slave = std::ranges::any_of(slave, [&](const auto& edge) {
          return edge[0] == rows.node[e] || edge[1] == rows.node[e];
        });
        if (on_slave && e > rows.start[r]) {
          EXPECT_EQ(rows.mortar[e], 0.0);
        }
        if (!on_slave) masters.push_back(rows.node[e]);
      }
      EXPECT_NEAR(sum, 0.0, 1e-14 * D) << "row " << r;
      EXPECT_EQ(masters, overlapping_master_nodes(b.model, slave, master, rows.slave_node[r])) << "row " << r;
      EXPECT_EQ(rows.normal[r], Vec2(0.0, f.slave_below ? 1.0 : -1.0));
    }
    const double expected = f.analysis == AnalysisType::axisymmetric ? pi * (9.0 - 1.0) : 2.0 * b.model.thickness;
    EXPECT_NEAR(area, expected, 1e-14 * expected);
  }
}

/// Displacements (u_r, u_z per node) moving `nodes` by delta.
std::vector<double> translation(const Model& m, const Edges& edges, const Vec2& delta) {
  std::vector<double> u(2 * m.nodes.size(), 0.0);
  for (const auto& e : edges) {
    for (const int n : e) {
      u[2 * static_cast<std::size_t>(n)] = delta.x();
      u[2 * static_cast<std::size_t>(n) + 1] = delta.y();
    }
  }
  return u;
}

/// Every row's gap change under a rigid translation of the master side is the opposite of the slave
/// side's, under both nothing (to round-off); and it is int_A psi_j n(xi) . delta dA, which is
/// n_j . delta D_j exactly where A is flat round node j and within `turn` |delta| D_j where the normal
/// field turns over the row's support (turn = 0: everywhere flat).
void expect_rigid_motions_exact(const Model& m, const Edges& slave, const Edges& master, double turn = 0.0) {
  const MortarRows rows = rows_of(m, slave, master);
  ASSERT_GT(rows.size(), 0U);
  const Vec2 delta(0.013, -0.007);
  const std::vector<double> move_master = translation(m, master, delta);
  const std::vector<double> move_slave = translation(m, slave, delta);
  Edges both = slave;
  both.insert(both.end(), master.begin(), master.end());
  const std::vector<double> move_both = translation(m, both, delta);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double expected = rows.normal[r].dot(delta) * rows.weight[r];
    const double tolerance = 1e-14 * delta.norm() * rows.weight[r] * 10.0;
    const double master_change = rows.gap(r, move_master) - rows.g0[r];
    EXPECT_NEAR(master_change, expected, std::max(tolerance, turn * delta.norm() * rows.weight[r])) << "row " << r;
    EXPECT_NEAR(rows.gap(r, move_slave) - rows.g0[r], -master_change, tolerance) << "row " << r;
    EXPECT_NEAR(rows.gap(r, move_both) - rows.g0[r], 0.0, tolerance) << "row " << r;
  }
}

TEST(MortarRows, RigidTranslationChangesEveryGapByNormalDisplacementTimesWeight) {
  for (const Interface& f : interfaces) {
    SCOPED_TRACE(f.name);
    const testing::StackedBlocks b = graded_blocks(f.analysis, 0.03);
    expect_rigid_motions_exact(b.model, f.slave_below ? b.lower_top : b.upper_bottom,
                               f.slave_below ? b.upper_bottom : b.lower_top);
  }
}

TEST(MortarRows, InitialGapOfAFlatInterfaceIsDistanceTimesWeight) {
  for (const Interface& f : interfaces) {
    for (const double h : {0.05, 0.0, -0.02}) {
      SCOPED_TRACE(std::string(f.name) + ", h = " + std::to_string(h));
      const testing::StackedBlocks b = graded_blocks(f.analysis, h);
      const MortarRows rows = rows_of(b.model, f.slave_below ? b.lower_top : b.upper_bottom,
                                      f.slave_below ? b.upper_bottom : b.lower_top);
      ASSERT_EQ(rows.size(), (f.slave_below ? 5U : 7U) + 1U);
      for (std::size_t r = 0; r < rows.size(); ++r) {
        EXPECT_NEAR(rows.g0[r], h * rows.weight[r], 1e-14 * rows.weight[r]) << "row " << r;
      }
    }
  }
}

/// An inner sector (radii R - 0.5 .. R, angles -0.6 .. 0.6, graded) facing an outer one (radii
/// R + c .. R + c + 0.5, angles -0.7 .. 0.7) about `centre`; side A the inner sector's outer face.
struct Arcs {
  Model model;
  Edges inner_face;
  Edges outer_face;
};

Arcs concentric_arcs(AnalysisType analysis, const Vec2& centre, double R, double c, int inner_segments,
                     int outer_segments) {
  Arcs a;
  a.model.analysis = analysis;
  a.model.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  auto polar = [&](double radius, double angle) { return Vec2(centre + radius * Vec2(std::cos(angle), std::sin(angle))); };
  // t runs inwards on the inner sector and angles run backwards on the outer: both counter-clockwise.
  const Grid inner = add_grid(
      a.model, inner_segments, 1,
      [&](double s, double t) { return polar(R - 0.5 * t, -0.6 + 1.2 * std::pow(s, 1.2)); }, 0);
  const Grid outer = add_grid(
      a.model, outer_segments, 1,
      [&](double s, double t) { return polar(R + c + 0.5 * t, 0.7 - 1.4 * std::pow(s, 0.9)); }, 0);
  a.inner_face = testing::row_edges(inner, 0);
  a.outer_face = testing::row_edges(outer, 0);
  testing::fill_temperatures(a.model, 0.0);
  return a;
}

TEST(MortarRows, InitialGapOfConcentricArcsIsTheClearanceToSecondOrder) {
  for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
    for (const double c : {0.02, -0.01}) {
      SCOPED_TRACE(std::to_string(static_cast<int>(analysis)) + ", c = " + std::to_string(c));
      const Vec2 centre = analysis == AnalysisType::axisymmetric ? Vec2(4.0, 0.5) : Vec2(0.0, 0.0);
      auto worst = [&](int n) {
        const Arcs a = concentric_arcs(analysis, centre, 1.0, c, n, n + n / 2 - 1);
        const MortarRows rows = rows_of(a.model, a.inner_face, a.outer_face);
        EXPECT_EQ(rows.size(), static_cast<std::size_t>(n) + 1);
        double error = 0.0;
        for (std::size_t r = 0; r < rows.size(); ++r) {
          error = std::max(error, std::abs(rows.g0[r] / rows.weight[r] - c));
          // The row's normal is the radial direction (nodal normals of a circle; the ends are chords').
          const Vec2 radial = (at(a.model, rows.slave_node[r]) - centre).normalized();
          EXPECT_GT(rows.normal[r].dot(radial), std::cos(0.75 / n));
        }
        return error;
      };
      const double coarse = worst(8);
      const double fine = worst(16);
      // What remains is the open ends' chord normals, tilted by up to a / 2 from radial (alpha <=
      // 1.2 * 1.2 / n): |c| a^2 / 8.
      // (The polygons' own weighted gap would be off by the chords' sags, ~1e-3 here.)
      const double alpha = 1.44 / 8;
      EXPECT_LT(coarse, std::abs(c) * alpha * alpha / 4.0 + 1e-5);
      EXPECT_GT(coarse / fine, 3.0) << coarse << " " << fine;  // second order: 4 in the limit
    }
  }
}

TEST(MortarRows, ConcentricArcsAtZeroClearanceHaveNoInitialGap) {
  // The polygons' own weighted gap n_j . sum_k m_jk x_k carries the chords' sag mismatch; the initial
  // gap measured to B's smooth curve does not.
  for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
    const Arcs a = concentric_arcs(analysis, Vec2(4.0, 0.5), 1.0, 0.0, 12, 17);
    const MortarRows rows = rows_of(a.model, a.inner_face, a.outer_face);
    double polygon_worst = 0.0;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      EXPECT_LT(std::abs(rows.g0[r] / rows.weight[r]), 2e-6) << "row " << r;
      Vec2 polygon = Vec2::Zero();
      for (std::size_t e = rows.start[r]; e < rows.start[r + 1]; ++e) {
        polygon += rows.mortar[e] * (at(a.model, rows.node[e]) - at(a.model, rows.slave_node[r]));
      }
      polygon_worst = std::max(polygon_worst, std::abs(rows.normal[r].dot(polygon) / rows.weight[r]));
    }
    EXPECT_GT(polygon_worst, 1e-4);
  }
}

TEST(MortarRows, RigidTranslationIsExactOnCurvedInterfacesToo) {
  for (const AnalysisType analysis : {AnalysisType::plane_strain, AnalysisType::axisymmetric}) {
    const Arcs a = concentric_arcs(analysis, Vec2(4.0, 0.5), 1.0, 0.02, 9, 13);
    // A's segments turn by up to 0.19 rad: n(xi) departs from n_j by that much, 1 - cos < 0.02.
    expect_rigid_motions_exact(a.model, a.inner_face, a.outer_face, 0.02);
  }
}

/// A block [0, 2]^2 (4 x 4) whose top and right faces (side A, one chain round the corner) face an
/// L-shaped strip at clearance h on both: its inner face runs (-0.5, 2 + h) -> (2 + h, 2 + h) ->
/// (2 + h, -0.5), 5 segments per leg, mitred at the corner.
struct Corner {
  Model model;
  Grid block;
  Edges block_faces;
  Edges strip_face;
};

Corner corner(double h) {
  Corner c;
  c.model.analysis = AnalysisType::plane_strain;
  c.model.thickness = 1.0;
  c.model.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  c.block = add_grid(c.model, 4, 4, [](double s, double t) { return Vec2(2.0 * s, 2.0 * t); }, 0);
  const Vec2 p0(-0.5, 2.0 + h);
  const Vec2 knee(2.0 + h, 2.0 + h);
  const Vec2 p1(2.0 + h, -0.5);
  const Grid strip = add_grid(
      c.model, 10, 1,
      [&](double s, double t) {
        if (s < 0.5) return Vec2(p0 + 2.0 * s * (knee - p0) + 0.3 * t * Vec2(0.0, 1.0));
        if (s > 0.5) return Vec2(knee + 2.0 * (s - 0.5) * (p1 - knee) + 0.3 * t * Vec2(1.0, 0.0));
        return Vec2(knee + 0.3 * t * Vec2(1.0, 1.0));
      },
      0);
  c.block_faces = testing::row_edges(c.block, 4);
  for (const auto& e : testing::column_edges(c.block, 4)) c.block_faces.push_back(e);
  c.strip_face = testing::row_edges(strip, 0);
  testing::fill_temperatures(c.model, 0.0);
  return c;
}

TEST(MortarRows, ChainWithACornerGivesOneRowPerNodeReachingBothLegs) {
  const double h = 0.1;
  const Corner c = corner(h);
  const MortarRows rows = rows_of(c.model, c.block_faces, c.strip_face);
  ASSERT_EQ(rows.size(), 9U);
  const int knee_node = c.block.at(4, 4);
  double area = 0.0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    area += rows.weight[r];
    double sum = 0.0;
    for (std::size_t e = rows.start[r]; e < rows.start[r + 1]; ++e) sum += rows.mortar[e];
    EXPECT_NEAR(sum, 0.0, 1e-14 * rows.weight[r]);
    const Vec2 x = at(c.model, rows.slave_node[r]);
    const bool next_to_corner = (x - at(c.model, knee_node)).norm() < 0.51;
    if (!next_to_corner) {
      EXPECT_NEAR(rows.g0[r], h * rows.weight[r], 1e-14 * rows.weight[r]) << "row " << r;
      EXPECT_NEAR(rows.weight[r], x.x() == 0.0 || x.y() == 0.0 ? 0.25 : 0.5, 1e-15);
    }
    if (rows.slave_node[r] != knee_node) continue;
    EXPECT_NEAR(rows.normal[r].x(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(rows.normal[r].y(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(rows.weight[r], 0.5, 1e-15);
    // Along the bisector to the strip's corner (a corner: not rounded off).
    EXPECT_NEAR(rows.g0[r] / rows.weight[r], h * std::sqrt(2.0), 1e-15);
    bool on_top_leg = false;
    bool on_side_leg = false;
    for (std::size_t e = rows.start[r] + 1; e < rows.start[r + 1]; ++e) {
      const Vec2 y = at(c.model, rows.node[e]);
      on_top_leg = on_top_leg || (y.y() == 2.0 + h && y.x() < 2.0 + h);
      on_side_leg = on_side_leg || (y.x() == 2.0 + h && y.y() < 2.0 + h);
    }
    EXPECT_TRUE(on_top_leg && on_side_leg);
  }
  EXPECT_NEAR(area, 4.0, 1e-14);
  // Next to the corner the normal field turns by 45 degrees over a segment.
  expect_rigid_motions_exact(c.model, c.block_faces, c.strip_face, 0.05);
}

TEST(MortarRows, SlaveNodesFacingNothingGiveNoRow) {
  // The upper face covers only r in [1, 2] of the lower's [1, 3]: its nodes' rows only.
  testing::StackedBlocks b = graded_blocks(AnalysisType::axisymmetric, 0.0);
  for (const int n : b.upper.nodes) b.model.nodes[static_cast<std::size_t>(n)].r =
      1.0 + 0.5 * (b.model.nodes[static_cast<std::size_t>(n)].r - 1.0);
  const MortarRows rows = rows_of(b.model, b.lower_top, b.upper_bottom);
  // Lower nodes at r = 1 + 2 (i / 5)^1.3 = 1, 1.25, 1.61, 2.03, 2.49, 3: the segment 1.61-2.03 is
  // partly covered, so node 3 has a row (of the covered part's weight) and nodes 4 and 5 none.
  ASSERT_EQ(rows.size(), 4U);
  EXPECT_EQ(rows.slave_node.front(), b.lower.at(3, 2));  // the chain runs right to left
  double area = 0.0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    area += rows.weight[r];
    double sum = 0.0;
    for (std::size_t e = rows.start[r]; e < rows.start[r + 1]; ++e) sum += rows.mortar[e];
    EXPECT_NEAR(sum, 0.0, 1e-14 * rows.weight[r]);
  }
  EXPECT_NEAR(area, pi * (4.0 - 1.0), 1e-13);  // exactly the covered ring
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

/// Two strips meeting along random wavy curves: the lower one's top (side A, `na` segments over
/// x in [0, 4]) and the upper one's bottom (side B, `nb` segments over [shift, shift + length]), both
/// with random node spacing and a random clearance that may be negative.
struct RandomFaces {
  Model model;
  Edges lower;
  Edges upper;
};

RandomFaces random_faces(std::mt19937& random, int na, int nb, double shift, double length) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  RandomFaces f;
  f.model.analysis = uniform(random) < 0.5 ? AnalysisType::plane_strain : AnalysisType::axisymmetric;
  f.model.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  // A random monotone spacing: cumulative sums of weights in [0.3, 1].
  auto spacing = [&](int n) {
    std::vector<double> s{0.0};
    for (int i = 0; i < n; ++i) s.push_back(s.back() + 0.3 + 0.7 * uniform(random));
    for (double& v : s) v /= s.back();
    return s;
  };
  const std::vector<double> sa = spacing(na), sb = spacing(nb);
  const double amplitude = 0.3 * uniform(random), phase = 6.0 * uniform(random), clearance = 0.04 * uniform(random) - 0.02;
  auto wave = [&](double x) { return 1.0 + amplitude * std::sin(1.3 * x + phase); };
  auto lookup = [](const std::vector<double>& s, double t) {
    const auto i = static_cast<std::size_t>(std::lround(t * static_cast<double>(s.size() - 1)));
    return s[i];
  };
  const Grid lower = add_grid(
      f.model, na, 1, [&](double s, double t) { const double x = 0.5 + 4.0 * lookup(sa, s); return Vec2(x, t * wave(x)); }, 0);
  const Grid upper = add_grid(
      f.model, nb, 1,
      [&](double s, double t) {
        const double x = 0.5 + shift + length * lookup(sb, s);
        return Vec2(x, wave(x) + clearance + 0.5 * t);
      },
      0);
  f.lower = testing::row_edges(lower, 1);
  f.upper = testing::row_edges(upper, 0);
  testing::fill_temperatures(f.model, 0.0);
  return f;
}

void expect_same_rows(const MortarRows& search, const MortarRows& all) {
  ASSERT_EQ(search.size(), all.size());
  ASSERT_EQ(search.node.size(), all.node.size());
  for (std::size_t r = 0; r < all.size(); ++r) {
    const double scale = 1e-12 * all.weight[r];
    EXPECT_EQ(search.slave_node[r], all.slave_node[r]);
    EXPECT_NEAR(search.weight[r], all.weight[r], scale);
    EXPECT_NEAR(search.g0[r], all.g0[r], scale);
    ASSERT_EQ(search.start[r + 1], all.start[r + 1]);
    for (std::size_t e = all.start[r]; e < all.start[r + 1]; ++e) {
      EXPECT_EQ(search.node[e], all.node[e]);
      EXPECT_NEAR(search.mortar[e], all.mortar[e], scale);
      EXPECT_NEAR((search.coefficient[e] - all.coefficient[e]).norm(), 0.0, scale);
    }
  }
}

TEST(MortarRows, ACoarseClosedRingAtTheCornerThresholdIsSmooth) {
  // A bore of 12 segments turns by exactly 30 degrees at every node, the corner threshold, which
  // round-off puts on either side of it depending on where the nodes fall. Its nodes are no corners:
  // a shaft of 20 segments at zero clearance has no initial gap anywhere (a node taken for a corner
  // would see a chord's sag instead, R (1 - cos 15 degrees) = 0.05 here), however the rings are turned.
  for (const double turned : {0.0, 0.1, 0.25, 1.0, 2.5, 7.3, 11.0, 13.7}) {
    SCOPED_TRACE("turned by " + std::to_string(turned) + " degrees");
    Model m;
    m.analysis = AnalysisType::plane_strain;
    m.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
    const Grid shaft = testing::add_ring(m, 1.0, 1.5, 1, 20, 0);
    const Grid hub = testing::add_ring(m, 1.5, 2.0, 1, 12, 0);
    const double a = turned * pi / 180.0;
    for (Node& n : m.nodes) n = Node{n.id, std::cos(a) * n.r - std::sin(a) * n.z, std::sin(a) * n.r + std::cos(a) * n.z};
    testing::fill_temperatures(m, 0.0);
    const MortarRows rows = rows_of(m, testing::column_edges(shaft, 1), testing::column_edges(hub, 0));
    ASSERT_EQ(rows.size(), 20U);
    for (std::size_t r = 0; r < rows.size(); ++r) EXPECT_LT(std::abs(rows.g0[r] / rows.weight[r]), 1e-12) << "row " << r;
  }
}

TEST(MortarRows, TheSearchFindsWhatAllAgainstAllFindsOnRandomChains) {
  std::mt19937 random(20261125);
  std::uniform_int_distribution<int> segments(3, 60);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::size_t rows = 0;
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    // Every other trial B covers only part of A (A's ends face nothing) or overhangs it.
    const bool partial = trial % 2 == 1;
    const RandomFaces f = random_faces(random, segments(random), segments(random), partial ? 2.0 * uniform(random) - 0.5 : 0.0,
                                       partial ? 1.0 + 3.0 * uniform(random) : 4.0);
    for (const bool swap : {false, true}) {
      const ContactSurface a = contact_surface(f.model, swap ? f.upper : f.lower);
      const ContactSurface b = contact_surface(f.model, swap ? f.lower : f.upper);
      const MortarRows search = mortar_rows(f.model.nodes, measure_of(f.model), a, b, Pairing::search);
      const MortarRows all = mortar_rows(f.model.nodes, measure_of(f.model), a, b, Pairing::all_against_all);
      expect_same_rows(search, all);
      rows += all.size();
    }
  }
  EXPECT_GT(rows, 1000U);  // the trials pair something
}

/// Master segments examined by the pairing of two long chains that never face each other: two
/// blocks `segments` long stacked 1 apart, A the upper block's top (facing +z, away from B), B the
/// lower block's top. Every normal line of A crosses B, but B faces the same way.
std::size_t candidate_checks_facing_away(int segments, Pairing pairing) {
  const testing::StackedBlocks b = testing::stacked_blocks(AnalysisType::plane_strain, 0.0, static_cast<double>(segments),
                                                           1.0, 1.0, BlockFace{segments, 1.0}, BlockFace{segments, 1.0}, 1);
  const ContactSurface a = contact_surface(b.model, testing::row_edges(b.upper, 1));
  const ContactSurface master = contact_surface(b.model, b.lower_top);
  std::size_t checks = 0;
  const MortarRows rows = mortar_rows(b.model.nodes, measure_of(b.model), a, master, pairing, &checks);
  EXPECT_EQ(rows.size(), 0U);
  return checks;
}

TEST(MortarRows, ASegmentFacingNothingExaminesOnlyTheBinsItsNormalLinesCross) {
  // All against all examines every segment of B for every segment of A: n^2. A search that widened
  // its box until it covered B did the same for a segment facing nothing. The search examines a
  // bounded number per segment of A (its box doubled a few times, then the bins its normal lines
  // cross), the same at 100 and at 800 segments.
  const std::size_t all = candidate_checks_facing_away(100, Pairing::all_against_all);
  EXPECT_EQ(all, 100U * 100U);
  const std::size_t small = candidate_checks_facing_away(100, Pairing::search);
  const std::size_t large = candidate_checks_facing_away(800, Pairing::search);
  std::printf("segments facing nothing: %.1f and %.1f master segments examined per slave segment (100, 800)\n",
              static_cast<double>(small) / 100.0, static_cast<double>(large) / 800.0);
  // About 40 per segment at both sizes (the box's four doublings reach B at a distance of 2
  // lengths; then the 3 or 4 bins its lines cross): 1/20 of all against all at 800.
  EXPECT_LE(static_cast<double>(large) / 800.0, 1.05 * static_cast<double>(small) / 100.0);
  EXPECT_LT(large, 50U * 800U);
}

}  // namespace
}  // namespace saasgaps
