// NAFEMS LE1 (the elliptic membrane) on the meshes of schemas/examples/make_le1_model.py, run as a
// user runs it, beside CalculiX 2.20 on the same meshes in the same test: the recovered nodal
// sigma_yy at D = (2, 0) (node 1) against the target 92.7 MPa and against CalculiX's extrapolated and
// averaged nodal SYY there (CPS8 on the quad8 meshes; tests/bench/accuracy_per_cost.py adds CPS4 on
// the SAAS meshes' corners).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "support/calculix_run.hpp"

namespace saasgaps {
namespace {

constexpr double target = 92.7;

nlohmann::json le1_document(int n, const std::string& type) {
  const std::string command = std::string(SAASGAPS_PYTHON3) + " " + SAASGAPS_EXAMPLES_DIR +
                              "/make_le1_model.py --n " + std::to_string(n) + " --type " + type;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::string out;
  char buffer[65536];
  for (std::size_t k; (k = std::fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, k);
  return nlohmann::json::parse(out);
}

/// Ours (the recovered nodal sigma_z at node 1) and, for quad8 when ccx is installed, CalculiX
/// CPS8's, both over the target.
std::pair<double, std::optional<double>> sigma_yy_at_d(int n, const std::string& type) {
  nlohmann::json doc = le1_document(n, type);
  const Solution s = solve(io::read_model(doc));
  EXPECT_EQ(s.status, RunStatus::converged) << s.message;
  const double ours = s.recovered.mean(0)[zz] / target;
  std::optional<double> theirs;
  if (type == "quad8") {
    if (const auto ccx = testing::run_calculix(doc)) theirs = ccx->sigma.at(1)[1] / target;
  }
  return {ours, theirs};
}

TEST(NafemsLe1, Quad8EightByEightAtD) {
  const auto [ours, calculix] = sigma_yy_at_d(8, "quad8");
  std::printf("LE1 quad8 8 x 8: sigma_yy(D) / 92.7 = %.4f here", ours);
  if (calculix) std::printf(", CalculiX CPS8 %.4f", *calculix);
  std::printf("\n");
  // Observed 0.9943: the issue asks within 1 %, CalculiX's own extrapolation gives -0.59 %. D is a
  // free boundary node on a symmetry line: its stress comes from the traction (zero) and the
  // stretch of the inner edge (docs/recovery.md, "What it gives").
  EXPECT_NEAR(ours, 0.9943, 5e-4);
  EXPECT_LT(std::abs(ours - 1.0), 0.01);
  if (!calculix) GTEST_SKIP() << "ccx (calculix-ccx) is not installed: deploy/test.sh installs it";
  EXPECT_NEAR(*calculix, 0.9941, 1e-4);  // observed: the figure, so these are its meshes
}

TEST(NafemsLe1, SaasSixteenBySixteenAtD) {
  const double ours = sigma_yy_at_d(16, "saas").first;
  std::printf("LE1 saas 16 x 16: sigma_yy(D) / 92.7 = %.4f here (CalculiX CPS4 on these corners: 1.0172)\n", ours);
  // Observed 0.9785: the issue asks within 3 % (docs/recovery.md, "What it gives").
  EXPECT_NEAR(ours, 0.9785, 5e-4);
  EXPECT_LT(std::abs(ours - 1.0), 0.03);
}

/// The LE1 model with its outer pressure replaced by the consistent nodal forces of each curved
/// 3-node edge, integrated here: F_k = t q integral N_k(s) (y'(s), -x'(s)) ds over s in [-1, 1] for
/// an edge from a to b with mid-side node m (N_a = s (s - 1) / 2, N_m = 1 - s^2, N_b = s (s + 1) / 2),
/// q = -normal the outward pull per unit area, t the thickness; (y', -x') is the outward normal times
/// the length element for an edge run with the region on its left. 3 Gauss points: the integrand is
/// cubic.
nlohmann::json with_nodal_forces(nlohmann::json doc) {
  std::map<int, std::array<double, 2>> at;
  for (const auto& n : doc["nodes"]) at[n["id"].get<int>()] = {n["r"].get<double>(), n["z"].get<double>()};
  const double thickness = doc["analysis"]["thickness"].get<double>();
  std::map<int, std::array<double, 2>> force;
  for (const auto& p : doc["loads"]["pressures"]) {
    const int a = p["nodes"][0].get<int>(), b = p["nodes"][1].get<int>();
    int m = -1;  // the mid-side node of edge a-b: quad8 nodes (c0, c1, c2, c3, m01, m12, m23, m30)
    for (const auto& e : doc["elements"]) {
      const auto nodes = e["nodes"].get<std::vector<int>>();
      for (int k = 0; k < 4; ++k) {
        if (nodes[static_cast<std::size_t>(k)] == a && nodes[static_cast<std::size_t>((k + 1) % 4)] == b) {
          m = nodes[static_cast<std::size_t>(4 + k)];
        }
      }
    }
    EXPECT_GT(m, 0) << a << "-" << b;
    const double q = -p["normal"].get<double>();
    const std::array<int, 3> node{a, m, b};
    const double g = std::sqrt(0.6);
    for (const auto& [s, w] : std::array<std::pair<double, double>, 3>{{{-g, 5.0 / 9.0}, {0.0, 8.0 / 9.0}, {g, 5.0 / 9.0}}}) {
      const std::array<double, 3> N{0.5 * s * (s - 1.0), 1.0 - s * s, 0.5 * s * (s + 1.0)};
      const std::array<double, 3> dN{s - 0.5, -2.0 * s, s + 0.5};
      double dx = 0.0, dy = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        dx += dN[k] * at[node[k]][0];
        dy += dN[k] * at[node[k]][1];
      }
      for (std::size_t k = 0; k < 3; ++k) {
        force[node[k]][0] += thickness * q * w * N[k] * dy;
        force[node[k]][1] -= thickness * q * w * N[k] * dx;
      }
    }
  }
  doc["loads"].erase("pressures");
  for (const auto& [id, f] : force) doc["loads"]["nodal_forces"].push_back({{"node", id}, {"fr", f[0]}, {"fz", f[1]}});
  return doc;
}

TEST(NafemsLe1, NodalForcesOnTheCurvedEdgesGiveWhatThePressureGives) {
  const nlohmann::json pressure = le1_document(8, "quad8");
  const Solution a = solve(io::read_model(pressure));
  const Solution b = solve(io::read_model(with_nodal_forces(pressure)));
  ASSERT_EQ(a.status, RunStatus::converged);
  ASSERT_EQ(b.status, RunStatus::converged);
  double scale = 0.0, worst = 0.0;
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t k = 0; k < a.nodes.size(); ++k) {
    scale = std::max({scale, std::abs(a.nodes[k].u_r), std::abs(a.nodes[k].u_z)});
    worst = std::max({worst, std::abs(a.nodes[k].u_r - b.nodes[k].u_r), std::abs(a.nodes[k].u_z - b.nodes[k].u_z)});
  }
  std::printf("LE1 quad8 8 x 8: nodal forces against pressures, displacements within %.2e, D %.6f and %.6f\n",
              worst / scale, a.recovered.mean(0)[zz] / target, b.recovered.mean(0)[zz] / target);
  EXPECT_LT(worst, 1e-10 * scale);
  EXPECT_NEAR(b.recovered.mean(0)[zz], a.recovered.mean(0)[zz], 1e-8 * target);
}

}  // namespace
}  // namespace saasgaps
