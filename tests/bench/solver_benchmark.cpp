// saasgaps_bench: times the solver's stages on a generated structured plane-strain model.
//
//   build/tests/bench/saasgaps_bench --dofs 1000000 [--gaps] [--baseline] [--end-to-end]
//   build/tests/bench/saasgaps_bench --dofs 1000000 --family quad8
//   build/tests/bench/saasgaps_bench --dofs 1000000 --family quad8 --recovery
//
// The model is an n x n block of SAAS quads, fixed at the bottom, pressed on the top, heated; with
// --gaps it is cut in two at mid height by a row of gap elements; with --family quad8 or quad9 the
// block is of those elements (n chosen for the same number of unknowns; no gaps). Reported per stage: wall time and
// the true peak resident memory of the whole process during that stage (VmHWM of /proc/self/status,
// reset before each stage by writing 5 to /proc/self/clear_refs; where the kernel refuses the reset
// the column is the running peak, and the header says so). Stages: pattern construction, assembly,
// symbolic analysis, numeric factorization (first, and repeated in the same factor object), solve,
// one gap iteration (gap patch + numeric factorization + solve); with --end-to-end, solve() itself
// for three iterations twice, first computing the analysis (and storing it in a fresh cache), then
// loading it: the first iteration over a later one, uncached and cached; before those, the symbolic
// analysis with a cache three ways: computed and stored, only the ordering loaded (cholmod_analyze_p
// on it), the whole symbolic factor loaded. Ratios are
// against baselines measured in the same run: assembly / factorization, gap iteration /
// factorization, and (with --baseline) our scatter assembly against Eigen's triplet assembly.
// With --recovery: after the solve, the element states at the material points (the evaluation every
// iteration does) and then the recovered nodal stresses with the error estimate
// (solver/recovery/stress_recovery.hpp, what solve() adds at the end of a run), and the ratio of
// the latter to the repeated numeric factorization (issue 32: below 0.1 at 10^6 unknowns), each
// the best of three runs.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "solver/analysis/analysis.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/element_data.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/gaps/gap_closure.hpp"
#include "solver/lac/cholmod_memory.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/recovery/stress_recovery.hpp"
#include "support/mesh_builder.hpp"

#include "stopwatch.hpp"

using namespace saasgaps;

namespace {

using saasgaps::bench::timed;

/// A field of /proc/self/status in kB (VmHWM, VmRSS, Threads ...), or -1.
double status_field(const std::string& name) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(name + ":", 0) == 0) return std::stod(line.substr(name.size() + 1));
  }
  return -1.0;
}

/// Starts a new peak-memory interval; false when the kernel does not allow it.
bool reset_peak_rss() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

/// Stages with their wall time and the process's peak resident memory while each ran.
class Stages {
 public:
  template <class F>
  double run(const std::string& name, F&& f) {
    resettable_ = reset_peak_rss() && resettable_;
    const double seconds = timed(std::forward<F>(f));
    rows_.push_back({name, seconds, status_field("VmHWM") / 1024.0});
    return seconds;
  }
  void print() const {
    std::printf("%-52s %10s %12s\n", "stage", "seconds", resettable_ ? "peak MiB" : "running peak MiB");
    for (const Row& r : rows_) std::printf("%-52s %10.3f %12.0f\n", r.name.c_str(), r.seconds, r.peak_mib);
  }
  [[nodiscard]] double peak_mib() const {
    double peak = 0.0;
    for (const Row& r : rows_) peak = std::max(peak, r.peak_mib);
    return peak;
  }

 private:
  struct Row {
    std::string name;
    double seconds;
    double peak_mib;
  };
  std::vector<Row> rows_;
  bool resettable_ = true;
};

/// Iteration seconds of a solve() run (the history rows), the peak memory stage recorded by Stages.
std::vector<double> iteration_seconds(const Model& m, const OrderingCache& cache, int iterations) {
  ResumeOptions limit;
  limit.max_iterations = iterations;
  const Solution s = solve(m, nullptr, nullptr, limit, &cache);
  std::vector<double> seconds;
  for (const IterationRecord& row : s.history) seconds.push_back(row.seconds);
  return seconds;
}

