// Contact surfaces on quadratic (quad8) elements through the full solve(): the mortar rows of
// 3-node edges (docs/contact-surfaces.md, section 7), alone and against straight SAAS-element edges.
//
// - The contact patch test on quad8: two blocks meeting on a face of 5 graded quad8 edges against 7,
//   and quad8 against a SAAS-element block, a uniform pressure p on top: every element's stress is
//   (0, -p, 0) and every contact point's pressure p (mid-side nodes included), to 1e-8 relative, in
//   plane stress, plane strain and axisymmetry, either side as A, touching or with an interference.
// - The Lame interference fit of two quarter rings of quad8 whose mid-side nodes lie on the true
//   circles, 20 edges against 16 on the quarter circle, plane strain: the mean pressure and every
//   point against the closed form of support/shrink_fit_rings.hpp; the axisymmetric slice too.
// - Hertz, a quad8 cylinder on a quad8 block at 0.04 (a / 5) per edge near the contact: peak pressure,
//   half-width and resultant.
// - Cattaneo-Mindlin on quad8 (friction): the stick zone within one edge + 5 %.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "solver/analysis/analysis.hpp"
#include "solver/analysis/reactions.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/contact/exact_contact.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/mortar/mortar_method.hpp"
#include "support/hertz_line_contact.hpp"
#include "support/mesh_builder.hpp"
#include "support/ring_fit.hpp"
#include "support/shrink_fit_rings.hpp"

namespace saasgaps {
namespace {

using Edges = std::vector<std::array<int, 2>>;

constexpr double pressure = 250.0;
constexpr int layers = 3;

/// The solid element (index) that has the edge between corners a and b.
int owner(const Model& m, int a, int b) {
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const auto nodes = m.elements[e].node_span();
    const bool has_a = std::find(nodes.begin(), nodes.end(), a) != nodes.end();
    const bool has_b = std::find(nodes.begin(), nodes.end(), b) != nodes.end();
    if (has_a && has_b) return static_cast<int>(e);
  }
  ADD_FAILURE() << "no element has the edge";
  return -1;
}

/// A uniform pressure on the given edges (loads.pressures: the consistent loads of each family).
void press(Model& m, const Edges& edges, double p) {
  for (const auto& e : edges) m.loads.pressures.push_back({owner(m, e[0], e[1]), e[0], e[1], p, 0.0});
}

/// A block's corner (and mid-side) rows: quad8 or SAAS (add_grid), r0 + width s^grading.
struct Block {
  Edges bottom, top;
  std::vector<int> bottom_nodes, top_left;  ///< every node of the bottom row; the top row's first node
  std::size_t first_element = 0, elements = 0;
};

Block add_block(Model& m, bool quad8, int segments, double grading, double z0, int material) {
  Block b;
  b.first_element = m.elements.size();
  const auto map = [&](double s, double t) { return Vec2(1.0 + 2.0 * std::pow(s, grading), z0 + t); };
  if (quad8) {
    const testing::QuadraticGrid g = testing::add_quadratic_grid(m, ElementType::quad8,
        segments, layers, map, material);
    b.bottom = g.row_edges(0);
    b.top = g.row_edges(layers);
    b.bottom_nodes = g.row_nodes(0);
    b.top_left = {g.corner(0, layers)};
  } else {
    const testing::Grid g = testing::add_grid(m, segments, layers, map, material);
    for (int i = 0; i < segments; ++i) {
      b.bottom.push_back({g.at(i, 0), g.at(i + 1, 0)});
      b.top.push_back({g.at(i, layers), g.at(i + 1, layers)});
    }
    for (int i = 0; i <= segments; ++i) b.bottom_nodes.push_back(g.at(i, 0));
    b.top_left = {g.at(0, layers)};
  }
  b.elements = m.elements.size() - b.first_element;
  return b;
}

struct PatchCase {
  const char* name;
  AnalysisType analysis;
  bool upper_quad8;
  bool lower_is_a;
  double gap;
};

/// The lower block (quad8, 5 edges graded 1.3) under the upper one (7 edges graded 0.75, quad8 or
/// SAAS), `gap` apart; the lower block's bottom held in z, in plane analyses one node of each block
/// in r.
Model patch_model(const PatchCase& c, std::size_t& a_nodes) {
  Model m;
  m.analysis = c.analysis;
  m.thickness = 0.4;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3), testing::isotropic_material(2, 3.0e6, 0.2)};
  const Block lower = add_block(m, true, 5, 1.3, 0.0, 0);
  const Block upper = add_block(m, c.upper_quad8, 7, 0.75, 1.0 + c.gap, 1);
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"lower top", lower.top}, {"upper bottom", upper.bottom}};
  contact.pairs.emplace_back().surfaces = c.lower_is_a ? std::array<int, 2>{0, 1} : std::array<int, 2>{1, 0};
  a_nodes = c.lower_is_a ? 2 * 5 + 1 : (c.upper_quad8 ? 2 * 7 + 1 : 7 + 1);
  press(m, upper.top, pressure);
  testing::fill_temperatures(m, 0.0);
  for (const int n : lower.bottom_nodes) testing::constrain(m, n, std::nullopt, 0.0);
  if (c.analysis != AnalysisType::axisymmetric) {
    testing::constrain(m, lower.bottom_nodes.front(), 0.0, std::nullopt);
    testing::constrain(m, upper.top_left.front(), 0.0, std::nullopt);
  }
  return m;
}

