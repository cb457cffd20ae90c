// The exact contact mode (gaps.method = "exact") against closed forms, the report's answers, an
// independent penalty method written only here, and bad input.
//
// Hertz, plane strain (Johnson, Contact Mechanics, 4.3): two bodies whose initial gap is
// g(x) = g_c + x^2 / (2 R), pressed together by P per unit length, touch over |x| < a with
//   p(x) = p0 sqrt(1 - x^2 / a^2),  p0 = sqrt(P E* / (pi R)),  a = sqrt(4 P R / (pi E*)),
//   1 / E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2,
// for bodies large against a (here 20 a) and a mesh fine against a (a / 25 near the contact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/base/errors.hpp"
#include "solver/contact/exact_contact.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/mortar/mortar_method.hpp"
#include "support/examples.hpp"
#include "support/hertz_line_contact.hpp"
#include "support/mesh_builder.hpp"
#include "support/quoted_figure.hpp"
#include "support/ring_fit.hpp"
#include "support/shrink_fit_rings.hpp"

namespace saasgaps {
namespace {

// ---- Hertz: a cylinder-like body (bottom z = g_c + x^2 / 2R) pressed onto a block, half model.

using testing::hertz_a, testing::hertz_E, testing::hertz_nu, testing::hertz_p0, testing::hertz_P, testing::hertz_R,
    testing::hertz_size;

struct Hertz {
  Model model;
  std::vector<int> contact_nodes;  // block surface nodes, x = xs[k]
  std::vector<double> xs;
};

Hertz hertz_model(double h) {
  Hertz H;
  Model& m = H.model;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, hertz_E, hertz_nu)};
  H.xs = testing::hertz_graded(h);
  const std::vector<double>& xs = H.xs;
  const int n = static_cast<int>(xs.size()) - 1;
  const auto at = [&xs, n](double s) { return xs[static_cast<std::size_t>(std::lround(s * n))]; };
  const double gap_c = 1.0e-4;
  const auto bottom = [gap_c](double x) { return gap_c + x * x / (2.0 * hertz_R); };
  const testing::Grid block = testing::add_grid(m, n, n, [&](double s, double t) { return Vec2(at(s), -at(1.0 - t)); }, 0);
  const testing::Grid body = testing::add_grid(
      m, n, n,
      [&](double s, double t) {
        const double x = at(s), z0 = bottom(x);
        return Vec2(x, z0 + at(t) * (hertz_size - z0) / hertz_size);
      },
      0);
  std::vector<int> surface, face;
  for (int i = 0; i <= n; ++i) {
    surface.push_back(block.at(i, n));
    face.push_back(body.at(i, 0));
  }
  m.gaps.emplace();
  testing::add_gap_row(m, surface, face, [](int) { return 90.0; });
  m.gaps->method = GapMethod::exact;
  m.gaps->initial_modulus = 1.0;
  m.gaps->tensile_schedule = {1.0};
  testing::fill_temperatures(m, 0.0);
  for (int i = 0; i <= n; ++i) testing::constrain(m, block.at(i, 0), std::nullopt, 0.0);
  for (int j = 0; j <= n; ++j) {
    testing::constrain(m, block.at(0, j), 0.0, std::nullopt);  // symmetry about x = 0
    testing::constrain(m, body.at(0, j), 0.0, std::nullopt);
  }
  // Half the load, a uniform pressure on the body's top as consistent nodal forces.
  const double q = 0.5 * hertz_P / hertz_size;
  for (int i = 0; i <= n; ++i) {
    const double left = i > 0 ? xs[i] - xs[i - 1] : 0.0, right = i < n ? xs[i + 1] - xs[i] : 0.0;
    m.loads.nodal_forces.push_back({body.at(i, n), 0.0, -q * 0.5 * (left + right)});
  }
  H.contact_nodes = surface;
  return H;
}