Model block_model(int n, bool with_gaps) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, 30.0e6, 0.3, 6.5e-6)};
  const double h = 1.0 / n;
  if (!with_gaps) {
    const testing::Grid g = testing::add_grid(m, n, n, [](double s, double t) { return Vec2(s, t); }, 0);
    for (int i = 0; i <= n; ++i) testing::constrain(m, g.at(i, 0), 0.0, 0.0);
    for (int i = 0; i < n; ++i) m.loads.pressures.push_back({(n - 1) * n + i, g.at(i, n), g.at(i + 1, n), 1000.0, 0.0});
  } else {
    // Two half blocks, the upper one resting on the lower through a row of gap elements 1 % of an
    // element thick.
    const int lower_rows = n / 2, upper_rows = n - lower_rows;
    const double gap = 0.01 * h;
    const testing::Grid lower = testing::add_grid(
        m, n, lower_rows, [&](double s, double t) { return Vec2(s, t * lower_rows * h); }, 0);
    const int upper_first = static_cast<int>(m.elements.size());
    const testing::Grid upper = testing::add_grid(
        m, n, upper_rows, [&](double s, double t) { return Vec2(s, lower_rows * h + gap + t * upper_rows * h); }, 0);
    std::vector<int> below, above;
    for (int i = 0; i <= n; ++i) {
      below.push_back(lower.at(i, lower_rows));
      above.push_back(upper.at(i, 0));
    }
    testing::add_gap_row(m, below, above, [](int) { return 90.0; });
    m.gaps->initial_modulus = 100.0;
    m.gaps->tensile_schedule = {1.0};
    for (int i = 0; i <= n; ++i) testing::constrain(m, lower.at(i, 0), 0.0, 0.0);
    // Hold the upper block sideways at one corner so the gaps' negligible shear is not all that holds it.
    testing::constrain(m, upper.at(0, upper_rows), 0.0, std::nullopt);
    for (int i = 0; i < n; ++i) {
      m.loads.pressures.push_back(
          {upper_first + (upper_rows - 1) * n + i, upper.at(i, upper_rows), upper.at(i + 1, upper_rows), 1000.0, 0.0});
    }
  }
  testing::fill_temperatures(m, 100.0);
  return m;
}

/// The block of quad8 or quad9 elements: n x n elements, fixed at the bottom, pressed on the top,
/// heated.
Model quadratic_block_model(int n, ElementType type) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  m.materials = {testing::isotropic_material(1, 30.0e6, 0.3, 6.5e-6)};
  const testing::QuadraticGrid g =
      testing::add_quadratic_grid(m, type, n, n, [](double s, double t) { return Vec2(s, t); }, 0);
  for (int i = 0; i <= 2 * n; ++i) testing::constrain(m, g.at(i, 0), 0.0, 0.0);
  for (int i = 0; i < n; ++i) {
    m.loads.pressures.push_back({(n - 1) * n + i, g.at(2 * i, 2 * n), g.at(2 * i + 2, 2 * n), 1000.0, 0.0});
  }
  testing::fill_temperatures(m, 100.0);
  return m;
}