TEST(QuadraticContact, PatchTestOnQuad8AndAgainstASaasBlock) {
  const std::vector<PatchCase> cases = {
      {"plane stress, quad8 5 on 7", AnalysisType::plane_stress, true, true, 0.0},
      {"plane stress, quad8 7 on 5", AnalysisType::plane_stress, true, false, 0.0},
      {"plane strain, quad8 5 on 7", AnalysisType::plane_strain, true, true, 0.0},
      {"plane strain, quad8 7 on 5, interference", AnalysisType::plane_strain, true, false, -0.01},
      {"axisymmetric, quad8 5 on 7", AnalysisType::axisymmetric, true, true, 0.0},
      {"axisymmetric, quad8 7 on 5", AnalysisType::axisymmetric, true, false, 0.0},
      {"axisymmetric, quad8 5 on 7, interference", AnalysisType::axisymmetric, true, true, -0.01},
      {"plane stress, quad8 5 on saas 7", AnalysisType::plane_stress, false, true, 0.0},
      {"plane strain, saas 7 on quad8 5", AnalysisType::plane_strain, false, false, 0.0},
      {"axisymmetric, quad8 5 on saas 7", AnalysisType::axisymmetric, false, true, 0.0},
      {"axisymmetric, saas 7 on quad8 5, interference", AnalysisType::axisymmetric, false, false, -0.01},
  };
  double worst_stress = 0.0, worst_pressure = 0.0;
  for (const PatchCase& c : cases) {
    SCOPED_TRACE(c.name);
    std::size_t a_nodes = 0;
    const Model m = patch_model(c, a_nodes);
    const Solution s = solve(m);
    ASSERT_EQ(s.status, RunStatus::converged) << s.message;
    double stress_error = 0.0;
    for (const ElementResult& e : s.elements) {
      for (const double d : {e.stress[rr], e.stress[zz] + pressure, e.stress[rz]}) {
        stress_error = std::max(stress_error, std::abs(d) / pressure);
      }
    }
    EXPECT_LT(stress_error, 1e-8);
    ASSERT_EQ(s.contact.size(), 1U);
    // A point at every node of side A, mid-side nodes included, in chain order.
    ASSERT_EQ(s.contact[0].points.size(), a_nodes);
    double pressure_error = 0.0, previous_r = -1.0;
    for (const ContactPointResult& p : s.contact[0].points) {
      pressure_error = std::max(pressure_error, std::abs(p.pressure / pressure - 1.0));
      EXPECT_EQ(p.state, ContactPointState::stick);
      EXPECT_NEAR(p.gap, 0.0, 1e-12);
      if (previous_r >= 0.0) {
        EXPECT_TRUE(c.lower_is_a ? p.r < previous_r : p.r > previous_r);
      }
      previous_r = p.r;
    }
    EXPECT_LT(pressure_error, 1e-8);
    worst_stress = std::max(worst_stress, stress_error);
    worst_pressure = std::max(worst_pressure, pressure_error);
    const double area = c.analysis == AnalysisType::axisymmetric ? std::numbers::pi * (9.0 - 1.0) : 2.0 * m.thickness;
    const double load = pressure * area;
    EXPECT_NEAR(s.contact[0].force.y(), c.lower_is_a ? -load : load, 1e-10 * load);
    EXPECT_NEAR(reaction_sum(s.reactions).y(), load, 1e-10 * load);
  }
  std::printf("quad8 patch test: worst stress error %.3g, worst pressure error %.3g (of p)\n", worst_stress,
              worst_pressure);
}

