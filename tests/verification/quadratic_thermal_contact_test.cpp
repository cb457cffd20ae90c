// Heat across contact pairs (model.contact with `conductance`) whose surfaces are 3-node edges of quad8
// elements: the mortar rows of docs/contact-surfaces.md section 7 carry the conductance
// (contact_conductance.hpp) as straight rows do. Closed forms derived here.
//
// Flat blocks. Two blocks of conductivity k1 (0 < z < 1) and k2 (1 < z < 2) over 1 < r < 3 touch at
// z = 1 on non-matching graded meshes (5 edges against 7, mid-side nodes at the grading's mid
// parameter, off the middle), T = T0 at z = 0 and T1 at z = 2, the sides insulated. The flux is
// uniform, q = (T0 - T1) / (1 / k1 + 1 / h + 1 / k2) (power / area, along +z), T = T0 - q z / k1 below
// and T1 + q (2 - z) / k2 above, a jump q / h across the interface: linear in each block, so quad8
// holds it and the rows (a uniform jump gives g_j = D_j (T_B - T_A) exactly) pass h D_j (T_A - T_B)
// at node j, a uniform flux's consistent nodal heat: exact to round-off, in plane stress and
// axisymmetry, either side as A.
//
// Concentric cylinders. Ring a < r < b of k1 inside ring b < r < c of k2, touching at r = b (plane:
// quarter rings whose mid-side nodes lie on the circles, so the interface is curved; axisymmetric:
// a slab along z), T(a) = Ta, T(c) = Tc, the other sides insulated. T depends on r only and
// q = k r |dT/dr| (power per radian and per thickness, plane; per radian and length, axisymmetric) is
// the same through every circle. Fourier's law integrated over each ring and the interface, which
// passes h (T_A - T_B) per area of side A at r = b, gives three resistances in series:
//   R = ln(b / a) / k1 + 1 / (h b) + ln(c / b) / k2,   q = (Ta - Tc) / R,
//   T = Ta - (q / k1) ln(r / a) (a <= r <= b),   T = Tc + (q / k2) ln(c / r) (b <= r <= c),
// and T jumps by q / (h b) at r = b. The heat through the model is Q = q x angle x thickness (plane,
// a quarter: angle pi / 2) or q x 2 pi x height (axisymmetric): the heat in at r = a (the held nodes'
// reactions), across the interface (the rows) and out at r = c must balance, and match Q.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>

#include "solver/analysis/analysis.hpp"
#include "solver/thermal/contact_conductance.hpp"
#include "solver/thermal/isoparametric_conduction.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/mesh_builder.hpp"
#include "support/shrink_fit_rings.hpp"

namespace saasgaps {
namespace {

using Edges = std::vector<std::array<int, 2>>;

Material conductor(int id, double k, double E = 1.0e6, double nu = 0.3) {
  Material m = testing::isotropic_material(id, E, nu);
  m.table[0].k1 = m.table[0].k2 = m.table[0].k3 = k;
  m.conducts = true;
  return m;
}

/// The heat flowing into the elements [first, last) at the given nodes: sum over those elements of
/// (K_e T_e) at the nodes (the reactions of held nodes, when nothing else touches them).
double heat_in(const Model& m, std::size_t first, std::size_t last, const std::set<int>& at, const std::vector<double>& T) {
  double total = 0.0;
  for (std::size_t e = first; e < last; ++e) {
    const Element& el = m.elements[e];
    const Material& mat = m.materials[static_cast<std::size_t>(el.material)];
    IsoConductionData d;
    d.type = el.type;
    d.node_count = el.node_count;
    for (int i = 0; i < el.node_count; ++i) {
      const Node& n = m.nodes[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(i)])];
      d.x[static_cast<std::size_t>(i)] = Vec2(n.r, n.z);
    }
    d.analysis = m.analysis;
    d.thickness = m.thickness;
    d.k = {mat.table[0].k1, mat.table[0].k2, 0.0};
    const IsoConductionParts p = isoparametric_conduction_parts(d);
    for (int i = 0; i < el.node_count; ++i) {
      if (!at.contains(el.nodes[static_cast<std::size_t>(i)])) continue;
      for (int j = 0; j < el.node_count; ++j) total += p.K(i, j) * T[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(j)])];
    }
  }
  return total;
}

