#pragma once
/// The adaptive loop of an assembly with `adapt` (docs/import.md): import the `.geo` (meshed with its
/// own sizes), solve, estimate; while error_estimate.relative > target_error and no limit is reached,
/// new sizes from the error field (io/import/adapt_sizes.hpp), re-mesh the geometry in the
/// sandboxed mesher with them as its background size, re-import (groups, contact surfaces and face
/// pairs, loads, temperatures, thermal conditions: everything the assembly names, regenerated
/// on the new mesh), solve again. `saasgaps solve ASSEMBLY.json` and the service's import jobs run
/// it; the caller solves (its observer, its cancellation) and hears of every cycle.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/import/adapt_settings.hpp"
#include "io/import/assembly_reader.hpp"
#include "io/json/json_writer.hpp"
#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps::io {

/// One cycle: a mesh and its solve (the result's `adaptation` rows, docs/results.md).
struct AdaptCycle {
  int cycle = 0;  ///< 1: the geometry's own mesh
  std::size_t nodes = 0;
  std::size_t elements = 0;
  std::size_t unknowns = 0;  ///< 2 per node (the displacements)
  double relative_error = 0.0;
  double mesh_seconds = 0.0;    ///< Gmsh meshing the geometry (in the sandboxed mesher), its transfer included
  double import_seconds = 0.0;  ///< the rest of the import: groups, loads, contact, the model read
  double solve_seconds = 0.0;   ///< the solve, its recovery and error estimate included
  double sizes_seconds = 0.0;   ///< the new sizes from the error field (0 in the last cycle)
};

struct AdaptiveRun {
  Model model;        ///< the last cycle's
  Solution solution;  ///< the last cycle's
  std::vector<AdaptCycle> cycles;
  bool reached = false;  ///< error_estimate.relative <= target_error
  std::string message;   ///< how the loop ended: the target reached, or the limit that stopped it
};

/// `solve` solves one cycle's model; `on_cycle` hears of each cycle once solved (may be empty).
/// Throws what import_assembly and `solve` throw; a re-mesh beyond the mesh limits ends the loop at
/// the cycle before (said in the message).
AdaptiveRun run_adaptive(const nlohmann::json& assembly, const std::filesystem::path& base, FileAccess access,
                         const AdaptSettings& settings, const std::function<Solution(const Model&)>& solve,
                         const std::function<void(const AdaptCycle&)>& on_cycle = {});

/// The `adaptation` rows: [{"cycle", "nodes", "elements", "relative_error", "unknowns", "seconds":
/// {"mesh", "import", "solve", "sizes"}}], members in byte order as the result writer keeps them.
void write_adaptation(JsonWriter& out, const std::vector<AdaptCycle>& cycles);
nlohmann::json adaptation_json(const AdaptCycle& cycle);

}  // namespace saasgaps::io