// ---- Lame: two quarter rings of quad8 (mid-side nodes on the true circles), shaft in hub.

namespace fit = testing::shrink_fit_rings;

struct FitResult {
  double mean = 0.0;   ///< mean pressure / Lame - 1
  double worst = 0.0;  ///< max |pressure / Lame - 1|
  std::size_t points = 0;
};

FitResult check_fit(const Model& m) {
  const Solution s = solve(m);
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  const double p = fit::lame_interference_pressure(m.analysis);
  FitResult r;
  double sum = 0.0;
  for (const ContactPointResult& point : s.contact.at(0).points) {
    EXPECT_EQ(point.state, ContactPointState::stick);
    sum += point.pressure;
    r.worst = std::max(r.worst, std::abs(point.pressure / p - 1.0));
  }
  r.points = s.contact.at(0).points.size();
  r.mean = sum / static_cast<double>(r.points) / p - 1.0;
  return r;
}

Model quarter_fit(int radial, std::array<int, 2> around) { return fit::quarter_shrink_fit(radial, around); }

TEST(QuadraticContact, LameFitOnCurvedQuad8Surfaces) {
  EXPECT_EQ(quarter_fit(4, {20, 16}).nodes.size(), 522U);  // 1,044 unknowns (docs/performance.md)
  const FitResult r = check_fit(quarter_fit(4, {20, 16}));
  std::printf("quad8 quarter ring fit, 20 against 16: mean pressure %+.4f %%, worst point %.4f %% (%zu points), "
              "Lame %.4f\n", 100 * r.mean, 100 * r.worst, r.points, fit::lame_interference_pressure(AnalysisType::plane_strain));
  // Observed +0.0051 % mean, 0.0167 % worst (the issue asks 0.05 % and 0.3 %).
  EXPECT_EQ(r.points, 41U);  // every node of the shaft's face, mid-side nodes included
  EXPECT_LT(std::abs(r.mean), 1e-4);
  EXPECT_LT(r.worst, 3e-4);
  const FitResult swapped = check_fit(quarter_fit(4, {16, 20}));
  std::printf("quad8 quarter ring fit, 16 against 20: mean pressure %+.4f %%, worst point %.4f %%\n",
              100 * swapped.mean, 100 * swapped.worst);
  // Observed +0.0058 % mean, 0.0084 % worst.
  EXPECT_LT(std::abs(swapped.mean), 1e-4);
  EXPECT_LT(swapped.worst, 2e-4);
}

// The unknowns the ring fit needs for its mean pressure within 0.05 % of Lame's, quad8 against the
// SAAS element: the same quarter rings (fit::quarter_shrink_fit, plane strain), `radial` elements
// through each ring and 5 radial / 4 radial edges on the shaft's / hub's face (the elements' shape
// kept), refined until the mean of the contact points' pressures is within 0.05 %. The quad8 edges
// follow the circles; the SAAS element's are chords. The table is printed (docs/performance.md).
struct Study {
  int radial = 0;
  std::size_t unknowns = 0;
  FitResult fit;
};

