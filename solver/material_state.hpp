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

#include "element_kernel.hpp"
#include "material.hpp"
#include "model.hpp"
#include "plastic_history.hpp"

namespace saasgaps {

/// What one iteration's solid stiffness was built with.
struct MaterialState {
  std::vector<double> secant_ratio;           ///< E_s / E per solid element (1 = elastic)
  std::vector<DirectionChoice> compression;   ///< bimodulus choice per solid element
  /// Stepped runs: the peak of each solid element at the end of the increments before this one
  /// (empty until an element has yielded at an increment's end; then one per solid element).
  std::vector<PlasticPeak> peaks;
  /// Per solid element, 1: on the unloading branch (elastic, with its peak's plastic strain as an
  /// initial strain, secant_ratio 1). Empty while no element has unloaded.
  std::vector<std::uint8_t> unloading;

  [[nodiscard]] bool unloads(std::size_t e) const { return !unloading.empty() && unloading[e] != 0; }
  /// The initial strain of element e: its peak's plastic strain on the unloading branch, else zero.
  [[nodiscard]] Vec4 initial_strain(std::size_t e) const {
    return unloads(e) ? peaks[e].plastic_strain : Vec4::Zero();
  }

  /// Equal laws: an empty `unloading` equals one of zeros (a decoded state lists only the ones).
  friend bool operator==(const MaterialState& a, const MaterialState& b);
};

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


/// Stress in material axes (1, 2, 12, 3) of a global stress (rr, zz, rz, th), axis 1 at angle_deg.
Vec4 stress_in_material_axes(const Vec4& stress, double angle_deg);

/// E of the bilinear curve for an element's constants: E itself when isotropic, the mean of
/// E1, E2, E3 when orthotropic.
double reference_modulus(const ElasticConstants& c, bool isotropic);

}  // namespace saasgaps
