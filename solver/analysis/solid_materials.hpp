#pragma once
/// The nonlinear material iteration of SAAS III: each solid element's stiffness is built from the
/// previous solution (strain invariance), through
///  - a secant modulus on the bilinear effective stress-strain curve (plasticity), and
///  - the tension or compression table per material direction, by the sign of its stress (bimodulus);
///    a direction whose stress is below the plastic tolerance of the element's largest keeps its table.
/// Across the increments of a stepped run, yielded elements unload elastically (plastic_history.hpp).

#include <cstdint>
#include <span>
#include <vector>

#include "solver/fe/element_kernel.hpp"
#include "solver/materials/material.hpp"
#include "solver/materials/material_state.hpp"
#include "solver/materials/plastic_history.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Per-element verdicts on one solution, and the state for the next iteration.
struct MaterialUpdate {
  MaterialState next;
  std::vector<bool> yielded;    ///< YIELD?: effective stress above the yield stress
  std::vector<bool> converged;  ///< N-L/CONV?: the secant modulus no longer changes
  int yielded_count = 0;
  int nonconverged_count = 0;
  int bimodulus_changes = 0;    ///< elements whose choice changed (only stressed directions change)
};

class SolidMaterials {
 public:
  explicit SolidMaterials(const Model& model);

  /// Every element elastic and in tension: the state of iteration 1.
  [[nodiscard]] MaterialState initial() const;

  /// The law of solid element e under state s (on the unloading branch: with its plastic strain).
  [[nodiscard]] Constitutive law(std::size_t e, const MaterialState& s) const;

  /// The last law computed and what it depended on: neighbouring elements usually share material,
  /// temperature, angle and state, and then share the law (a 4x4 inversion and rotation saved).
  struct LawMemo {
    int material = -1;
    double temperature = 0.0, angle = 0.0, secant_ratio = 0.0;
    DirectionChoice compression = 0;
    Constitutive law;
  };
  /// law(e, s), reusing memo when element e needs the same law as the last one.
  [[nodiscard]] const Constitutive& law(std::size_t e, const MaterialState& s, LawMemo& memo) const;

  /// Strain invariance: from the element stresses of a solution built with `used`, read the secant
  /// modulus off the bilinear curve at the same effective strain, and the bimodulus choice from
  /// the stress signs. tolerance: relative change of E_s that still counts as converged. Writes into
  /// `out`, whose buffers are reused from one iteration to the next.
  void update(const MaterialState& used, std::span<const ElementState> states, double tolerance,
              MaterialUpdate& out) const;

  /// At the end of a converged increment solved with `used` (states: its solution): every element on
  /// the loading branch past its peak (yielded: secant ratio below 1) records its new peak in
  /// `next`, the state the next increment starts from (plastic_history.hpp).
  void record_peaks(const MaterialState& used, std::span<const ElementState> states, MaterialState& next) const;

  /// True when some material is plastic or bimodulus (the iteration can change stiffness).
  [[nodiscard]] bool nonlinear() const { return nonlinear_; }

 private:
  /// Elastic constants of element e for a direction choice, before any secant scaling.
  [[nodiscard]] ElasticConstants constants(std::size_t e, DirectionChoice choice) const;

  const Model& model_;
  std::vector<double> temperature_;  // per solid element: mean of its nodes
  bool nonlinear_ = false;
};

}  // namespace saasgaps
