#include "io/import/adaptive_loop.hpp"

#include <algorithm>
#include <array>
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
                         const AdaptCycleObserver& on_cycle, const AdaptResume* resume,
                         const std::function<bool()>& stop_requested) {
  AdaptiveRun run;
  std::optional<AdaptSizes> sizes;
  int first = 1;
  if (resume != nullptr && !resume->cycles.empty()) {
    run.cycles = resume->cycles;
    sizes = resume->sizes;
    first = resume->cycles.back().cycle + 1;
  }
  const std::string target = number(settings.target_error);
  for (int cycle = first;; ++cycle) {
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
      if (cycle == first) {
        // Resumed right at the re-mesh that fails: the last cycle is meshed and solved again for the result.
        sizes = resume->previous;
        run.cycles.pop_back();
        cycle -= 2;  // the loop's ++cycle makes it the last cycle again
        continue;
      }
      return run;
    }
    Model model = read_model(document);
    document = nlohmann::json();
    row.mesh_seconds = mesh_seconds;
    row.import_seconds = seconds_since(start) - mesh_seconds;
    if (stop_requested && stop_requested()) {  // asked while Gmsh meshed
      run.stopped = true;
      return run;
    }
    const auto solve_start = Clock::now();
    Solution solution = solve(model);
    if (solution.status == RunStatus::stopped) {
      run.stopped = true;
      return run;
    }
    // The recovery and the estimate, of the stresses and (with `thermal`) of the heat flux.
    row.estimate_seconds = solution.recovery_seconds + (solution.thermal ? solution.thermal->recovery_seconds : 0.0);
    row.solve_seconds = std::max(0.0, seconds_since(solve_start) - row.estimate_seconds);
    row.nodes = model.nodes.size();
    row.elements = model.elements.size();
    row.unknowns = 2 * model.nodes.size();
    row.relative_error = solution.error_estimate ? solution.error_estimate->relative : 0.0;
    const bool converged = solution.status == RunStatus::converged && solution.error_estimate.has_value();
    run.reached = converged && row.relative_error <= settings.target_error;
    std::string stop = run.message;  // a re-mesh past the limit after a resume: this cycle is the last
    if (!stop.empty()) {
    } else if (!converged) {
      stop = "adaptation stopped at cycle " + std::to_string(cycle) + ": the solve did not converge";
    } else if (run.reached) {
      stop = "adaptation reached relative error " + number(row.relative_error) + " <= target " + target + " in " +
             std::to_string(cycle) + (cycle == 1 ? " cycle" : " cycles");
    } else if (cycle >= settings.max_cycles) {
      stop = "adaptation stopped at the limit max_cycles = " + std::to_string(settings.max_cycles) +
             " with relative error " + number(row.relative_error) + " > target " + target;
    } else if ((sizes && sizes->bounded_by_nodes && static_cast<double>(row.nodes) >= 0.8 * settings.max_nodes) ||
               row.nodes >= settings.max_nodes) {  // Gmsh may overshoot the count the sizes aimed at
      stop = "adaptation stopped at the limit max_nodes = " + std::to_string(settings.max_nodes) + " (" +
             std::to_string(row.nodes) + " nodes) with relative error " + number(row.relative_error) + " > target " +
             target;
    }
    run.message = std::move(stop);
    const bool last = !run.message.empty();
    if (!last) {
      const auto sizes_start = Clock::now();
      sizes = adapt_sizes(model, solution, settings.target_error, settings.max_nodes);
      row.sizes_seconds = seconds_since(sizes_start);
    }
    run.cycles.push_back(row);
    if (on_cycle) on_cycle(row, last ? nullptr : &*sizes);
    run.model = std::move(model);
    run.solution = std::move(solution);
    if (last) return run;
    if (stop_requested && stop_requested()) {
      run.stopped = true;
      return run;
    }
  }
}

nlohmann::json adaptation_json(const AdaptCycle& c) {
  return {{"cycle", c.cycle},
          {"elements", c.elements},
          {"nodes", c.nodes},
          {"relative_error", c.relative_error},
          {"seconds", {{"estimate", c.estimate_seconds}, {"import", c.import_seconds}, {"mesh", c.mesh_seconds},
                       {"sizes", c.sizes_seconds}, {"solve", c.solve_seconds}}},
          {"unknowns", c.unknowns}};
}

AdaptCycle adaptation_row(const nlohmann::json& row) {
  AdaptCycle c;
  c.cycle = row.at("cycle").get<int>();
  c.elements = row.at("elements").get<std::size_t>();
  c.nodes = row.at("nodes").get<std::size_t>();
  c.relative_error = row.at("relative_error").get<double>();
  c.unknowns = row.at("unknowns").get<std::size_t>();
  const nlohmann::json& t = row.at("seconds");
  c.estimate_seconds = t.value("estimate", 0.0);
  c.import_seconds = t.at("import").get<double>();
  c.mesh_seconds = t.at("mesh").get<double>();
  c.sizes_seconds = t.at("sizes").get<double>();
  c.solve_seconds = t.at("solve").get<double>();
  return c;
}

nlohmann::json adapt_sizes_json(const AdaptSizes& sizes) {
  return {{"bounded_by_nodes", sizes.bounded_by_nodes}, {"predicted_nodes", sizes.predicted_nodes},
          {"size", sizes.field.size}, {"triangles", sizes.field.triangles}, {"x", sizes.field.x},
          {"y", sizes.field.y}};
}

AdaptSizes adapt_sizes_from_json(const nlohmann::json& j) {
  AdaptSizes s;
  s.bounded_by_nodes = j.at("bounded_by_nodes").get<bool>();
  s.predicted_nodes = j.at("predicted_nodes").get<double>();
  s.field.size = j.at("size").get<std::vector<double>>();
  s.field.triangles = j.at("triangles").get<std::vector<std::array<int, 3>>>();
  s.field.x = j.at("x").get<std::vector<double>>();
  s.field.y = j.at("y").get<std::vector<double>>();
  return s;
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
        .field("estimate", c.estimate_seconds)
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
