// Recovered stresses and error estimates (solver/recovery) against closed forms and converged
// references, every model written as a JSON document and read through io::read_model:
//
// 1. NAFEMS LE1, the elliptic membrane (plane stress, t = 0.1, E = 210e3, nu = 0.3, 10 MPa outward
//    on the outer ellipse; target sigma_yy = 92.7 MPa at D = (2, 0)): the recovered nodal value at D
//    against the element-centre value, the SAAS element at 16 x 16 and quad8 at 8 x 8.
// 2. Lame's thick cylinder, 4 axisymmetric quad8 through the wall: the recovered hoop stress at the bore.
// 3. The estimate: error^2 = sum of the elements' error^2; its effectivity index (estimate / true
//    error) where the true error in the energy norm is, for a conforming displacement model with
//    consistent loads and homogeneous supports (Galerkin orthogonality),
//        ||u - u_h||_E^2 = a(u, u) - a(u_h, u_h),   a(v, v) = integral sigma(v) : D^-1 : sigma(v) dV,
//    with a(u_h, u_h) = sum_e u_e^T K_e u_e computed here from the element kernels (not from the
//    estimate's integrals) and a(u, u) either the closed form (Lame: the external work
//    p 2 pi a h u(a)) or the converged limit of a(u_h, u_h) over a sequence of meshes halving h,
//    extrapolated by Aitken's delta-squared (the energy converges geometrically in h, whatever the
//    rate: 2p on a smooth problem, 2 lambda at a singularity).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/fe/element_kernel.hpp"
#include "solver/materials/material.hpp"
#include "solver/recovery/patch_recovery.hpp"
#include "solver/recovery/symmetry_lines.hpp"