/// The fits of `type` at each radial count, printed as the table's rows.
std::vector<Study> study(ElementType type, std::span<const int> radials) {
  std::vector<Study> rows;
  for (const int r : radials) {
    const Model m = fit::quarter_shrink_fit(r, {5 * r, 4 * r}, 0.0, type);
    rows.push_back({r, 2 * m.nodes.size(), check_fit(m)});
    std::printf("| %s | %d | %d, %d | %zu | %+.4f | %.4f |\n", type == ElementType::quad8 ? "quad8" : "SAAS", r, 5 * r,
                4 * r, rows.back().unknowns, 100 * rows.back().fit.mean, 100 * rows.back().fit.worst);
  }
  return rows;
}

/// The first row whose mean pressure is within `target` (rows.end() if none).
std::vector<Study>::const_iterator first_within(const std::vector<Study>& rows, double target) {
  return std::find_if(rows.begin(), rows.end(), [target](const Study& s) { return std::abs(s.fit.mean) <= target; });
}

TEST(QuadraticContact, UnknownsForTheRingFitsMeanPressureQuad8AgainstTheSaasElement) {
  constexpr double target = 5e-4;
  const std::vector<int> radials = {1, 2, 3, 4, 6, 8};
  std::printf("| element | radial | edges on A, B | unknowns | mean pressure %% | worst point %% |\n");
  const std::vector<Study> quad8 = study(ElementType::quad8, radials);
  const std::vector<Study> saas = study(ElementType::saas, radials);
  // Observed: quad8 within 0.05 % from the coarsest mesh, 1 element through each ring (102 unknowns,
  // -0.0294 %); the SAAS element from 8 (1,332 unknowns, +0.0445 %; 6: 784 unknowns, +0.0806 %).
  const auto q = first_within(quad8, target), s = first_within(saas, target);
  ASSERT_NE(q, quad8.end());
  ASSERT_NE(s, saas.end());
  EXPECT_EQ(q->radial, 1);
  EXPECT_EQ(q->unknowns, 102U);
  EXPECT_NEAR(q->fit.mean, -2.94e-4, 0.05e-4);
  EXPECT_EQ(s->radial, 8);
  EXPECT_EQ(s->unknowns, 1332U);
  EXPECT_NEAR(s->fit.mean, 4.45e-4, 0.05e-4);
  // And quad8 stays within it as the mesh is refined.
  for (const Study& row : quad8) EXPECT_LE(std::abs(row.fit.mean), target) << "radial " << row.radial;
}

/// The axisymmetric slice: the rings as quad8 slabs `height` along z, held in z, the interface a
/// straight line along z with `around` edges on each side.
Model axisymmetric_fit(int radial, std::array<int, 2> along) {
  Model m;
  m.analysis = AnalysisType::axisymmetric;
  m.materials = {testing::isotropic_material(1, fit::E1, fit::nu1), testing::isotropic_material(2, fit::E2, fit::nu2)};
  const double height = 0.2;
  const auto slab = [height](double r0, double r1) {
    return [=](double s, double t) { return Vec2(r0 + s * (r1 - r0), t * height); };
  };
  const testing::QuadraticGrid shaft = testing::add_quadratic_grid(m, ElementType::quad8,
      radial, along[0], slab(fit::a1, fit::b + 0.5 * fit::delta), 0);
  const testing::QuadraticGrid hub = testing::add_quadratic_grid(m, ElementType::quad8,
      radial, along[1], slab(fit::b - 0.5 * fit::delta, fit::b2), 1);
  const auto column = [](const testing::QuadraticGrid& g, int i) {
    Edges edges;
    for (int j = 0; j < g.nj; ++j) edges.push_back({g.corner(i, j), g.corner(i, j + 1)});
    return edges;
  };
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"shaft", column(shaft, radial)}, {"hub", column(hub, 0)}};
  contact.pairs.emplace_back().surfaces = {0, 1};
  for (std::size_t n = 0; n < m.nodes.size(); ++n) testing::constrain(m, static_cast<int>(n), std::nullopt, 0.0);
  testing::fill_temperatures(m, 0.0);
  return m;
}