/// The heat the interface passes from side A to side B: the rows' heat into B's nodes, -(K_row T).
double heat_across(const ContactConductance& pairs, std::span<const double> H, const std::set<int>& b_nodes,
                   const std::vector<double>& T) {
  double total = 0.0;
  for (std::size_t r = 0; r < pairs.row_count(); ++r) {
    const std::span<const int> nodes = pairs.nodes(r);
    Eigen::VectorXd t(static_cast<Eigen::Index>(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k) t[static_cast<Eigen::Index>(k)] = T[static_cast<std::size_t>(nodes[k])];
    const Eigen::VectorXd into = -(pairs.block(r, H[r]) * t);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (b_nodes.contains(nodes[k])) total += into[static_cast<Eigen::Index>(k)];
    }
  }
  return total;
}

std::set<int> set_of(const std::vector<int>& nodes) { return {nodes.begin(), nodes.end()}; }

// ---- Flat blocks: uniform flux, exact -------------------------------------------------------------

struct FlatCase {
  const char* name;
  AnalysisType analysis;
  bool lower_is_a;
};

TEST(QuadraticThermalContact, UniformFluxAcrossNonMatchingQuad8BlocksIsExact) {
  constexpr double k1 = 2.0, k2 = 5.0, h = 1.5, T0 = 300.0, T1 = 100.0;
  const double q = (T0 - T1) / (1.0 / k1 + 1.0 / h + 1.0 / k2);
  for (const FlatCase& c : {FlatCase{"plane stress, lower is A", AnalysisType::plane_stress, true},
                            FlatCase{"plane stress, upper is A", AnalysisType::plane_stress, false},
                            FlatCase{"axisymmetric, lower is A", AnalysisType::axisymmetric, true},
                            FlatCase{"axisymmetric, upper is A", AnalysisType::axisymmetric, false}}) {
    SCOPED_TRACE(c.name);
    Model m;
    m.analysis = c.analysis;
    m.thickness = 0.4;
    m.materials = {conductor(1, k1), conductor(2, k2)};
    const auto graded = [](double grading, double z0) {
      return [=](double s, double t) { return Vec2(1.0 + 2.0 * std::pow(s, grading), z0 + t); };
    };
    const testing::QuadraticGrid lower = testing::add_quadratic_grid(m, ElementType::quad8, 5, 2, graded(1.3, 0.0), 0);
    const std::size_t lower_elements = m.elements.size();
    const testing::QuadraticGrid upper = testing::add_quadratic_grid(m, ElementType::quad8, 7, 3, graded(0.75, 1.0), 1);
    ContactSettings& contact = m.contact.emplace();
    contact.surfaces = {{"lower top", lower.row_edges(lower.nj)}, {"upper bottom", upper.row_edges(0)}};
    SurfacePair& pair = contact.pairs.emplace_back();
    pair.surfaces = c.lower_is_a ? std::array<int, 2>{0, 1} : std::array<int, 2>{1, 0};
    pair.conductance = InterfaceConductance{{{0.0, h}}, 0.0};
    m.thermal.emplace();
    const std::vector<ThermalEdge> bottom = testing::quadratic_grid_side(m, lower, 'b');
    const std::vector<ThermalEdge> top = testing::quadratic_grid_side(m, upper, 't');
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, bottom, T0, 0.0});
    m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, top, T1, 0.0});

    const ThermalResult r = solve_steady_conduction(m);
    double worst = 0.0;
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      const double z = m.nodes[n].z;
      const bool below = n < static_cast<std::size_t>(upper.nodes.front());
      const double exact = below ? T0 - q * z / k1 : T1 + q * (2.0 - z) / k2;
      worst = std::max(worst, std::abs(r.T[n] - exact));
    }
    EXPECT_LT(worst, 2e-10 * (T0 - T1));  // observed: 4e-13 with the lower block as A, 4e-11 the upper
    std::printf("  worst T %.1e of T0 - T1\n", worst / (T0 - T1));

    // The heat: in at z = 0, across the interface, out at z = 2, each q times the face's area.
    const double area = c.analysis == AnalysisType::axisymmetric ? std::numbers::pi * (9.0 - 1.0) : 2.0 * m.thickness;
    const ContactConductance pairs(m);
    const std::vector<double> H = pairs.conductances({});
    const std::set<int> b_nodes = set_of(c.lower_is_a ? upper.row_nodes(0) : lower.row_nodes(lower.nj));
    const double across = (c.lower_is_a ? 1.0 : -1.0) * heat_across(pairs, H, b_nodes, r.T);
    const double in = heat_in(m, 0, lower_elements, set_of(lower.row_nodes(0)), r.T);
    const double out = -heat_in(m, lower_elements, m.elements.size(), set_of(upper.row_nodes(upper.nj)), r.T);
    EXPECT_NEAR(in, q * area, 1e-10 * q * area);
    EXPECT_NEAR(across, q * area, 1e-10 * q * area);
    EXPECT_NEAR(out, q * area, 1e-10 * q * area);
  }
}

