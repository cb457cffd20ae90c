// The adaptive loop (io/import/adaptive_loop.hpp) on NAFEMS LE1 from its .geo
// (schemas/examples/assemblies/le1.geo): the 1 % target reached in a few cycles, sigma_yy at D
// within 1.5 % of 92.7, on fewer nodes than the uniform mesh (the same .geo, one size everywhere)
// that reaches the same estimated error. And the press fit from ring-press-fit.geo with contact
// surfaces: the loop refines at the contact surfaces and meets Lame's interference pressure.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/import/adapt_sizes.hpp"
#include "io/import/adaptive_loop.hpp"
#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "support/lame_rings.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path assemblies = fs::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";

json load(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return json::parse(in);
}

io::AdaptiveRun adapt(const json& assembly, const fs::path& dir) {
  const auto settings = io::read_adapt_settings(assembly, [](const std::string& p, const std::string& d) {
    ADD_FAILURE() << p << ": " << d;
  });
  if (!settings) throw std::runtime_error("no adapt settings");
  return io::run_adaptive(assembly, dir, io::FileAccess::anywhere, *settings, [](const Model& m) { return solve(m); },
                          [](const io::AdaptCycle& c, const io::AdaptSizes*) {
                            std::printf("cycle %d: %zu nodes, %zu elements, relative error %.4g (mesh %.3f s, "
                                        "import %.3f s, solve %.3f s, estimate %.3f s, sizes %.3f s)\n",
                                        c.cycle, c.nodes, c.elements, c.relative_error, c.mesh_seconds,
                                        c.import_seconds, c.solve_seconds, c.estimate_seconds, c.sizes_seconds);
                          });
}

/// The node at (r, z), or -1.
int node_at(const Model& m, double r, double z) {
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    if (std::hypot(m.nodes[n].r - r, m.nodes[n].z - z) < 1e-9) return static_cast<int>(n);
  }
  return -1;
}