TEST(QuadraticContact, AxisymmetricLameFitOnQuad8) {
  const FitResult r = check_fit(axisymmetric_fit(4, {3, 5}));
  std::printf("quad8 axisymmetric fit, 3 against 5: mean pressure %+.4f %%, worst point %.4f %%\n", 100 * r.mean,
              100 * r.worst);
  EXPECT_EQ(r.points, 7U);
  EXPECT_LT(r.worst, 1e-4);  // observed 0.0061 % (every point)
}

// ---- Hertz (support/hertz_line_contact.hpp), plane strain, half model: a quad8 block (a / 7 per
// edge near the contact) under a quad8 body whose bottom is the cylinder's parabola z = x^2 / 2R,
// 0.04 = a / 5 per edge along it (mid-side nodes on the parabola). Side A is the block's flat top.

using testing::hertz_a, testing::hertz_E, testing::hertz_nu, testing::hertz_p0, testing::hertz_P, testing::hertz_R,
    testing::hertz_size;

/// The coordinate at grid parameter s in [0, 1] of a graded row xs, half-way between nodes at the
/// mid-side positions.
double graded(const std::vector<double>& xs, double s) {
  const double at = s * static_cast<double>(xs.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at + 1e-9));
  if (std::abs(at - static_cast<double>(lo)) < 1e-9) return xs[lo];
  return 0.5 * (xs[lo] + xs[lo + 1]);
}

Model hertz_model(double block_h, double arc_h) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, hertz_E, hertz_nu)};
  const std::vector<double> xb = testing::hertz_graded(block_h), xc = testing::hertz_graded(arc_h);
  const int nb = static_cast<int>(xb.size()) - 1, nc = static_cast<int>(xc.size()) - 1;
  const testing::QuadraticGrid block = testing::add_quadratic_grid(m, ElementType::quad8,
      nb, nb, [&](double s, double t) { return Vec2(graded(xb, s), -graded(xb, 1.0 - t)); }, 0);
  const testing::QuadraticGrid body = testing::add_quadratic_grid(m, ElementType::quad8, nc, nc,
      [&](double s, double t) {
        const double x = graded(xc, s), z0 = x * x / (2.0 * hertz_R);
        return Vec2(x, z0 + graded(xc, t) * (hertz_size - z0) / hertz_size);
      },
      0);
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"block", block.row_edges(nb)}, {"cylinder", body.row_edges(0)}};
  contact.pairs.emplace_back().surfaces = {0, 1};
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= 2 * nb; ++i) testing::constrain(m, block.at(i, 0), std::nullopt, 0.0);
  for (int j = 0; j <= 2 * nb; ++j) testing::constrain(m, block.at(0, j), 0.0, std::nullopt);  // symmetry x = 0
  for (int j = 0; j <= 2 * nc; ++j) testing::constrain(m, body.at(0, j), 0.0, std::nullopt);
  press(m, body.row_edges(nc), 0.5 * hertz_P / hertz_size);  // half the load on the body's top
  return m;
}

