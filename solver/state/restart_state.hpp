#pragma once
/// The computational restart of the report (Appendix A, "COMPUTATIONAL RESTART"): after every
/// iteration, a complete snapshot of everything the next iteration depends on. Resuming from it
/// with nothing changed reproduces the uninterrupted run to the last digit.

#include <optional>
#include <vector>

#include "solver/materials/material_state.hpp"
#include "solver/model/load_schedule.hpp"
#include "solver/state/contact_state.hpp"
#include "solver/state/gap_history.hpp"
#include "solver/state/iteration_record.hpp"

namespace saasgaps {

/// Version 1: a model without steps (written exactly as before steps existed). Version 2: a stepped
/// model's state, which also records its position on the load path. Version 3: a stepped model with
/// a plastic material, whose state also records the elements' plastic peaks and unloading branches
/// (MaterialState::peaks, unloading); a version-2 state of such a model still reads, as a run with no
/// peak recorded before it.
struct RestartState {
  static constexpr int plain_version = 1;
  static constexpr int stepped_version = 2;
  static constexpr int plastic_steps_version = 3;
  static constexpr int current_version = plain_version;  ///< of a state without position
  int version = current_version;
  int iteration = 0;               ///< K: iterations finished (0: nothing solved yet)
  int attempt = 1;                 ///< run that produced iteration K (1, then +1 per resume)
  MaterialState materials;         ///< secant ratios, bimodulus choices and plastic branches iteration K used
  GapHistory gaps;                 ///< gap moduli and strains of iterations K and K-1
  std::vector<double> displacement;  ///< (u_r, u_z) per node of iteration K, prescribed ones included
  ContactState contact;            ///< exact mode: pair forces and active set of iteration K (empty in classic)
  /// Contact surfaces with friction > 0 (empty otherwise): every mortar point's friction state of
  /// iteration K, with the slip history of the finished increments (they replace `contact` then).
  FrictionState friction;
  std::vector<IterationRecord> history;  ///< rows 1..K
  /// Stepped models only (version 2): the increment of iteration K (K counts over the whole run).
  std::optional<StepPosition> position;

  /// Model dimensions the state belongs to, checked on resume.
  std::size_t node_count = 0;
  std::size_t element_count = 0;
  /// Material points of the solid elements (fe/material_points.hpp), the length of the material
  /// state's vectors: element_count when every element is one of the report's (one point each).
  std::size_t material_point_count = 0;
  std::size_t gap_count = 0;
};

/// The version a run of `model` writes: 1 without steps, 2 with steps, 3 with steps and plasticity.
inline int restart_version(const Model& model) {
  if (model.steps.empty()) return RestartState::plain_version;
  for (const Material& m : model.materials) {
    if (!m.plasticity.empty()) return RestartState::plastic_steps_version;
  }
  return RestartState::stepped_version;
}

}  // namespace saasgaps