/// A scratch directory holding a copy of le1.geo with one element size `lc`.
class UniformLe1 {
 public:
  UniformLe1() : dir_(fs::temp_directory_path() / ("saasgaps-le1-" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~UniformLe1() { fs::remove_all(dir_); }
  UniformLe1(const UniformLe1&) = delete;
  UniformLe1& operator=(const UniformLe1&) = delete;

  struct Solved {
    std::size_t nodes = 0;
    double relative_error = 1.0;
    double sigma_yy_at_d = 0.0;  ///< recovered
  };

  /// The uniform mesh of size lc and element order 1 or 2 solved.
  Solved solve_at(double lc, int order = 1) const {
    std::ifstream in(assemblies / "le1.geo");
    std::stringstream text;
    text << in.rdbuf();
    std::string geo = text.str();
    const std::string from = "lc = 0.25;";
    geo.replace(geo.find(from), from.size(), "lc = " + std::to_string(lc) + ";");
    std::ofstream(dir_ / "le1.geo") << geo;
    json a = load(assemblies / "le1-adapt.assembly.json");
    a.erase("adapt");
    if (order == 2) a["order"] = 2;
    const Model m = io::read_model(io::import_assembly(a, dir_));
    const Solution s = solve(m);
    EXPECT_EQ(s.status, RunStatus::converged);
    const int d = node_at(m, 2.0, 0.0);
    EXPECT_GE(d, 0);
    return {m.nodes.size(), s.error_estimate ? s.error_estimate->relative : 1.0,
            d >= 0 ? s.recovered.mean(static_cast<std::size_t>(d))[1] : 0.0};
  }

 private:
  fs::path dir_;
};

TEST(AdaptiveLoop, Le1ReachesOnePercentWithFewerNodesThanAUniformMesh) {
  // The uniform mesh of 26000 nodes takes Gmsh 20 to 70 s on a loaded 2-core machine (the
  // recombination): beyond the default 60 s.
  io::MeshLimits limits = io::mesh_limits();
  limits.seconds = 600;
  io::set_mesh_limits(limits);
  const io::AdaptiveRun run = adapt(load(assemblies / "le1-adapt.assembly.json"), assemblies);
  ASSERT_TRUE(run.reached) << run.message;
  ASSERT_GE(run.cycles.size(), 2U);
  EXPECT_LE(run.cycles.size(), 5U) << "a few cycles";
  EXPECT_LE(run.cycles.back().relative_error, 0.01);
  EXPECT_EQ(run.cycles.back().nodes, run.model.nodes.size());
  EXPECT_NE(run.message.find("adaptation reached relative error"), std::string::npos) << run.message;
  // The error falls at every cycle.
  for (std::size_t k = 1; k < run.cycles.size(); ++k) {
    EXPECT_LT(run.cycles[k].relative_error, run.cycles[k - 1].relative_error) << "cycle " << k + 1;
  }
  const int d = node_at(run.model, 2.0, 0.0);
  ASSERT_GE(d, 0) << "D = (2, 0) is a point of le1.geo, so a node of every mesh";
  const double sigma_yy = run.solution.recovered.mean(static_cast<std::size_t>(d))[1];
  std::printf("LE1 adaptive: %zu nodes, relative error %.4g, sigma_yy at D %.4g (%.3g %% from 92.7)\n",
              run.model.nodes.size(), run.cycles.back().relative_error, sigma_yy, 100.0 * (sigma_yy / 92.7 - 1.0));
  EXPECT_NEAR(sigma_yy / 92.7, 1.0, 0.015);  // the bound
  EXPECT_NEAR(sigma_yy, 92.65, 0.05);          // docs/import.md and README: 92.65
  // docs/import.md, README, docs/performance.md: 4 cycles, 148 .. 13864 nodes (Gmsh is deterministic;
  // 2 % for another Gmsh build).
  EXPECT_EQ(run.cycles.size(), 4U);
  EXPECT_EQ(run.cycles.front().nodes, 148U);
  EXPECT_NEAR(static_cast<double>(run.model.nodes.size()), 13864.0, 0.02 * 13864.0);
  EXPECT_NEAR(run.cycles.front().relative_error, 0.1214, 0.0005);

  // Uniform meshes of the same geometry, halving the size until the estimate is as small.
  const UniformLe1 uniform;
  const double reached = run.cycles.back().relative_error;
  std::size_t uniform_nodes = 0;
  for (double lc = 0.25; lc > 0.25 / 64; lc /= 2) {
    const auto [nodes, error, sigma] = uniform.solve_at(lc);
    std::printf("LE1 uniform lc %.4g: %zu nodes, relative error %.4g\n", lc, nodes, error);
    if (error <= reached) {
      uniform_nodes = nodes;
      break;
    }
  }
  ASSERT_GT(uniform_nodes, 0U) << "no uniform mesh down to lc = 0.0078 reaches " << reached;
  EXPECT_LT(run.model.nodes.size(), uniform_nodes);
  EXPECT_NEAR(static_cast<double>(uniform_nodes), 26171.0, 0.02 * 26171.0);  // docs/import.md, README
}

TEST(AdaptiveLoop, Le1UnstructuredMeshesRecoverD) {
  // D lies on the symmetry line y = 0 and on the free inner edge: docs/recovery.md, "What it gives".
  // The report element at lc = 0.2, 0.1, 0.05, 0.025: -5.0 %, -2.2 %, +0.56 %, -0.45 %; quad8 at
  // lc = 0.2, 0.1, 0.05: -0.31 %, -0.12 %, -0.11 %.
  const UniformLe1 uniform;
  const auto saas = uniform.solve_at(0.05);
  const auto quad8 = uniform.solve_at(0.1, 2);
  std::printf("LE1 unstructured: report element %zu nodes sigma_yy(D) %+.4f, quad8 %zu nodes %+.4f\n", saas.nodes,
              saas.sigma_yy_at_d / 92.7 - 1.0, quad8.nodes, quad8.sigma_yy_at_d / 92.7 - 1.0);
  EXPECT_NEAR(static_cast<double>(saas.nodes), 2752.0, 0.02 * 2752.0);
  EXPECT_NEAR(static_cast<double>(quad8.nodes), 2887.0, 0.02 * 2887.0);
  EXPECT_NEAR(saas.sigma_yy_at_d / 92.7 - 1.0, 0.0056, 0.001);    // observed +0.56 %
  EXPECT_NEAR(quad8.sigma_yy_at_d / 92.7 - 1.0, -0.0012, 0.001);  // observed -0.12 %
}

/// The mean size (sqrt of the area) of the elements with a node within `band` of r = r0.
double size_near(const Model& m, double r0, double band) {
  double sum = 0.0;
  int count = 0;
  for (const Element& e : m.elements) {
    bool near = false;
    for (int k = 0; k < 4 && e.nodes[static_cast<std::size_t>(k)] >= 0 && k < e.node_count; ++k) {
      near = near || std::fabs(m.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])].r - r0) < band;
    }
    if (!near) continue;
    const int c = std::min(e.node_count, 4);
    double twice = 0.0;
    for (int k = 0; k < c; ++k) {
      const Node& a = m.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(k)])];
      const Node& b = m.nodes[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>((k + 1) % c)])];
      twice += a.r * b.z - b.r * a.z;
    }
    sum += std::sqrt(0.5 * std::fabs(twice));
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

