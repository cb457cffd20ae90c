#include "io/import/adaptive_loop.hpp"

#include <chrono>
#include <cstdio>
#include <optional>
#include <utility>

#include "io/import/adapt_sizes.hpp"
#include "io/mesher/gmsh_mesh.hpp"
#include "io/model/model_reader.hpp"

namespace saasgaps::io {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

}  // namespace

AdaptiveRun run_adaptive(const nlohmann::json& assembly, const std::filesystem::path& base, FileAccess access,
                         const AdaptSettings& settings, const std::function<Solution(const Model&)>& solve,
                         const std::function<void(const AdaptCycle&)>& on_cycle) {
  AdaptiveRun run;
  std::optional<AdaptSizes> sizes;
  const std::string target = number(settings.target_error);
  for (int cycle = 1;; ++cycle) {
    AdaptCycle row;
    row.cycle = cycle;
    const auto start = Clock::now();
    double mesh_seconds = 0.0;
    nlohmann::json document;
    try {
      document = import_assembly(assembly, base, access, sizes ? &sizes->field : nullptr, &mesh_seconds);
    } catch (const MeshTooLarge& e) {
      if (cycle == 1) throw;
      run.message = "adaptation stopped after cycle " + std::to_string(cycle - 1) + " at relative error " +
                    number(run.cycles.back().relative_error) + " > target " + target +
                    ": the refined mesh passes the mesh limit (" + e.what() + ")";
      return run;
    }
    Model model = read_model(document);
    document = nlohmann::json();
    row.mesh_seconds = mesh_seconds;
    row.import_seconds = seconds_since(start) - mesh_seconds;
    const auto solve_start = Clock::now();
    Solution solution = solve(model);
    row.solve_seconds = seconds_since(solve_start);
    row.nodes = model.nodes.size();
    row.elements = model.elements.size();
    row.unknowns = 2 * model.nodes.size();
    row.relative_error = solution.error_estimate ? solution.error_estimate->relative : 0.0;
    const bool converged = solution.status == RunStatus::converged && solution.error_estimate.has_value();
    run.reached = converged && row.relative_error <= settings.target_error;
    std::string stop;
    if (!converged) {
      stop = "adaptation stopped at cycle " + std::to_string(cycle) + ": the solve did not converge";
    } else if (run.reached) {
      run.message = "adaptation reached relative error " + number(row.relative_error) + " <= target " + target + " in " +
                    std::to_string(cycle) + (cycle == 1 ? " cycle" : " cycles");
    } else if (cycle >= settings.max_cycles) {
      stop = "adaptation stopped at the limit max_cycles = " + std::to_string(settings.max_cycles) +
             " with relative error " + number(row.relative_error) + " > target " + target;
    } else if (sizes && sizes->bounded_by_nodes && static_cast<double>(row.nodes) >= 0.8 * settings.max_nodes) {
      stop = "adaptation stopped at the limit max_nodes = " + std::to_string(settings.max_nodes) + " (" +
             std::to_string(row.nodes) + " nodes) with relative error " + number(row.relative_error) + " > target " +
             target;
    }
    if (!stop.empty()) run.message = std::move(stop);
    const bool last = !run.message.empty();
    if (!last) {
      const auto sizes_start = Clock::now();
      sizes = adapt_sizes(model, solution, settings.target_error, settings.max_nodes);
      row.sizes_seconds = seconds_since(sizes_start);
    }
    run.cycles.push_back(row);
    if (on_cycle) on_cycle(row);
    run.model = std::move(model);
    run.solution = std::move(solution);
    if (last) return run;
  }
}

nlohmann::json adaptation_json(const AdaptCycle& c) {
  return {{"cycle", c.cycle},
          {"elements", c.elements},
          {"nodes", c.nodes},
          {"relative_error", c.relative_error},
          {"seconds", {{"import", c.import_seconds}, {"mesh", c.mesh_seconds}, {"sizes", c.sizes_seconds},
                       {"solve", c.solve_seconds}}},
          {"unknowns", c.unknowns}};
}

void write_adaptation(JsonWriter& out, const std::vector<AdaptCycle>& cycles) {
  out.key("adaptation").begin_array();
  for (const AdaptCycle& c : cycles) {
    out.begin_object()
        .field("cycle", c.cycle)
        .field("elements", static_cast<std::uint64_t>(c.elements))
        .field("nodes", static_cast<std::uint64_t>(c.nodes))
        .field("relative_error", c.relative_error);
    out.key("seconds")
        .begin_object()
        .field("import", c.import_seconds)
        .field("mesh", c.mesh_seconds)
        .field("sizes", c.sizes_seconds)
        .field("solve", c.solve_seconds)
        .end_object();
    out.field("unknowns", static_cast<std::uint64_t>(c.unknowns)).end_object();
  }
  out.end_array();
}

}  // namespace saasgaps::io