TEST(QuadraticContact, HertzOnQuad8) {
  const Model m = hertz_model(hertz_a / 7.0, 0.04);
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const std::vector<ContactPointResult>& points = s.contact.at(0).points;
  // Fit p^2 = p0^2 (1 - x^2 / a^2) over the touching points well inside the contact.
  double sxx = 0, sx = 0, sy = 0, sxy = 0, count = 0, peak = 0.0;
  for (const ContactPointResult& p : points) {
    if (p.r == 0.0) peak = p.pressure;
    if (p.state != ContactPointState::stick || p.r > 0.8 * hertz_a) continue;
    const double X = p.r * p.r, Y = p.pressure * p.pressure;
    sx += X, sy += Y, sxx += X * X, sxy += X * Y, count += 1;
  }
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / count;
  const double a = std::sqrt(-intercept / slope);
  const Vec2 force = s.contact[0].force;
  std::printf("Hertz on quad8 (a / 7 block, 0.04 arc): peak %.5g vs %.5g (%.3g %%), a %.5g vs %.5g (%.3g %%), "
              "resultant %.3g %%\n", peak, hertz_p0, 100 * (peak / hertz_p0 - 1), a, hertz_a, 100 * (a / hertz_a - 1),
              100 * (-force.y() / (0.5 * hertz_P) - 1));
  // Observed: peak +0.126 %, half-width -0.062 % (the issue asks 1 %; straight 4-node surfaces at the
  // same spacing give the peak 1.5 % low).
  EXPECT_LT(std::abs(peak / hertz_p0 - 1.0), 2e-3);
  EXPECT_LT(std::abs(a / hertz_a - 1.0), 1e-3);
  // The body is held in z by contact alone: the pair's resultant is the load, to round-off.
  EXPECT_NEAR(force.y(), -0.5 * hertz_P, 1e-10 * hertz_P);
  EXPECT_NEAR(force.x(), 0.0, 1e-10 * hertz_P);
  EXPECT_NEAR(reaction_sum(s.reactions).y(), 0.5 * hertz_P, 1e-8 * hertz_P);
}

// ---- Cattaneo-Mindlin on quad8 (as tests/verification/friction_surfaces_test.cpp's, Johnson 7.1):
// the whole Hertz contact, a quad8 block (spacing h near the contact) and a quad8 body (0.72 h along
// the parabola), pressed by a rigid platen (the body's top moved down, step 1), then sheared by
// Q = ratio mu P on its top (step 2, 2 increments); held along x by friction alone. Every node of the
// block's face is a contact point, mid-side nodes included.

constexpr double mu = 0.3;

struct CattaneoResult {
  double a = 0.0;  ///< Hertz half-width for the measured P
  double c = 0.0;  ///< measured stick half-width
  double h = 0.0;  ///< edge length at the contact
};

CattaneoResult cattaneo(double h, double ratio) {
  constexpr double sink = 0.006;
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, hertz_E, hertz_nu)};
  const std::vector<double> xb = testing::hertz_mirrored(testing::hertz_graded(h)),
                            xc = testing::hertz_mirrored(testing::hertz_graded(0.72 * h));
  const std::vector<double> depth = testing::hertz_graded(h);
  const int nb = static_cast<int>(xb.size()) - 1, nc = static_cast<int>(xc.size()) - 1;
  const int nd = static_cast<int>(depth.size()) - 1;
  const testing::QuadraticGrid block = testing::add_quadratic_grid(m, ElementType::quad8,
      nb, nd, [&](double s, double t) { return Vec2(graded(xb, s), -graded(depth, 1.0 - t)); }, 0);
  const testing::QuadraticGrid body = testing::add_quadratic_grid(m, ElementType::quad8, nc, nd,
      [&](double s, double t) {
        const double x = graded(xc, s), z0 = x * x / (2.0 * hertz_R);
        return Vec2(x, z0 + graded(depth, t) * (hertz_size - z0) / hertz_size);
      },
      0);
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"block", block.row_edges(nd)}, {"cylinder", body.row_edges(0)}};
  SurfacePair& pair = contact.pairs.emplace_back();
  pair.surfaces = {0, 1};
  pair.friction = mu;
  testing::fill_temperatures(m, 0.0);
  for (const int n : block.row_nodes(0)) testing::constrain(m, n, 0.0, 0.0);
  Step press;
  press.name = "press";
  for (const int n : body.row_nodes(nd)) press.constraints.push_back({n, std::nullopt, -sink});
  m.steps = {press};
  CattaneoResult r;
  r.h = h;
  const Solution pressed = solve(m);
  EXPECT_EQ(pressed.status, RunStatus::converged) << pressed.message;
  double P = 0.0;
  const std::vector<int> top = body.row_nodes(nd);
  for (const NodeReaction& n : pressed.reactions) {
    for (const int t : top) {
      if (n.id == m.nodes[static_cast<std::size_t>(t)].id) P -= n.f_z;
    }
  }
  r.a = std::sqrt(4.0 * P * hertz_R / (std::numbers::pi * testing::hertz_E_star));
  Step shear;
  shear.name = "shear";
  shear.increments = 2;
  shear.loads = m.loads;
  // A shear traction along +x (a -> b on the top's edges, which run left to right).
  for (const auto& e : body.row_edges(nd)) {
    shear.loads->pressures.push_back({owner(m, e[0], e[1]), e[0], e[1], 0.0, ratio * mu * P / (2.0 * hertz_size)});
  }
  m.steps = {press, shear};
  const Solution s = solve(m);
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  if (s.contact.empty()) return r;
  double lo = 0.0, hi = 0.0;
  for (const ContactPointResult& p : s.contact[0].points) {
    if (p.state != ContactPointState::stick) continue;
    lo = std::min(lo, p.r);
    hi = std::max(hi, p.r);
  }
  r.c = 0.5 * (hi - lo);
  return r;
}