/// Node pressures along the contact: -sigma_m is per gap; the pair pressure at node k comes from the
/// gap's mean of its two pairs, so take the gaps' values at their centres.
TEST(ExactHertz, PeakPressureAndHalfWidthAsDocumented) {
  const Hertz H = hertz_model(hertz_a / 25.0);
  const Solution s = solve(H.model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  // Pressure at the gap centres, x_c; fit p^2 = p0^2 (1 - x^2 / a^2) over the gaps well inside contact.
  double sxx = 0, sx = 0, sy = 0, sxy = 0, count = 0, peak = 0.0;
  double last_closed = 0.0;
  for (std::size_t k = 0; k < s.gaps.size(); ++k) {
    const double xc = 0.5 * (H.xs[k] + H.xs[k + 1]), p = -s.gaps[k].sigma_m;
    if (k == 0) peak = p;
    if (s.gaps[k].state == GapState::closed) last_closed = xc;
    if (s.gaps[k].state != GapState::closed || xc > 0.8 * hertz_a) continue;
    const double X = xc * xc, Y = p * p;
    sx += X, sy += Y, sxx += X * X, sxy += X * Y, count += 1;
  }
  const double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / count;
  const double p0 = std::sqrt(intercept), a = std::sqrt(-intercept / slope);
  // The first gap's centre is at h/2: p(h/2) = p0 (1 - h^2/8a^2), 0.02 % below p0.
  const double peak_error = peak / hertz_p0 - 1.0, fit_error = p0 / hertz_p0 - 1.0, a_error = a / hertz_a - 1.0;
  std::printf("Hertz: %d active sets; p0 %.1f (%.3e; fit %.1f, %.3e) vs %.1f, a %.5f (%.3e; last closed gap centre %.4f) "
              "vs %.4f, %zu gaps\n",
              s.history.back().active_set_iterations, peak, peak_error, p0, fit_error, hertz_p0, a, a_error, last_closed,
              hertz_a, s.gaps.size());
  // docs/contact.md: "p0 -0.06 %, a -0.05 % (fit of p^2 against x^2)" (p0: the peak gap's pressure;
  // the fit's p0 is -0.041 %), and "Hertz: 8 active sets". The half-width's error is observed at
  // -0.060 %, not the -0.05 % docs/contact.md quotes: pinned as observed (-5.97e-4). "Hertz: 2
  // active sets" (8 before the look-ahead from the first set's factorization).
  EXPECT_TRUE(testing::rounds_to(100.0 * peak_error, "-0.06"));
  EXPECT_LT(std::abs(a_error), 6.6e-4);
  EXPECT_LT(std::abs(fit_error), 4.6e-4);  // observed -4.14e-4
  EXPECT_EQ(s.history.back().active_set_iterations, 2);
  EXPECT_NEAR(last_closed, hertz_a, 1.5 * hertz_a / 25.0);
}

// ---- The report's Problems 1 and 2 in exact mode.

Model exact_example(const std::string& name) {
  nlohmann::json doc = testing::example_document(name);
  doc["gaps"]["method"] = "exact";
  return io::read_model(doc);
}

TEST(ExactReport, Problem1BodyRestsOnItsGapsAtAThousandPsi) {
  const Model m = exact_example("report-problem1.json");
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  for (const GapResult& g : s.gaps) {
    if (g.id == 10 || g.id == 20) {
      EXPECT_EQ(g.state, GapState::open) << "side gap " << g.id;
      continue;
    }
    EXPECT_EQ(g.state, GapState::closed) << "gap " << g.id;
    // docs/contact.md: "-1000.00 psi on every gap and in the body"; observed within 4.4e-5 psi.
    EXPECT_NEAR(g.sigma_m, -1000.0, 6e-5) << "gap " << g.id;
    EXPECT_NEAR(g.closure, 100.0, 1e-9) << "gap " << g.id;  // observed 5.9e-11
  }
  // Observed within 3.2e-4 psi.
  for (const ElementResult& e : s.elements) EXPECT_NEAR(e.stress[zz], -1000.0, 4e-4) << "element " << e.id;
  // "10^-16 to 10^-12 in the tests": round-off, observed 1.6e-12 here.
  EXPECT_LT(s.history.back().complementarity, 1e-11);
}

TEST(ExactReport, Problem2ThermalGrowthClosesGap20AtTenThousandPsi) {
  const Model m = exact_example("report-problem2.json");
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  for (const GapResult& g : s.gaps) {
    if (g.id != 20) continue;
    EXPECT_EQ(g.state, GapState::closed);
    // docs/contact.md: "10000.0 psi in gap 20 and every element"; observed within 8.7e-5 psi.
    EXPECT_NEAR(g.sigma_m, -10000.0, 1.1e-4);
  }
  // Observed within 3.7e-4 psi.
  for (const ElementResult& e : s.elements) EXPECT_NEAR(e.stress[rr], -10000.0, 4.5e-4) << "element " << e.id;
  EXPECT_LT(s.history.back().complementarity, 1e-11);  // round-off, observed 5e-16
}

// ---- An independent second method: penalty springs on the ordinary assembled system.

/// Vertical node pairs of gap quads laid out like the report's and the Hertz generator's:
/// nodes (a0, a1, b1, b0), M at 90 degrees, a below b.
struct VerticalPair {
  int a = 0, b = 0;
  double g0 = 0.0;
};

std::vector<VerticalPair> vertical_pairs(const Model& m) {
  std::set<std::pair<int, int>> seen;
  std::vector<VerticalPair> out;
  for (const GapElement& g : m.gaps->elements) {
    for (const auto& [a, b] : {std::pair{g.nodes[0], g.nodes[3]}, std::pair{g.nodes[1], g.nodes[2]}}) {
      if (seen.insert({a, b}).second) out.push_back({a, b, m.nodes[b].z - m.nodes[a].z});
    }
  }
  return out;
}

/// u (two per node) of the contact problem solved with penalty springs k (g < 0 only), the active set
/// iterated to a fixed point, k raised until the displacements stop changing.
std::vector<double> penalty_solution(const Model& m) {
  DofMap dofs(m);
  StiffnessSystem system(m, dofs);
  testing::assemble_with_gaps_at_floor(m, system);
  SparseCholesky cholesky(system.pattern());
  const auto values = system.values();
  double stiffest = 0.0;
  for (Index j = 0; j < dofs.size(); ++j) stiffest = std::max(stiffest, values[system.pattern().find(j, j)]);

  const std::vector<VerticalPair> pairs = vertical_pairs(m);
  std::vector<char> active(pairs.size(), 0);
  std::vector<double> u(static_cast<std::size_t>(dofs.size()), 0.0), work(values.begin(), values.end());
  std::vector<double> rhs(u.size());
  const auto gap = [&](const VerticalPair& p) {
    const Index ea = dofs.equation(p.a, 1), eb = dofs.equation(p.b, 1);
    return p.g0 + (eb >= 0 ? u[eb] : 0.0) - (ea >= 0 ? u[ea] : 0.0);
  };
  for (double k : {1e4 * stiffest, 1e6 * stiffest}) {
    for (int round = 0; round < 50; ++round) {
      std::copy(values.begin(), values.end(), work.begin());
      std::copy(system.rhs().begin(), system.rhs().end(), rhs.begin());
      for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (!active[i]) continue;
        // Energy k g^2 / 2 with g = g0 + u_b - u_a: adds k c c^T and -k g0 c.
        const Index ea = dofs.equation(pairs[i].a, 1), eb = dofs.equation(pairs[i].b, 1);
        if (ea >= 0) work[system.pattern().find(ea, ea)] += k, rhs[ea] += k * pairs[i].g0;
        if (eb >= 0) work[system.pattern().find(eb, eb)] += k, rhs[eb] -= k * pairs[i].g0;
        if (ea >= 0 && eb >= 0) work[system.pattern().find(ea, eb)] -= k;
      }
      cholesky.factorize(work);
      cholesky.solve(rhs, u);
      bool changed = false;
      for (std::size_t i = 0; i < pairs.size(); ++i) {
        const char now = gap(pairs[i]) < 0.0;
        changed = changed || now != active[i];
        active[i] = now;
      }
      if (!changed) break;
    }
  }
  std::vector<double> full(2 * m.nodes.size(), 0.0);
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    for (int dir = 0; dir < 2; ++dir) {
      const Index eq = dofs.equation(static_cast<int>(n), dir);
      full[2 * n + dir] = eq >= 0 ? u[eq] : dofs.prescribed(static_cast<int>(n), dir);
    }
  }
  return full;
}