/// Eigen's triplet assembly of the same element matrices: the textbook baseline.
double triplet_assembly_seconds(const Model& m, const DofMap& dofs, const SolidMaterials& materials,
                                const MaterialState& state) {
  return timed([&] {
    std::vector<Eigen::Triplet<double, Index>> triplets;
    triplets.reserve(m.elements.size() * 36);
    for (std::size_t e = 0; e < m.elements.size(); ++e) {
      const ElementMatrices em = element_matrices(solid_element_data(m, e, materials.law(e, state)));
      std::array<Index, 8> eq{};
      dofs.equations(m.elements[e].nodes, eq);
      for (int b = 0; b < 8; ++b) {
        for (int a = 0; a <= b; ++a) {
          if (eq[a] >= 0 && eq[b] >= 0) triplets.emplace_back(std::min(eq[a], eq[b]), std::max(eq[a], eq[b]), em.K(a, b));
        }
      }
    }
    Eigen::SparseMatrix<double, Eigen::ColMajor, Index> K(dofs.size(), dofs.size());
    K.setFromTriplets(triplets.begin(), triplets.end());
  });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times the SAASGAPS solver stages on a generated structured plane-strain model"};
  double target_dofs = 1.0e5;
  bool with_gaps = false;
  bool baseline = false;
  bool end_to_end = false;
  app.add_option("--dofs", target_dofs, "Approximate number of degrees of freedom")->check(CLI::Range(100.0, 1.0e8));
  app.add_flag("--gaps", with_gaps, "Cut the block by a row of gap elements and time a gap iteration");
  app.add_flag("--baseline", baseline, "Also time Eigen's triplet assembly (after the peak memory reading)");
  app.add_flag("--end-to-end", end_to_end,
               "Also time one whole iteration as saasgaps solve runs it (fresh objects; symbolic analysis "
               "beside the assembly; stress recovery)");
  bool huge_pages = false;
  app.add_flag("--huge-pages", huge_pages, "Advise CHOLMOD's large blocks to use transparent huge pages");
  std::string family = "saas";
  app.add_option("--family", family, "The block's elements: saas (the report's), quad8 or quad9")
      ->check(CLI::IsMember({"saas", "quad8", "quad9"}));
  bool recovery = false;
  app.add_flag("--recovery", recovery,
               "Also time the stress recovery and error estimate of the solved displacements");
  CLI11_PARSE(app, argc, argv);
  advise_huge_pages(huge_pages);
  if (family != "saas" && (with_gaps || baseline)) {
    std::fprintf(stderr, "--gaps and --baseline need the SAAS block (gap elements join linear edges)\n");
    return 2;
  }

  // Unknowns per element: 2 for a 4-node grid, 6 for quad8 (3 nodes per cell), 8 for quad9.
  const double per_cell = family == "saas" ? 2.0 : family == "quad8" ? 6.0 : 8.0;
  const int n = std::max(2, static_cast<int>(std::lround(std::sqrt(target_dofs / per_cell))) - 1);
  const Model m = family == "saas" ? block_model(n, with_gaps)
                                   : quadratic_block_model(n, family == "quad8" ? ElementType::quad8 : ElementType::quad9);

  Stages stages;
  std::vector<double> u;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<StiffnessSystem> system;
  const SolidMaterials materials(m);
  const MaterialState state = materials.initial();
  stages.run("pattern and scatter map (once per model)", [&] {
    dofs = std::make_unique<DofMap>(m);
    system = std::make_unique<StiffnessSystem>(m, *dofs);
  });
  SolidMaterials::LawMemo memo;
  const double assembly_s = stages.run("assembly (solid elements)", [&] {
    system->assemble_solids([&](std::size_t e) { return materials.law(e, state, memo); });
  });

  std::unique_ptr<GapClosure> gaps;
  GapModuli moduli;
  if (with_gaps) {
    gaps = std::make_unique<GapClosure>(*m.gaps);
    moduli = gaps->initial();
    system->assemble_gaps([&](std::size_t g) { return gaps->law(g, moduli, m.analysis); });
  }
  std::unique_ptr<SparseCholesky> cholesky;
  stages.run("symbolic analysis (once per model)", [&] {
    cholesky = std::make_unique<SparseCholesky>(system->pattern(), dofs->node_of_equation());
  });
  const double ordering_s = cholesky->ordering_seconds();
  const std::string ordering_name = cholesky->ordering();
  const auto cache_dir = std::filesystem::temp_directory_path() / ("saasgaps-bench-cache-" + std::to_string(::getpid()));
  if (end_to_end) {
    // The analysis as solve() makes it with a cache: computed and stored, then with only the
    // ordering file there (cholmod_analyze_p on the loaded order), then all of it loaded.
    std::filesystem::remove_all(cache_dir);
    const OrderingCache cache(cache_dir);
    const auto analysis = [&](const char* stage) {
      cholesky.reset();
      stages.run(stage, [&] {
        cholesky = std::make_unique<SparseCholesky>(system->pattern(), dofs->node_of_equation(), &cache);
      });
    };
    analysis("symbolic analysis with a cache, computed and stored");
    for (const auto& entry : std::filesystem::directory_iterator(cache_dir)) {
      if (entry.path().extension() == ".symbolic") std::filesystem::remove(entry.path());
    }
    analysis("symbolic analysis, ordering loaded, rest computed");
    analysis("symbolic analysis, all loaded");
    std::filesystem::remove_all(cache_dir);
  }
  stages.run("numeric factorization, first", [&] { cholesky->factorize(system->values()); });
  // With --recovery the two sides of its ratio are each the best of three runs.
  const int repeats = recovery ? 3 : 1;
  double numeric_s = 0.0;
  for (int k = 0; k < repeats; ++k) {
    const double s = stages.run("numeric factorization, repeated", [&] { cholesky->factorize(system->values()); });
    numeric_s = k == 0 ? s : std::min(numeric_s, s);
  }
  u.resize(static_cast<std::size_t>(dofs->size()));
  stages.run("solve", [&] { cholesky->solve(system->rhs(), u); });
  double recovery_s = 0.0;
  if (recovery) {
    // The displacements per node (u_r, u_z), prescribed components included.
    std::vector<double> displacement(2 * m.nodes.size(), 0.0);
    for (std::size_t node = 0; node < m.nodes.size(); ++node) {
      for (int dir = 0; dir < 2; ++dir) {
        const Index eq = dofs->equation(static_cast<int>(node), dir);
        displacement[2 * node + static_cast<std::size_t>(dir)] =
            eq >= 0 ? u[static_cast<std::size_t>(eq)] : dofs->prescribed(static_cast<int>(node), dir);
      }
    }
    const MaterialPoints& points = materials.points();
    std::vector<ElementState> point_states(points.size());
    stages.run("element states at the material points (each iteration's evaluation)", [&] {
      std::array<Constitutive, max_material_points> laws;
      for (std::size_t e = 0; e < m.elements.size(); ++e) {
        const ElementData data = solid_element_data(m, e, materials.laws(e, state, memo, laws));
        const ElementStates s = element_states(data, values(element_displacements(displacement, m.elements[e].node_span())));
        std::copy_n(s.point.begin(), s.point_count, point_states.begin() + static_cast<std::ptrdiff_t>(points.first(e)));
      }
    });
    StressRecovery recovered;
    for (int k = 0; k < repeats; ++k) {
      const double s = stages.run("recovered stresses and error estimate", [&] {
        recovered = recover_stresses(
            m, displacement,
            [&] {
              return PointLawsOf([&, memo = SolidMaterials::LawMemo{}](std::size_t e, std::span<Constitutive> scratch) mutable {
                return materials.laws(e, state, memo, scratch);
              });
            },
            point_states, points);
      });
      recovery_s = k == 0 ? s : std::min(recovery_s, s);
    }
    std::printf("error estimate: relative %.4g, error %.4g, energy norm %.4g\n", recovered.estimate.relative,
                recovered.estimate.error, recovered.estimate.energy_norm);
  }
  double gap_iteration_s = 0.0;
  if (with_gaps) {
    // One iteration of section II when only gap moduli change: patch, refactor, solve.
    for (double& e : moduli.normal) e *= 3.0;
    gap_iteration_s = stages.run("gap iteration (patch + factorize + solve)", [&] {
      system->assemble_gaps([&](std::size_t g) { return gaps->law(g, moduli, m.analysis); });
      cholesky->factorize(system->values());
      cholesky->solve(system->rhs(), u);
    });
  }

  std::printf("model: %d x %d %s elements%s, %zu nodes, %lld unknowns, nnz(K upper) %lld, nnz(L) %.3g, %.3g Gflop per "
              "factorization, ordering %s (%.3f s of the analysis)\n",
              n, n, family.c_str(), with_gaps ? " cut by a row of gap elements" : "", m.nodes.size(),
              static_cast<long long>(dofs->size()), static_cast<long long>(system->pattern().nnz()),
              cholesky->factor_nonzeros(), cholesky->factor_flops() / 1e9, ordering_name.c_str(), ordering_s);
  // The stage objects go before solve() runs on its own, so its peak is a solve's alone.
  cholesky.reset();
  system.reset();
  std::vector<double>().swap(u);

  std::vector<double> uncached, cached;
  if (end_to_end) {
    const OrderingCache cache(cache_dir);
    stages.run("end to end: solve(), 3 iterations, ordering computed", [&] { uncached = iteration_seconds(m, cache, 3); });
    stages.run("end to end: solve(), 3 iterations, analysis cached", [&] { cached = iteration_seconds(m, cache, 3); });
    std::filesystem::remove_all(cache_dir);
  }
  double triplet_s = 0.0;
  if (baseline) {
    triplet_s = stages.run("baseline: Eigen triplet assembly", [&] {
      dofs = std::make_unique<DofMap>(m);
      triplet_assembly_seconds(m, *dofs, materials, state);
    });
  }
  stages.print();
  std::printf("threads in the process at the end: %.0f; huge-page advice %s\n", status_field("Threads"),
              huge_pages ? "on" : "off");
  std::printf("ratio assembly / repeated factorization: %.3f\n", assembly_s / numeric_s);
  if (with_gaps) std::printf("ratio gap iteration / repeated factorization: %.3f\n", gap_iteration_s / numeric_s);
  if (recovery) {
    std::printf("ratio recovery and estimate / repeated factorization: %.3f\n", recovery_s / numeric_s);
  }
  const auto first_over_later = [](const std::vector<double>& s) {
    if (s.size() < 2) return 0.0;
    std::vector<double> later(s.begin() + 1, s.end());
    std::sort(later.begin(), later.end());
    return s.front() / later[later.size() / 2];
  };
  const auto print_iterations = [&](const char* name, const std::vector<double>& s) {
    std::printf("%s: iteration seconds", name);
    for (double x : s) std::printf(" %.3f", x);
    std::printf("; first / later (median) %.3f\n", first_over_later(s));
  };
  if (end_to_end) {
    print_iterations("end to end, ordering computed", uncached);
    print_iterations("end to end, analysis cached", cached);
  }
  if (baseline) std::printf("ratio scatter assembly / triplet assembly: %.3f\n", assembly_s / triplet_s);
  return 0;
}
