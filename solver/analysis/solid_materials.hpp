#pragma once
/// The nonlinear material iteration of SAAS III: each solid element's stiffness is built from the
/// previous solution (strain invariance), through
///  - a secant modulus on the bilinear effective stress-strain curve (plasticity), and
///  - the tension or compression table per material direction, by the sign of its stress (bimodulus);
///    a direction whose stress is below the plastic tolerance of the element's largest keeps its table.
/// Across the increments of a stepped run, yielded elements unload elastically (plastic_history.hpp).
///
/// The state lives at material points (fe/material_points.hpp): the report's elements have one, at
/// their centre, read at the mean temperature of their nodes; the other families one per
/// integration point, read at the temperature their shape functions interpolate there.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/fe/element_kernel.hpp"
#include "solver/fe/material_points.hpp"
#include "solver/materials/material.hpp"
#include "solver/materials/material_state.hpp"
#include "solver/materials/plastic_history.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Per-point verdicts on one solution, and the state for the next iteration.
struct MaterialUpdate {
  MaterialState next;
  std::vector<bool> yielded;    ///< per material point, YIELD?: effective stress above the yield stress
  std::vector<bool> converged;  ///< per material point, N-L/CONV?: the secant modulus no longer changes
  int yielded_count = 0;        ///< elements with a yielded point
  int nonconverged_count = 0;   ///< elements with a point not converged
  int bimodulus_changes = 0;    ///< elements whose choice changed (only stressed directions change)
};

class SolidMaterials {
 public:
  explicit SolidMaterials(const Model& model);

  /// Every element elastic and in tension: the state of iteration 1.
  [[nodiscard]] MaterialState initial() const;

  /// The law of solid element e's first material point (the report's elements: its only one)
  /// under state s (on the unloading branch: with its plastic strain).
  [[nodiscard]] Constitutive law(std::size_t e, const MaterialState& s) const;
  /// The law at material point `point` of element e.
  [[nodiscard]] Constitutive law(std::size_t e, int point, const MaterialState& s) const;

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
  /// The laws of every material point of element e into out (at least max_material_points long);
  /// returns the leading count(e) of them.
  std::span<const Constitutive> laws(std::size_t e, const MaterialState& s, LawMemo& memo,
                                     std::span<Constitutive> out) const;

  [[nodiscard]] const MaterialPoints& points() const { return points_; }

  /// Strain invariance: from the element stresses of a solution built with `used`, read the secant
  /// modulus off the bilinear curve at the same effective strain, and the bimodulus choice from
  /// the stress signs. tolerance: relative change of E_s that still counts as converged. Writes into
  /// `out`, whose buffers are reused from one iteration to the next.
  /// `states`: one per material point.
  void update(const MaterialState& used, std::span<const ElementState> states, double tolerance,
              MaterialUpdate& out) const;

  /// At the end of a converged increment solved with `used` (states: its solution): every element on
  /// the loading branch past its peak (yielded: secant ratio below 1) records its new peak in
  /// `next`, the state the next increment starts from (plastic_history.hpp).
  void record_peaks(const MaterialState& used, std::span<const ElementState> states, MaterialState& next) const;

  /// True when some material is plastic or bimodulus (the iteration can change stiffness).
  [[nodiscard]] bool nonlinear() const { return nonlinear_; }

 private:
  /// Elastic constants at material point p of element e for a direction choice, before any secant scaling.
  [[nodiscard]] ElasticConstants constants(std::size_t e, std::size_t p, DirectionChoice choice) const;
  [[nodiscard]] Constitutive point_law(std::size_t e, std::size_t p, const MaterialState& s) const;
  [[nodiscard]] const Constitutive& point_law(std::size_t e, std::size_t p, const MaterialState& s,
                                              LawMemo& memo) const;

  const Model& model_;
  MaterialPoints points_;
  std::vector<double> temperature_;  // per material point
  bool nonlinear_ = false;
};

}  // namespace saasgaps