void expect_same_displacements(const Model& m, const Solution& s, double tolerance) {
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const std::vector<double> reference = penalty_solution(m);
  double largest = 0.0, worst = 0.0;
  for (double v : reference) largest = std::max(largest, std::abs(v));
  for (std::size_t n = 0; n < s.nodes.size(); ++n) {
    worst = std::max({worst, std::abs(s.nodes[n].u_r - reference[2 * n]), std::abs(s.nodes[n].u_z - reference[2 * n + 1])});
  }
  std::printf("exact vs penalty: largest displacement %.6e, worst difference %.3e (%.2e of it)\n", largest, worst,
              worst / largest);
  EXPECT_LT(worst, tolerance * largest);
}

// docs/contact.md quotes "2e-10, and 2e-8 to 4e-8" of the largest displacement. The difference is the
// penalty's own error at k = 10^6 max diag K, mostly round-off: k multiplies the condition number by
// 10^6, so the penalty solve's digits move with the BLAS kernel. Observed: the beam 1.86e-10 with every
// OpenBLAS core type; Hertz 1.90e-8 (Haswell, Zen, SkylakeX), 1.98e-8 (SandyBridge), 3.9e-8 (Nehalem)
// and 4.3e-8 (Prescott, Core2). A wrong contact answer differs by 10^-3 and more.
TEST(ExactCrossCheck, PenaltyMethodAgreesOnTheReportBeam) {
  const Model m = testing::example_model("report-problem3-case1-exact.json");
  expect_same_displacements(m, solve(m), 5e-10);
}