TEST(AdaptiveLoop, PressFitRefinesAtTheContactAndMeetsLame) {
  json a = load(assemblies / "ring-press-fit.assembly.json");
  a["adapt"] = {{"target_error", 0.002}, {"max_cycles", 5}};  // the first mesh: 0.41 %
  const Model first = io::read_model(io::import_assembly(a, assemblies));
  const io::AdaptiveRun run = adapt(a, assemblies);
  ASSERT_TRUE(run.reached) << run.message;
  ASSERT_GE(run.cycles.size(), 2U);
  ASSERT_TRUE(run.model.contact);
  // The contact surfaces were regenerated on the new mesh.
  ASSERT_EQ(run.model.contact->pairs.size(), 1U);
  const double before = size_near(first, 1.5, 0.01), after = size_near(run.model, 1.5, 0.01);
  // The hub's outside (r = 2.2), where the stresses vary least, is refined less.
  const double far_before = size_near(first, 2.2, 0.01), far_after = size_near(run.model, 2.2, 0.01);
  std::printf("press fit: element size at the contact surface %.4g before, %.4g after; at r = 2.2 %.4g, %.4g\n",
              before, after, far_before, far_after);
  EXPECT_LT(after, before);
  EXPECT_LT(after / before, far_after / far_before);
  EXPECT_LT(after / before, 0.4);          // docs/import.md: 0.0188 -> 0.0065 (0.35)
  EXPECT_GT(far_after / far_before, 0.7);  // and 0.0161 -> 0.0117 (0.73)
  EXPECT_EQ(run.cycles.size(), 2U);
  EXPECT_NEAR(run.cycles.front().relative_error, 0.0041, 0.0001);
  EXPECT_NEAR(run.cycles.back().relative_error, 0.0017, 0.0001);

  const double p = testing::lame_rings::plane_strain_interference_pressure({1.0, 1.5, 2.2, 30.0e6, 0.3, 10.0e6, 0.33},
                                                                           1.5e-4);
  ASSERT_EQ(run.solution.status, RunStatus::converged);
  double worst = 0.0;
  for (const ContactPointResult& point : run.solution.contact[0].points) {
    worst = std::max(worst, std::abs(point.pressure / p - 1.0));
  }
  std::printf("press fit adaptive: %zu nodes, worst contact pressure error %.3g %%\n", run.model.nodes.size(),
              100.0 * worst);
  // Observed 0.123 %; docs/import.md: within 0.13 % (0.093 % when the free surfaces' recovered
  // stresses were extrapolated patches and the hub's outside was refined less: the contact's mesh
  // is the same, 0.0188 -> 0.0065).
  EXPECT_LT(worst, 0.0013);
}