// ---- Concentric cylinders: log profiles and the jump ----------------------------------------------

struct Cylinders {
  double a = 1.0, b = 2.0, c = 3.0, k1 = 2.0, k2 = 5.0, Ta = 500.0, Tc = 100.0, h = 1.5;
  double b_outer = 2.0;  ///< the outer ring's inner radius (b - interference on a fit)
  [[nodiscard]] double flow() const {
    return (Ta - Tc) / (std::log(b / a) / k1 + 1.0 / (h * b) + std::log(c / b_outer) / k2);
  }
  [[nodiscard]] double exact(double r, bool inner) const {
    return inner ? Ta - flow() / k1 * std::log(r / a) : Tc + flow() / k2 * std::log(c / r);
  }
  [[nodiscard]] double jump() const { return flow() / (h * b); }
};

struct CylinderModel {
  Model model;
  std::size_t inner_elements = 0;  ///< the inner ring's elements come first
  double angle = 0.0;              ///< the model's angle about the axis (radians)
};

/// The edges of elements [first, last) whose corners both lie at radius r (plane: distance from the
/// origin; axisymmetric: r), as thermal edges.
std::vector<ThermalEdge> edges_at(const Model& m, std::size_t first, std::size_t last, double r) {
  const auto radius = [&](int n) {
    const Node& x = m.nodes[static_cast<std::size_t>(n)];
    return m.analysis == AnalysisType::axisymmetric ? x.r : std::hypot(x.r, x.z);
  };
  std::vector<ThermalEdge> edges;
  for (std::size_t e = first; e < last; ++e) {
    const Element& el = m.elements[e];
    for (std::size_t k = 0; k < 4; ++k) {
      const int a = el.nodes[k], b = el.nodes[(k + 1) % 4];
      if (std::abs(radius(a) - r) < 1e-12 * r && std::abs(radius(b) - r) < 1e-12 * r) {
        edges.push_back({static_cast<int>(e), a, b});
      }
    }
  }
  return edges;
}

/// The nodes of elements [first, last) at radius r, mid-side nodes included.
std::set<int> nodes_at(const Model& m, std::size_t first, std::size_t last, double r) {
  std::set<int> out;
  for (const ThermalEdge& e : edges_at(m, first, last, r)) {
    for (const int n : m.elements[static_cast<std::size_t>(e.element)].node_span()) {
      const Node& x = m.nodes[static_cast<std::size_t>(n)];
      const double rn = m.analysis == AnalysisType::axisymmetric ? x.r : std::hypot(x.r, x.z);
      if (std::abs(rn - r) < 1e-12 * r) out.insert(n);
    }
  }
  return out;
}

/// Conduction from r = a (Ta) to r = c (Tc) on a model of two rings: the inner ring's elements first.
void hold_faces(const Cylinders& t, CylinderModel& c) {
  Model& m = c.model;
  m.thermal.emplace();
  m.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, edges_at(m, 0, c.inner_elements, t.a), t.Ta, 0.0});
  m.thermal->boundary.push_back(
      {ThermalBoundary::Kind::temperature, edges_at(m, c.inner_elements, m.elements.size(), t.c), t.Tc, 0.0});
}

