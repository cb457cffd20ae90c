#pragma once
/// The state of the solid materials between iterations, as plain data (what a restart state carries):
/// the secant ratio, bimodulus choice and plastic history of each solid element. The iteration that
/// updates it is analysis/solid_materials.hpp.

#include <cstdint>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/materials/material.hpp"
#include "solver/materials/plastic_history.hpp"

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

/// Stress in material axes (1, 2, 12, 3) of a global stress (rr, zz, rz, th), axis 1 at angle_deg.
Vec4 stress_in_material_axes(const Vec4& stress, double angle_deg);

/// E of the bilinear curve for an element's constants: E itself when isotropic, the mean of
/// E1, E2, E3 when orthotropic.
double reference_modulus(const ElasticConstants& c, bool isotropic);

}  // namespace saasgaps