TEST(ExactCrossCheck, PenaltyMethodAgreesOnHertz) {
  const Hertz H = hertz_model(hertz_a / 8.0);
  expect_same_displacements(H.model, solve(H.model), 1e-7);
}

// ---- Bad input and problems without a solution.

TEST(ExactInput, AGapWhoseMAxisIsNotAcrossItIsAModelErrorAtItsAngleInBothMethods) {
  nlohmann::json doc = testing::example_document("report-problem1.json");
  doc["gaps"]["elements"][3]["angle"] = 45.0;  // no two opposite edges across M
  for (const char* method : {"exact", "classic"}) {
    doc["gaps"]["method"] = method;
    try {
      io::read_model(doc);
      FAIL() << "accepted in " << method;
    } catch (const ModelError& e) {
      ASSERT_EQ(e.issues().size(), 1U);
      EXPECT_EQ(e.issues()[0].pointer, "/gaps/elements/3/angle");
      EXPECT_NE(e.issues()[0].detail.find("angle 45 does not run across gap element 13"), std::string::npos)
          << e.issues()[0].detail;
    }
  }
  // A model that did not come through the reader: the exact mode's pairing says the same.
  doc["gaps"]["elements"][3]["angle"] = 90.0;
  Model m = io::read_model(doc);
  m.gaps->elements[3].angle_deg = 45.0;
  const std::vector<PairingIssue> issues = contact_pairing_issues(m);
  ASSERT_EQ(issues.size(), 1U);
  EXPECT_EQ(issues[0].gap, 3U);
  EXPECT_NE(issues[0].detail.find("gap element 13 cannot be paired: angle 45 does not run across"), std::string::npos)
      << issues[0].detail;
}

TEST(ExactInput, ZeroSeparationAndANodeFacingNothingAreNamed) {
  Model m;
  m.nodes = {{1, 0.0, 0.0}, {2, 1.0, 0.0}, {3, 1.0, 0.01}, {4, 0.0, 0.0}, {5, 3.0, 0.01}, {6, 0.0, 0.01},
             {7, 0.0, 0.0}, {8, 1.0, 0.0}};
  m.gaps.emplace();
  m.gaps->tensile_schedule = {1.0};
  m.gaps->elements.push_back({7, {0, 1, 2, 3}, 4, 90.0});  // nodes 1 and 4 coincide
  m.gaps->elements.push_back({8, {6, 7, 4, 5}, 4, 90.0});  // node 8 "faces" node 5, two lengths away
  const std::vector<PairingIssue> issues = contact_pairing_issues(m);
  ASSERT_EQ(issues.size(), 2U);
  EXPECT_EQ(issues[0].gap, 0U);
  EXPECT_NE(issues[0].detail.find("zero separation"), std::string::npos) << issues[0].detail;
  EXPECT_EQ(issues[1].gap, 1U);
  EXPECT_NE(issues[1].detail.find("does not face"), std::string::npos) << issues[1].detail;
  EXPECT_THROW(contact_pairs(m), GapPairingError);
}