/// The two rings, `radial` quad8 through each, around[0] edges on the inner ring's face (side A),
/// around[1] on the outer one's (side B). Plane: quarter rings, grid i radial, j round; axisymmetric:
/// slabs of height 0.2 along z.
CylinderModel cylinders(const Cylinders& t, AnalysisType analysis, int radial, std::array<int, 2> around,
                        const InterfaceConductance& conductance) {
  CylinderModel out;
  Model& m = out.model;
  m.analysis = analysis;
  m.thickness = 0.4;
  m.materials = {conductor(1, t.k1), conductor(2, t.k2)};
  const bool plane = analysis != AnalysisType::axisymmetric;
  out.angle = plane ? 0.5 * std::numbers::pi : 2.0 * std::numbers::pi;
  const auto ring = [plane](double r0, double r1) {
    return [=](double s, double u) {
      const double r = r0 + s * (r1 - r0);
      if (!plane) return Vec2(r, 0.2 * u);
      const double angle = u * std::numbers::pi / 2.0;
      return Vec2(r * std::cos(angle), r * std::sin(angle));
    };
  };
  const testing::QuadraticGrid inner = testing::add_quadratic_grid(m, ElementType::quad8, radial, around[0], ring(t.a, t.b), 0);
  out.inner_elements = m.elements.size();
  const testing::QuadraticGrid outer = testing::add_quadratic_grid(m, ElementType::quad8, radial, around[1], ring(t.b, t.c), 1);
  const auto column = [](const testing::QuadraticGrid& g, int i) {
    Edges edges;
    for (int j = 0; j < g.nj; ++j) edges.push_back({g.corner(i, j), g.corner(i, j + 1)});
    return edges;
  };
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"inner", column(inner, radial)}, {"outer", column(outer, 0)}};
  SurfacePair& pair = contact.pairs.emplace_back();
  pair.surfaces = {0, 1};
  pair.conductance = conductance;
  hold_faces(t, out);
  return out;
}

struct CylinderErrors {
  double T = 0.0;        ///< worst |T - exact| over the nodes, of Ta - Tc
  double jump = 0.0;     ///< worst |jump - q / (h b)| over side A's nodes, of q / (h b)
  double heat = 0.0;     ///< worst of the three heats (in, across, out) against Q, relative
  double balance = 0.0;  ///< largest difference of the three heats, of Q
};

CylinderErrors cylinder_errors(const Cylinders& t, const CylinderModel& c, const ThermalResult& r,
                               std::span<const double> H) {
  const Model& m = c.model;
  const std::size_t n_inner = c.inner_elements, n_all = m.elements.size();
  CylinderErrors err;
  for (std::size_t e = 0; e < n_all; ++e) {
    for (const int n : m.elements[e].node_span()) {
      const Node& x = m.nodes[static_cast<std::size_t>(n)];
      const double radius = m.analysis == AnalysisType::axisymmetric ? x.r : std::hypot(x.r, x.z);
      const double d = std::abs(r.T[static_cast<std::size_t>(n)] - t.exact(radius, e < n_inner));
      err.T = std::max(err.T, d / (t.Ta - t.Tc));
    }
  }
  // Side B's face is an isotherm (to discretisation error): its mean is T_B.
  const std::set<int> b_face = nodes_at(m, n_inner, n_all, t.b_outer);
  double tb = 0.0;
  for (const int n : b_face) tb += r.T[static_cast<std::size_t>(n)];
  tb /= static_cast<double>(b_face.size());
  for (const int n : nodes_at(m, 0, n_inner, t.b)) {
    err.jump = std::max(err.jump, std::abs(r.T[static_cast<std::size_t>(n)] - tb - t.jump()) / t.jump());
  }
  const double height = m.analysis == AnalysisType::axisymmetric ? 0.2 : m.thickness;
  const double Q = t.flow() * c.angle * height;
  const ContactConductance pairs(m);
  const double in = heat_in(m, 0, n_inner, nodes_at(m, 0, n_inner, t.a), r.T);
  const double across = heat_across(pairs, H, b_face, r.T);
  const double out = -heat_in(m, n_inner, n_all, nodes_at(m, n_inner, n_all, t.c), r.T);
  for (const double v : {in, across, out}) err.heat = std::max(err.heat, std::abs(v - Q) / Q);
  err.balance = std::max({std::abs(in - across), std::abs(across - out), std::abs(in - out)}) / Q;
  std::printf("  T %.2e, jump %.2e, heat %.2e (Q %.6g, in %.6g, across %.6g, out %.6g), balance %.1e\n", err.T,
              err.jump, err.heat, Q, in, across, out, err.balance);
  return err;
}

