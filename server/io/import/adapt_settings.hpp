#pragma once
/// The `adapt` block of an assembly document (docs/import.md, schemas/assembly.schema.json):
/// `{"target_error": 0.02, "max_cycles": 6, "max_nodes": 200000}`, only target_error required.
/// The adaptive loop (solve, estimate, re-mesh the `.geo` with sizes from the error field, re-import,
/// solve again) runs until error_estimate.relative <= target_error or a limit is reached.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

struct AdaptSettings {
  double target_error = 0.0;      ///< 0 < target_error < 1: the relative error in the energy norm sought
  int max_cycles = 6;             ///< solves at most, the first mesh's included (1 .. max_adapt_cycles)
  std::size_t max_nodes = 200000; ///< a refined mesh is never asked for beyond this many nodes
};

constexpr int max_adapt_cycles = 50;          ///< more cycles than this is a mistake, not a plan
constexpr std::size_t min_adapt_nodes = 100;  ///< fewer nodes leave nothing to refine
constexpr std::size_t max_adapt_nodes = 100000000;  ///< as --max-mesh-nodes

/// The settings of assembly["adapt"], nullopt when there is none or it is wrong; every problem is
/// reported at its JSON Pointer (/adapt, /adapt/target_error, ...) with the value.
std::optional<AdaptSettings> read_adapt_settings(const nlohmann::json& assembly,
                                                 const std::function<void(const std::string&, std::string)>& report);

}  // namespace saasgaps::io
