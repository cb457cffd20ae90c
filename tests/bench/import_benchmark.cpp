// saasgaps_import_bench: times `saasgaps import` on a generated transfinite Gmsh geometry against
// the solve of the model it produces, in the same run.
//
//   build/tests/bench/saasgaps_import_bench --nodes-per-side 708    # 2 x 708 x 354 nodes: 10^6 unknowns
//
// The geometry is a unit square cut at mid height by a 1e-4 clearance: two transfinite blocks of
// quadrilaterals, fixed at the bottom, held in r on the left, pressed on the top, with one gap
// pair between the facing edges. Reported: import of the .geo (Gmsh meshing included), import of
// the same mesh saved as .msh, and the solve (model read + every iteration to convergence), and the
// ratios import / solve.
#include <gmsh.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/import/assembly_reader.hpp"
#include "io/mesher/gmsh_mesh.hpp"
#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"

#include "stopwatch.hpp"

using namespace saasgaps;
namespace fs = std::filesystem;

namespace {

using saasgaps::bench::timed;

std::string geometry(int n) {
  const int half = n / 2;
  return "n = " + std::to_string(n) + "; half = " + std::to_string(half) + "; c = 1e-4;\n" + R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 0.5, 0}; Point(4) = {0, 0.5, 0};
Point(5) = {0, 0.5 + c, 0}; Point(6) = {1, 0.5 + c, 0}; Point(7) = {1, 1 + c, 0}; Point(8) = {0, 1 + c, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 5, 7} = n; Transfinite Curve{2, 4, 6, 8} = half;
Transfinite Surface{1, 2}; Recombine Surface{1, 2};
Physical Surface("lower") = {1}; Physical Surface("upper") = {2};
Physical Curve("base") = {1}; Physical Curve("left") = {4, 8}; Physical Curve("top") = {7};
Physical Curve("lower_top") = {3}; Physical Curve("upper_bottom") = {5};
)";
}

nlohmann::json assembly(const std::string& mesh) {
  return nlohmann::json::parse(R"({
    "schema_version": 1, "title": "import benchmark", "mesh": ")" + mesh + R"(",
    "analysis": {"type": "plane_strain"},
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 30e6, "nu": 0.3, "alpha": 6.5e-6}]}],
    "regions": [{"group": "lower", "material": 1}, {"group": "upper", "material": 1}],
    "constraints": [{"group": "base", "r": 0, "z": 0}, {"group": "left", "r": 0}],
    "loads": {"pressures": [{"group": "top", "normal": 1000}]},
    "gaps": {"initial_modulus": 100, "tensile_schedule": [20, 5, 1],
             "pairs": [{"faces": ["lower_top", "upper_bottom"], "first_id": 100000000}]},
    "solver": {"max_iterations": 30}})");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Times saasgaps import against the solve of the imported model"};
  int n = 708;
  std::string dir = (fs::temp_directory_path() / "saasgaps-import-bench").string();
  app.add_option("--nodes-per-side", n, "Nodes along each side (2 blocks of n x n/2 nodes)")->check(CLI::Range(4, 5000));
  app.add_option("--dir", dir, "Scratch directory for the .geo and .msh files");
  CLI11_PARSE(app, argc, argv);

  fs::create_directories(dir);
  const fs::path geo = fs::path(dir) / "bench.geo";
  const fs::path msh = fs::path(dir) / "bench.msh";
  std::ofstream(geo) << geometry(n);
  // The .msh variant: meshed once by Gmsh here, outside the timings.
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(geo.string());
  gmsh::model::mesh::generate(2);
  gmsh::write(msh.string());
  gmsh::finalize();
  // Beyond the default node limit (200,000) at 10^6 unknowns: this geometry is our own.
  io::MeshLimits limits = io::mesh_limits();
  limits.max_nodes = std::max(limits.max_nodes, static_cast<std::size_t>(2 * n * n));
  limits.seconds = 600;
  limits.memory_bytes = std::size_t{16} << 30;
  io::set_mesh_limits(limits);

  nlohmann::json from_geo, from_msh;
  const double geo_seconds = timed([&] { from_geo = io::import_assembly(assembly("bench.geo"), dir); });
  const double msh_seconds = timed([&] { from_msh = io::import_assembly(assembly("bench.msh"), dir); });
  // Where an import's time goes: Gmsh reading the mesh, and the model reader's check of the result.
  const double gmsh_seconds = timed([&] { (void)io::read_gmsh_mesh(msh); });
  const double check_seconds = timed([&] { (void)io::read_model(from_msh); });
  std::string text;
  const double dump_seconds = timed([&] { text = from_msh.dump(); });
  Solution solution;
  const double solve_seconds = timed([&] {
    const Model model = io::parse_model(text);
    solution = solve(model);
  });
  std::printf("nodes %zu, elements %zu, gap elements %zu, unknowns %zu\n", from_msh["nodes"].size(),
              from_msh["elements"].size(), from_msh["gaps"]["elements"].size(), 2 * from_msh["nodes"].size());
  std::printf("import .geo (Gmsh meshing included)   %8.2f s\n", geo_seconds);
  std::printf("import .msh                           %8.2f s\n", msh_seconds);
  std::printf("  of which Gmsh reads the .msh          %8.2f s\n", gmsh_seconds);
  std::printf("  of which the model reader's check     %8.2f s\n", check_seconds);
  std::printf("write the model document (JSON text)  %8.2f s\n", dump_seconds);
  std::printf("solve: read model + %d iterations      %8.2f s (%s)\n", solution.iterations, solve_seconds,
              solution.status == RunStatus::converged ? "converged" : "not converged");
  std::printf("ratio import .geo / solve             %8.3f\n", geo_seconds / solve_seconds);
  std::printf("ratio import .msh / solve             %8.3f\n", msh_seconds / solve_seconds);
  fs::remove(geo);
  fs::remove(msh);
  return 0;
}