TEST(ExactInput, ABodyPulledAwayFromEverySupportHasNoSolution) {
  nlohmann::json doc = testing::example_document("report-problem1.json");
  doc["gaps"]["method"] = "exact";
  for (auto& p : doc["loads"]["pressures"]) p["normal"] = -p["normal"].get<double>();  // pull, not push
  const Model m = io::read_model(doc);
  try {
    solve(m);
    FAIL() << "solved";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("has no solution"), std::string::npos) << what;
    EXPECT_NE(what.find("pushed away from every support"), std::string::npos) << what;
    EXPECT_NE(what.find("gap 1"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace saasgaps

namespace saasgaps {
namespace {

// The floor springs' share at part load. Report problem 3 case 1 in 3 increments: at 1/3 of the
// pressure the retainer's gaps are 77-86 % closed but not touching, and their floor springs (the
// report's 1 psi) carry 1.25 % of that smaller load, above the exact method's 1 % guard: the run
// stops and says the floor modulus may not be negligible. A floor 100 times lower (the remedy the
// message and docs/contact.md section 4 give) carries 100 times less, and the run converges.
TEST(ExactInput, APartLoadWhoseFloorSpringsCarryMoreThanOnePercentNamesTheFloorAndALowerFloorSolvesIt) {
  nlohmann::json doc = testing::example_document("report-problem3-case1-exact.json");
  doc["steps"] = nlohmann::json::array({{{"name", "ramp"}, {"increments", 3}}});
  try {
    solve(io::read_model(doc));
    FAIL() << "solved";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("the contact problem has no solution: 1.2", 0), 0U) << what;
    EXPECT_NE(what.find("the floor modulus 1 (the last tensile_schedule value) is not negligible"), std::string::npos)
        << what;
  }
  doc["gaps"]["tensile_schedule"] = nlohmann::json::array({0.01});
  const Solution s = solve(io::read_model(doc));
  EXPECT_EQ(s.status, RunStatus::converged);
}

}  // namespace
}  // namespace saasgaps

// ---- Looking ahead from a factorized set (solver/contact/exact_contact.hpp, docs/contact.md section 3).

namespace saasgaps {
namespace {

TEST(ExactLookAhead, AnEccentricFitFindsWhereContactEndsInTwoActiveSets) {
  // The benchmark's partial contact at small scale (tests/bench/surface_contact_benchmark.cpp): the
  // shaft moved by two interferences, so the gap runs -delta (1 + 2 cos theta) and the arc where
  // cos theta < -1/2 starts open. Step by step the boundary moved by a few rows per set; the
  // condensed problem of the rows near it places it at once.
  Model m = testing::shrink_fit_rings::shrink_fit(AnalysisType::plane_strain, 8, {120, 200});
  std::vector<bool> shaft(m.nodes.size(), false);
  for (const Element& e : m.elements) {
    if (e.material != 0) continue;
    for (int k = 0; k < e.node_count; ++k) shaft[static_cast<std::size_t>(e.nodes[k])] = true;
  }
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    if (shaft[n]) m.nodes[n].r += 2.0 * testing::shrink_fit_rings::delta;
  }
  const SurfaceContact surfaces = surface_contact(m);
  const DofMap dofs(m);
  StiffnessSystem system(m, dofs, contact_couplings(surfaces, dofs));
  const SolidMaterials materials(m);
  const MaterialState state = materials.initial();
  system.assemble_solids([&](std::size_t e) { return materials.law(e, state); });
  SparseCholesky cholesky(system.pattern(), dofs.node_of_equation());
  ExactContact contact(m, dofs, system.pattern(), surfaces.pairs);
  std::vector<double> u(static_cast<std::size_t>(dofs.size()));
  ContactState cold;
  const ContactReport report = contact.solve(cholesky, system.values(), system.rhs(), cold, u);
  const auto rows = static_cast<int>(surfaces.pairs.pairs.size());
  std::printf("eccentric fit: %d rows, %d in contact, %d active sets, %d factorizations, %d solves, complementarity %.2e\n",
              rows, report.pairs_in_contact, report.active_set_iterations, report.factorizations,
              report.multiplier_iterations, report.complementarity);
  EXPECT_GT(report.pairs_in_contact, rows / 2);
  EXPECT_LT(report.pairs_in_contact, rows);
  EXPECT_EQ(report.active_set_iterations, 2);
  EXPECT_EQ(report.factorizations, 1);
  EXPECT_LT(report.complementarity, 1e-12);
}

}  // namespace
}  // namespace saasgaps