TEST(QuadraticContact, CattaneoMindlinStickZoneOnQuad8) {
  constexpr double ratio = 0.5;  // Q / (mu P)
  const CattaneoResult r = cattaneo(hertz_a / 6.0, ratio);
  const double c = r.a * std::sqrt(1.0 - ratio);
  std::printf("Cattaneo-Mindlin on quad8, h = %.4g: a %.4g, c / a %.4f (closed form %.4f), |c - c_exact| %.3g "
              "(bound h + 5 %% c = %.3g)\n", r.h, r.a, r.c / r.a, c / r.a, std::abs(r.c - c), r.h + 0.05 * c);
  EXPECT_NEAR(r.c, c, r.h + 0.05 * c);  // the bound
  EXPECT_NEAR(r.c, c, 0.01);             // observed 0.0069 (points every h / 2)
}

// The eccentric ring fit on quad8 (the benchmark's `--quad8 --eccentric 2` at 8 elements through
// each ring: 183 against 146 edges, 367 rows, 17,108 unknowns): the bore widened from 0 at 0 degrees
// to two interferences at 90, so 46 rows end in contact where the first set holds all 367. With the
// penalty capped at 4 Jacobi stiffnesses (ConstraintRows::jacobi_multiple) and a look-ahead window
// of every row (ExactContact::max_window 512), the look-ahead from the first set finds the final
// set, which is solved on the first factorization through a correction of the 321 rows that
// change: 2 active sets, 1 factorization, 4 solves (observed; 16 sets, 2 factorizations and 19
// solves before, with the same 46 rows in contact). docs/performance.md, quad8 contact surfaces.
TEST(QuadraticContact, EccentricQuad8FitSettlesFromItsFirstFactorization) {
  const Model m = fit::quarter_shrink_fit(8, {183, 146}, 2.0);
  const SurfaceContact surfaces = surface_contact(m);
  ASSERT_EQ(surfaces.pairs.pairs.size(), 367U);
  const DofMap dofs(m);
  ASSERT_EQ(dofs.size(), 17108);
  StiffnessSystem system(m, dofs, contact_couplings(surfaces, dofs));
  const SolidMaterials materials(m);
  const MaterialState state = materials.initial();
  system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
  SparseCholesky cholesky(system.pattern(), dofs.node_of_equation());
  std::vector<double> u(static_cast<std::size_t>(dofs.size()));
  ExactContact contact(m, dofs, system.pattern(), surfaces.pairs);
  ContactState cold;
  const ContactReport report = contact.solve(cholesky, system.values(), system.rhs(), cold, u);
  EXPECT_EQ(report.active_set_iterations, 2);
  EXPECT_EQ(report.factorizations, 1);
  EXPECT_EQ(report.multiplier_iterations, 4);
  EXPECT_EQ(report.pairs_in_contact, 46);
  EXPECT_LT(report.complementarity, 1e-11);  // observed 2.25e-13 (the round-off criterion 1e-11)
}

}  // namespace
}  // namespace saasgaps