namespace saasgaps {
namespace {

using nlohmann::json;

/// A mesh on a lattice of parameter points (I, J), each mapped to (r, z); one element spans 1
/// lattice step (saas) or 2 (quad8, whose mid-side nodes sit on the odd points).
struct LatticeMesh {
  std::map<std::pair<int, int>, int> id;  ///< lattice point -> node id
  json nodes = json::array();
  json elements = json::array();
  int step = 1;
};

/// Adds the elements of the lattice block [I0, I1] x [J0, J1] (in element counts ni x nj from I0, J0).
void add_block(LatticeMesh& m, const std::string& type, int I0, int J0, int ni, int nj,
               const std::function<std::pair<double, double>(int, int)>& at) {
  const int s = m.step;
  const auto node = [&](int I, int J) {
    const auto key = std::make_pair(I, J);
    const auto found = m.id.find(key);
    if (found != m.id.end()) return found->second;
    const int id = static_cast<int>(m.id.size()) + 1;
    const auto [r, z] = at(I, J);
    m.nodes.push_back({{"id", id}, {"r", r}, {"z", z}});
    m.id[key] = id;
    return id;
  };
  for (int j = 0; j < nj; ++j) {
    for (int i = 0; i < ni; ++i) {
      const int I = I0 + s * i, J = J0 + s * j;
      json n = {node(I, J), node(I + s, J), node(I + s, J + s), node(I, J + s)};
      if (type == "quad8") {
        for (const auto& [a, b] : {std::pair{I + 1, J}, {I + 2, J + 1}, {I + 1, J + 2}, {I, J + 1}}) n.push_back(node(a, b));
      }
      m.elements.push_back({{"id", m.elements.size() + 1}, {"nodes", n}, {"material", 1}, {"type", type}});
    }
  }
}

json model_document(const LatticeMesh& m, const std::string& analysis, double E, double nu, double thickness) {
  json doc = {{"schema_version", 1}, {"title", "recovery"}, {"analysis", {{"type", analysis}}}};
  if (analysis != "axisymmetric") doc["analysis"]["thickness"] = thickness;
  doc["nodes"] = m.nodes;
  doc["materials"] = json::array(
      {{{"id", 1}, {"elastic", "isotropic"}, {"table", json::array({{{"T", 0.0}, {"E", E}, {"nu", nu}, {"alpha", 0.0}}})}}});
  doc["elements"] = m.elements;
  doc["constraints"] = json::array();
  doc["loads"] = {{"pressures", json::array()}};
  return doc;
}

/// a(u_h, u_h) = sum_e u_e^T K_e u_e from the element kernels (linear elastic, no initial strain).
double discrete_energy(const Model& model, const Solution& s) {
  std::vector<double> u;
  for (const NodeResult& n : s.nodes) {
    u.push_back(n.u_r);
    u.push_back(n.u_z);
  }
  double energy = 0.0;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    const Material& mat = model.materials[static_cast<std::size_t>(el.material)];
    const Constitutive law = constitutive(interpolate(mat.table, 0.0, mat.isotropic), model.analysis, el.angle_deg);
    const ElementData data = solid_element_data(model, e, law);
    const ElementMatrices k = element_matrices(data);
    const ElementVector ue = element_displacements(u, el.node_span());
    const ElementMatrix K = k.K.selfadjointView<Eigen::Upper>();
    energy += ue.dot(K * ue);
  }
  return energy;
}

/// Aitken's delta-squared limit of three values of a sequence converging geometrically.
double aitken(double a0, double a1, double a2) { return a2 - (a2 - a1) * (a2 - a1) / ((a2 - a1) - (a1 - a0)); }

// ---- 1. NAFEMS LE1.

struct Le1 {
  Model model;
  Solution solution;
  int D = 0;  ///< node index of D
};

Le1 le1(const std::string& type, int n) {
  LatticeMesh m;
  m.step = type == "quad8" ? 2 : 1;
  const int lattice = m.step * n;
  const auto at = [&](int I, int J) {
    const double s = static_cast<double>(I) / lattice, t = std::numbers::pi / 2.0 * J / lattice;
    return std::pair{(1.0 - s) * 2.0 * std::cos(t) + s * 3.25 * std::cos(t), (1.0 - s) * std::sin(t) + s * 2.75 * std::sin(t)};
  };
  add_block(m, type, 0, 0, n, n, at);
  json doc = model_document(m, "plane_stress", 210.0e3, 0.3, 0.1);
  for (const auto& [key, id] : m.id) {
    if (key.second == 0) doc["constraints"].push_back({{"node", id}, {"z", 0.0}});
    if (key.second == lattice) doc["constraints"].push_back({{"node", id}, {"r", 0.0}});
  }
  for (int J = 0; J < lattice; J += m.step) {
    doc["loads"]["pressures"].push_back({{"nodes", {m.id.at({lattice, J}), m.id.at({lattice, J + m.step})}}, {"normal", -10.0}});
  }
  Le1 out{io::read_model(doc), {}, m.id.at({0, 0}) - 1};
  out.solution = solve(out.model);
  EXPECT_EQ(out.solution.status, RunStatus::converged) << out.solution.message;
  return out;
}

constexpr double le1_target = 92.7;

TEST(RecoveryLe1, SaasSixteenBySixteenRecoversSigmaYyAtD) {
  const Le1 c = le1("saas", 16);
  const double recovered = c.solution.recovered.mean(static_cast<std::size_t>(c.D))[zz];
  const double centre = c.solution.elements[0].stress[zz];
  std::printf("LE1 saas 16 x 16: recovered %.3f (%+.4f), element centre %.3f (%+.4f)\n", recovered,
              recovered / le1_target - 1.0, centre, centre / le1_target - 1.0);
  EXPECT_NEAR(centre / le1_target - 1.0, -0.1625, 0.002);  // observed -0.1625
  // Observed -0.0215 (the issue asks within 3 %). D is a free boundary node on the symmetry line:
  // sigma_xx = sigma_xy = 0 there and sigma_yy = E eps_yy from the stretch of the inner edge through
  // D (boundary_stresses.hpp).
  EXPECT_NEAR(recovered / le1_target - 1.0, -0.0215, 0.002);
  EXPECT_LT(std::abs(recovered / le1_target - 1.0), 0.03);
  // The patches alone (docs/recovery.md), extrapolated to D from each element's sample, its centre
  // stress: observed -6.81 % (-4.94 % when the element was sampled at its four triangles'
  // centroids instead).
  std::vector<ElementSamples> samples(c.model.elements.size());
  for (std::size_t e = 0; e < samples.size(); ++e) {
    const ElementData geometry = solid_element_geometry(c.model, e);
    const ElementState state{Vec4::Zero(), c.solution.elements[e].stress};
    samples[e] = stress_samples(geometry, std::span<const ElementState>(&state, 1));
  }
  const SymmetryLines lines = stress_symmetry_lines(c.model);
  const double patches = recover_field(c.model, samples, &lines).mean(static_cast<std::size_t>(c.D))[zz];
  std::printf("LE1 saas 16 x 16: the patches alone %.3f (%+.4f)\n", patches, patches / le1_target - 1.0);
  EXPECT_NEAR(patches / le1_target - 1.0, -0.0681, 0.002);
}

TEST(RecoveryLe1, Quad8RecoversSigmaYyAtDAndConverges) {
  // 8 x 8, 16 x 16, 32 x 32. The issue asks 1 % at 8 x 8. D from its traction and the stretch
  // through the five nodes of the inner edge and its mirror image; the patches alone, extrapolated
  // to D: +1.29 %, +0.41 %, -0.03 % (plain SPR: +5.09 %, +1.22 %, +0.06 %).
  const std::array<double, 3> observed{-0.0057, -0.0010, -0.0005};
  for (int k = 0; k < 3; ++k) {
    const int n = 8 << k;
    const Le1 c = le1("quad8", n);
    const double recovered = c.solution.recovered.mean(static_cast<std::size_t>(c.D))[zz];
    const double centre = c.solution.elements[0].stress[zz];
    std::printf("LE1 quad8 %d x %d: recovered %.3f (%+.4f), element centre %.3f (%+.4f)\n", n, n, recovered,
                recovered / le1_target - 1.0, centre, centre / le1_target - 1.0);
    EXPECT_NEAR(recovered / le1_target - 1.0, observed[static_cast<std::size_t>(k)], 0.001) << n;
    EXPECT_LT(std::abs(recovered / le1_target - 1.0), 0.01) << n;
  }
}

// ---- 2. Lame's thick cylinder (a = 1, b = 2, p = 1000, E = 30e6, nu = 0.3), a slice of height h held
// along z top and bottom: sigma_theta = A + B / r^2, u(r) = (1 + nu) / E ((1 - 2 nu) A r + B / r).

constexpr double la = 1.0, lb = 2.0, lp = 1000.0, lE = 30.0e6, lnu = 0.3;
constexpr double lA = lp * la * la / (lb * lb - la * la), lB = lp * la * la * lb * lb / (lb * lb - la * la);

struct Lame {
  Model model;
  Solution solution;
  double height = 0.0;
  int bore = 0;  ///< node index of the bore's corner node at mid-height (a, h / 2)
};

Lame lame(const std::string& type, int radial, int rows) {
  LatticeMesh m;
  m.step = type == "quad8" ? 2 : 1;
  const int lattice = m.step * radial;
  const double height = (lb - la) / radial * rows;
  add_block(m, type, 0, 0, radial, rows, [&](int I, int J) {
    return std::pair{la + (lb - la) * I / lattice, height * J / (m.step * rows)};
  });
  json doc = model_document(m, "axisymmetric", lE, lnu, 1.0);
  for (const auto& [key, id] : m.id) {
    if (key.second == 0 || key.second == m.step * rows) doc["constraints"].push_back({{"node", id}, {"z", 0.0}});
  }
  for (int J = 0; J < m.step * rows; J += m.step) {
    doc["loads"]["pressures"].push_back({{"nodes", {m.id.at({0, J}), m.id.at({0, J + m.step})}}, {"normal", lp}});
  }
  Lame out{io::read_model(doc), {}, height, m.id.at({0, m.step * (rows / 2)}) - 1};
  out.solution = solve(out.model);
  EXPECT_EQ(out.solution.status, RunStatus::converged) << out.solution.message;
  return out;
}

TEST(RecoveryLame, FourQuad8ThroughTheWallRecoverTheBoreHoopStress) {
  const Lame c = lame("quad8", 4, 4);
  const double hoop = c.solution.recovered.mean(static_cast<std::size_t>(c.bore))[th];
  const double exact = lA + lB / (la * la);
  std::printf("Lame, 4 quad8: recovered bore hoop %.3f vs %.3f (%+.3e); element centre %.3f\n", hoop, exact,
              hoop / exact - 1.0, c.solution.elements[0].stress[th]);
  // Observed -7.9e-5 (the issue asks 0.5 %): sigma_rr = -p at the bore, eps_zz from the stretch
  // along it and eps_th = u_r / r (boundary_stresses.hpp). The patches alone, extrapolated to the
  // bore: -7.43e-3.
  EXPECT_NEAR(hoop / exact - 1.0, -7.9e-5, 2e-5);
  EXPECT_LT(std::abs(hoop / exact - 1.0), 0.005);
}

/// The effectivity index on Lame's cylinder, true error from the closed-form energy.
double lame_effectivity(const std::string& type, int radial, int rows) {
  const Lame c = lame(type, radial, rows);
  const double u_a = (1.0 + lnu) / lE * ((1.0 - 2.0 * lnu) * lA * la + lB / la);
  const double exact = lp * 2.0 * std::numbers::pi * la * c.height * u_a;  // a(u, u): the external work
  const double discrete = discrete_energy(c.model, c.solution);
  const double true_error = std::sqrt(exact - discrete);
  const ErrorEstimate& e = *c.solution.error_estimate;
  std::printf("Lame %s %d: a(u,u) %.9e a(u_h,u_h) %.9e energy_norm^2 %.9e true %.4e estimate %.4e index %.4f\n",
              type.c_str(), radial, exact, discrete, e.energy_norm * e.energy_norm, true_error, e.error,
              e.error / true_error);
  EXPECT_NEAR(e.energy_norm * e.energy_norm, discrete, 1e-9 * discrete);
  double sum = 0.0;
  for (const ElementResult& r : c.solution.elements) sum += r.error * r.error;
  EXPECT_NEAR(sum, e.error * e.error, 1e-12 * e.error * e.error);
  return e.error / true_error;
}

TEST(RecoveryEffectivity, Quad8OnLameTendsToOne) {
  std::vector<double> index;
  for (const int radial : {2, 4, 8}) index.push_back(lame_effectivity("quad8", radial, radial));
  for (const double i : index) {
    EXPECT_GT(i, 0.8);
    EXPECT_LT(i, 1.25);
  }
  // Observed 1.088, 1.016, 0.997 (4, 16, 64 quad8, square elements; with the patches alone at the
  // boundary 1.097, 0.945, 0.965).
  EXPECT_NEAR(index[0], 1.088, 0.01);
  EXPECT_NEAR(index[1], 1.016, 0.01);
  EXPECT_NEAR(index[2], 0.997, 0.01);
  EXPECT_LT(std::abs(index[2] - 1.0), std::abs(index[0] - 1.0));
}

// ---- 3. Effectivity against a converged reference: LE1 (smooth) and an L-shaped plate (a stress
// singularity at the re-entrant corner and at the clamped edge's ends).

struct Effectivity {
  double index = 0.0;
  double relative = 0.0;  ///< error_estimate.relative
};

/// The index of the coarsest mesh of a sequence n, 2n, 4n, 8n of one family; a(u, u) by Aitken from
/// the three finest.
template <class Solve>
Effectivity effectivity(const char* name, int n, const Solve& solve_mesh) {
  std::vector<double> energy;
  ErrorEstimate coarse;
  for (int k = 0; k < 4; ++k) {
    const auto [model, solution] = solve_mesh(n << k);
    energy.push_back(discrete_energy(model, solution));
    if (k == 0) coarse = *solution.error_estimate;
    EXPECT_NEAR(solution.error_estimate->energy_norm * solution.error_estimate->energy_norm, energy.back(),
                1e-9 * energy.back());
  }
  const double limit = aitken(energy[1], energy[2], energy[3]);
  const double true_error = std::sqrt(limit - energy[0]);
  std::printf("%s %d: a(u_h,u_h) %.9e, limit %.9e, true %.4e, estimate %.4e, index %.4f, relative %.4f\n", name, n,
              energy[0], limit, true_error, coarse.error, coarse.error / true_error, coarse.relative);
  return {coarse.error / true_error, coarse.relative};
}

std::pair<Model, Solution> le1_solved(const std::string& type, int n) {
  Le1 c = le1(type, n);
  return {std::move(c.model), std::move(c.solution)};
}

/// The L: [0, 2]^2 without (1, 2]^2, plane stress, E = 1000, nu = 0.3, t = 1; the edge r = 0 clamped,
/// the edge r = 2 (z in [0, 1]) pulled along +z by a shear of 1 (a bending of the lower leg).
std::pair<Model, Solution> l_shape(const std::string& type, int n) {
  LatticeMesh m;
  m.step = type == "quad8" ? 2 : 1;
  const int L = m.step * n;  // lattice points per unit length
  const auto at = [&](int I, int J) { return std::pair{static_cast<double>(I) / L, static_cast<double>(J) / L}; };
  add_block(m, type, 0, 0, n, n, at);
  add_block(m, type, L, 0, n, n, at);
  add_block(m, type, 0, L, n, n, at);
  json doc = model_document(m, "plane_stress", 1000.0, 0.3, 1.0);
  for (const auto& [key, id] : m.id) {
    if (key.first == 0) doc["constraints"].push_back({{"node", id}, {"r", 0.0}, {"z", 0.0}});
  }
  for (int J = 0; J < L; J += m.step) {
    doc["loads"]["pressures"].push_back({{"nodes", {m.id.at({2 * L, J}), m.id.at({2 * L, J + m.step})}}, {"shear", 1.0}});
  }
  Model model = io::read_model(doc);
  Solution s = solve(model);
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  return {std::move(model), std::move(s)};
}

TEST(RecoveryEffectivity, Le1Smooth) {
  const Effectivity quad8 = effectivity("LE1 quad8", 8, [](int n) { return le1_solved("quad8", n); });
  const Effectivity saas = effectivity("LE1 saas", 8, [](int n) { return le1_solved("saas", n); });
  // Observed: quad8 8 x 8 1.336 (the patches alone at the boundary 1.349, plain SPR 1.499), an
  // overestimate outside the 0.8 .. 1.25: near D sigma_yy falls by a third within one
  // element, and the recovered field between the nodes (the quad8 interpolation of nodal values)
  // misses it by as much as the element's own stress does. The SAAS element at 8 x 8: 0.914 (the
  // patches alone 0.916; 0.903 sampled at its four triangles' centroids). Both
  // limits agree to 1e-5 (1.216747e-3, 1.216757e-3).
  EXPECT_NEAR(quad8.index, 1.336, 0.01);
  EXPECT_NEAR(saas.index, 0.914, 0.01);
  EXPECT_GT(saas.index, 0.7);
  EXPECT_LT(saas.index, 1.4);
}

TEST(RecoveryEffectivity, LShapeWithSingularities) {
  const Effectivity quad8 = effectivity("L quad8", 2, [](int n) { return l_shape("quad8", n); });
  const Effectivity saas = effectivity("L saas", 4, [](int n) { return l_shape("saas", n); });
  // Observed: quad8 2 x 2 per unit (12 elements) 0.872, the SAAS element 4 x 4 per unit 0.962 (the
  // patches alone at the boundary: 0.873, 0.922).
  EXPECT_NEAR(quad8.index, 0.872, 0.01);
  EXPECT_NEAR(saas.index, 0.962, 0.01);
  EXPECT_GT(quad8.index, 0.8);
  EXPECT_LT(quad8.index, 1.25);
  EXPECT_GT(saas.index, 0.7);
  EXPECT_LT(saas.index, 1.4);
}

}  // namespace
}  // namespace saasgaps
