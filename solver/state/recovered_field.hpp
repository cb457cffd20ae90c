#pragma once
/// A nodal field recovered from the elements around each node (solver/recovery/patch_recovery.hpp),
/// kept per material side: a node where elements of several materials meet holds one value per
/// material, each recovered from that material's elements alone. And the model's error estimate
/// (solver/recovery/error_estimate.hpp). Plain data.

#include <array>
#include <cstdint>
#include <vector>

#include "solver/base/voigt.hpp"

namespace saasgaps {

/// A nodal field recovered per material side. Components: the sampled values' (Voigt stress: rr, zz,
/// rz, th; a flux uses the first two).
struct RecoveredField {
  std::vector<std::uint32_t> first;  ///< node_count + 1 offsets: node n's sides are first[n] .. first[n + 1] - 1
  std::vector<int> material;         ///< per side: the material index (Model::materials)
  std::vector<Vec4> value;           ///< per side: the recovered value

  /// True when node n belongs to a solid element (it has at least one side).
  [[nodiscard]] bool has(std::size_t node) const { return node + 1 < first.size() && first[node + 1] > first[node]; }
  [[nodiscard]] int side_count(std::size_t node) const { return has(node) ? static_cast<int>(first[node + 1] - first[node]) : 0; }
  [[nodiscard]] bool empty() const { return first.empty(); }
  /// The side of node n in material m, -1 if none.
  [[nodiscard]] int side(std::size_t node, int material) const;
  /// The value node n has in material m (the mean of its sides if it has none in m).
  [[nodiscard]] Vec4 at(std::size_t node, int material) const;
  /// The mean of node n's sides (what nodes[] reports); zero for a node of no solid element.
  [[nodiscard]] Vec4 mean(std::size_t node) const;
};

/// The model's error estimate in the energy norm (result `error_estimate`): error = sqrt(sum of the
/// elements' error^2), energy_norm = sqrt(integral sigma_h : D^-1 : sigma_h dV),
/// relative = error / sqrt(energy_norm^2 + error^2).
struct ErrorEstimate {
  double relative = 0.0;
  double error = 0.0;
  double energy_norm = 0.0;
};

}  // namespace saasgaps