TEST(AdaptiveLoop, AReMeshThatOvershootsMaxNodesStopsAtTheLimit) {
  // Sizes aimed at 400 nodes give Gmsh's 482: the run stops there with the error reached (it used
  // to fail the re-import with "max_nodes = 400 is fewer than the first mesh's 482 nodes").
  json a = load(assemblies / "le1-adapt.assembly.json");
  a["adapt"] = {{"target_error", 0.001}, {"max_cycles", 6}, {"max_nodes", 400}};
  const io::AdaptiveRun run = adapt(a, assemblies);
  EXPECT_FALSE(run.reached);
  ASSERT_EQ(run.cycles.size(), 2U);
  EXPECT_GT(run.cycles.back().nodes, 400U);
  EXPECT_EQ(run.solution.status, RunStatus::converged);
  EXPECT_NE(run.message.find("adaptation stopped at the limit max_nodes = 400"), std::string::npos) << run.message;
}

TEST(AdaptiveLoop, ALimitThatCannotBeMetStopsWithTheReachedError) {
  json a = load(assemblies / "le1-adapt.assembly.json");
  a["adapt"] = {{"target_error", 0.001}, {"max_cycles", 2}};
  const io::AdaptiveRun run = adapt(a, assemblies);
  EXPECT_FALSE(run.reached);
  ASSERT_EQ(run.cycles.size(), 2U);
  EXPECT_EQ(run.solution.status, RunStatus::converged);
  EXPECT_NE(run.message.find("adaptation stopped at the limit max_cycles = 2 with relative error"), std::string::npos)
      << run.message;
  EXPECT_NE(run.message.find("relative error 0.02857 > target 0.001"), std::string::npos) << run.message;  // docs/import.md
}

/// A loop resumed after cycle 1 from the sizes that cycle asked for (as the service resumes an
/// adaptive job after a crash) meshes and solves cycle 2 exactly as the loop that never stopped; the
/// sizes survive their JSON form. Each cycle's time is split into mesh, import, solve, estimate.
TEST(AdaptiveLoop, AResumedLoopGoesOnWhereItStopped) {
  json a = load(assemblies / "le1-adapt.assembly.json");
  a["adapt"] = {{"target_error", 0.001}, {"max_cycles", 2}};
  const auto settings = io::read_adapt_settings(a, [](const std::string&, const std::string&) {});
  ASSERT_TRUE(settings);
  std::vector<io::AdaptCycle> rows;
  std::vector<json> sizes;
  const io::AdaptiveRun whole = io::run_adaptive(
      a, assemblies, io::FileAccess::anywhere, *settings, [](const Model& m) { return solve(m); },
      [&](const io::AdaptCycle& c, const io::AdaptSizes* next) {
        rows.push_back(c);
        sizes.push_back(next != nullptr ? io::adapt_sizes_json(*next) : json());
      });
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_TRUE(sizes[1].is_null());
  ASSERT_TRUE(sizes[0].is_object());
  for (const io::AdaptCycle& c : rows) {
    EXPECT_GT(c.mesh_seconds, 0.0);
    EXPECT_GT(c.solve_seconds, 0.0);
    EXPECT_GT(c.estimate_seconds, 0.0);
    EXPECT_EQ(io::adaptation_json(io::adaptation_row(io::adaptation_json(c))), io::adaptation_json(c));
  }

  io::AdaptResume resume;
  resume.cycles = {rows[0]};
  resume.sizes = io::adapt_sizes_from_json(json::parse(sizes[0].dump()));
  int reported = 0;
  const io::AdaptiveRun resumed = io::run_adaptive(
      a, assemblies, io::FileAccess::anywhere, *settings, [](const Model& m) { return solve(m); },
      [&](const io::AdaptCycle& c, const io::AdaptSizes*) {
        ++reported;
        EXPECT_EQ(c.cycle, 2);
      },
      &resume);
  EXPECT_EQ(reported, 1);
  ASSERT_EQ(resumed.cycles.size(), 2U);
  EXPECT_EQ(resumed.cycles[1].nodes, whole.cycles[1].nodes);
  EXPECT_EQ(resumed.cycles[1].relative_error, whole.cycles[1].relative_error);
  EXPECT_EQ(resumed.message, whole.message);
  EXPECT_EQ(resumed.solution.error_estimate->error, whole.solution.error_estimate->error);
}

}  // namespace
}  // namespace saasgaps