TEST(QuadraticThermalContact, ConcentricCylindersOnCurvedQuad8FacesHaveBothLogProfilesAndTheJump) {
  const Cylinders t;
  for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
    SCOPED_TRACE(analysis == AnalysisType::axisymmetric ? "axisymmetric" : "plane stress (quarter rings)");
    // Non-matching: 5 edges of side A against 7 of side B (plane: on the quarter circle).
    const CylinderModel c = cylinders(t, analysis, 4, {5, 7}, InterfaceConductance{{{0.0, t.h}}, 0.0});
    const ThermalResult r = solve_steady_conduction(c.model);  // before any stress solve: touching at gap 0
    const ContactConductance pairs(c.model);
    ASSERT_EQ(pairs.row_count(), 11U);  // every node of side A, mid-side nodes included
    const CylinderErrors e = cylinder_errors(t, c, r, pairs.conductances({}));
    // The issue asks 0.2 %; 4 quad8 through each ring give about 1e-5 (observed: T 6.9e-6 and 9.2e-6,
    // jump 1.6e-5 and 3.3e-6, heat 1.1e-6 and 3.3e-6, plane and axisymmetric).
    EXPECT_LT(e.T, 2e-5);
    EXPECT_LT(e.jump, 3e-5);
    EXPECT_LT(e.heat, 1e-5);
    EXPECT_LT(e.balance, 1e-10);
    // The interface is a sizeable share of the whole resistance, so the jump is tested, not noise.
    EXPECT_GT(t.jump(), 0.2 * (t.Ta - t.Tc));
  }
}

// Coupled with the contact state: the plane-strain quarter ring fit of quad8 (20 edges against 16 on
// the curved faces, support/shrink_fit_rings.hpp) conducts h(p) of a table at each point's contact
// pressure. The materials do not expand (alpha = 0), so the stresses are Lame's whatever T is and
// every point's h is the table's at Lame's pressure p: the temperatures must be the cylinders' closed
// form with that h (a = 1, side A at b + delta / 2, side B at b - delta / 2, c = 2.2).
TEST(QuadraticThermalContact, ARingFitOnQuad8ConductsAtItsContactPressure) {
  namespace fit = testing::shrink_fit_rings;
  const int radial = 4;
  CylinderModel c{fit::quarter_shrink_fit(radial, {20, 16}), static_cast<std::size_t>(radial * 20),
                  0.5 * std::numbers::pi};
  Model& m = c.model;
  Cylinders t;
  t.a = fit::a1;
  t.b = fit::b + 0.5 * fit::delta;
  t.b_outer = fit::b - 0.5 * fit::delta;
  t.c = fit::b2;
  const double p = fit::lame_interference_pressure(AnalysisType::plane_strain);
  const InterfaceConductance table{{{0.0, 0.5}, {100.0, 2.5}}, 0.0};
  t.h = closed_conductance(table, p);
  for (std::size_t k = 0; k < 2; ++k) {
    m.materials[k].table[0].k1 = m.materials[k].table[0].k2 = m.materials[k].table[0].k3 = k == 0 ? t.k1 : t.k2;
    m.materials[k].conducts = true;
  }
  m.contact->pairs[0].conductance = table;
  hold_faces(t, c);

  const Solution s = solve_with_heat(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_TRUE(s.thermal.has_value());
  ASSERT_EQ(s.contact.size(), 1U);
  ASSERT_EQ(s.contact[0].points.size(), 41U);
  const ContactConductance pairs(m);
  const std::vector<double> H = pairs.conductances(s.contact);
  for (std::size_t j = 0; j < H.size(); ++j) {
    EXPECT_NE(s.contact[0].points[j].state, ContactPointState::open) << "point " << j;
    EXPECT_NEAR(H[j], t.h, 5e-4 * t.h) << "point " << j;  // the points' pressures are Lame's within 0.02 %
  }
  const CylinderErrors e = cylinder_errors(t, c, *s.thermal, H);
  // Observed: T 9.4e-7, jump 4.0e-7, heat 3.0e-7 (the issue asks 0.2 %).
  EXPECT_LT(e.T, 3e-6);
  EXPECT_LT(e.jump, 2e-6);
  EXPECT_LT(e.heat, 1e-6);
  EXPECT_LT(e.balance, 1e-10);
  // Before any stress solve the points conduct h(0): the pressure's h is far from it, so a run that
  // ignored the contact state would miss the closed form.
  EXPECT_GT(t.h, 3.0 * pairs.conductances({}).front());
}

}  // namespace
}  // namespace saasgaps
