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
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/import/adapt_settings.hpp"
#include "io/import/adapt_sizes.hpp"
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
  double solve_seconds = 0.0;   ///< the solve, without its recovery and error estimate
  double estimate_seconds = 0.0;  ///< the recovered stresses (and heat flux) and the error estimate
  double sizes_seconds = 0.0;   ///< the new sizes from the error field (0 in the last cycle)
};

/// Where a loop stopped part-way resumes (the service's adaptive jobs after a crash, a shutdown or
/// a cancel): the cycles done, and the sizes the last of them asked for. run_adaptive then meshes
/// with `sizes` as cycle cycles.back().cycle + 1. `previous`: the sizes that meshed the last cycle
/// (none for cycle 1): should that re-mesh pass the mesh limits, the last cycle is meshed and solved
/// again for the result.
struct AdaptResume {
  std::vector<AdaptCycle> cycles;
  AdaptSizes sizes;
  std::optional<AdaptSizes> previous;
};

struct AdaptiveRun {
  Model model;        ///< the last cycle's
  Solution solution;  ///< the last cycle's
  std::vector<AdaptCycle> cycles;
  bool reached = false;  ///< error_estimate.relative <= target_error
  bool stopped = false;  ///< a solve was stopped (cancel, shutdown): model and solution are not set
  std::string message;   ///< how the loop ended: the target reached, or the limit that stopped it
};

/// Hears of each cycle once solved: the cycle, and the sizes the next cycle will mesh with (null
/// when this cycle is the last).
using AdaptCycleObserver = std::function<void(const AdaptCycle&, const AdaptSizes* next)>;

/// `solve` solves one cycle's model; `on_cycle` hears of each cycle once solved (may be empty).
/// `resume`: go on from a loop stopped part-way (nullptr: from the geometry's own mesh). A solve
/// that returns RunStatus::stopped (a cancel, a shutdown) ends the loop at once: that cycle is
/// neither reported nor kept (`stopped` set); so does `stop_requested` returning true, asked before
/// each solve and after each cycle that is not the last. Throws what import_assembly and `solve` throw; a
/// re-mesh beyond the mesh limits ends the loop at the cycle before (said in the message).
AdaptiveRun run_adaptive(const nlohmann::json& assembly, const std::filesystem::path& base, FileAccess access,
                         const AdaptSettings& settings, const std::function<Solution(const Model&)>& solve,
                         const AdaptCycleObserver& on_cycle = {}, const AdaptResume* resume = nullptr,
                         const std::function<bool()>& stop_requested = {});

/// The `adaptation` rows: [{"cycle", "nodes", "elements", "relative_error", "unknowns", "seconds":
/// {"estimate", "import", "mesh", "sizes", "solve"}}], members in byte order as the result writer
/// keeps them.
void write_adaptation(JsonWriter& out, const std::vector<AdaptCycle>& cycles);
nlohmann::json adaptation_json(const AdaptCycle& cycle);
/// A row of adaptation_json read back. Throws nlohmann's exceptions for a row of another shape.
AdaptCycle adaptation_row(const nlohmann::json& row);

/// The sizes a cycle asked for, as JSON ({"x", "y", "size", "triangles", "predicted_nodes",
/// "bounded_by_nodes"}), and back: what the service stores with each cycle so that a loop resumes
/// where it stopped.
nlohmann::json adapt_sizes_json(const AdaptSizes& sizes);
AdaptSizes adapt_sizes_from_json(const nlohmann::json& j);

}  // namespace saasgaps::io
