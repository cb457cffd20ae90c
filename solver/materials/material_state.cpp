#include "solver/materials/material_state.hpp"

#include <cmath>
#include <numbers>

namespace saasgaps {

Vec4 stress_in_material_axes(const Vec4& s, double angle_deg) {
  const double t = angle_deg * std::numbers::pi / 180.0;
  const double c = std::cos(t);
  const double n = std::sin(t);
  return Vec4(c * c * s[rr] + n * n * s[zz] + 2.0 * c * n * s[rz],
              n * n * s[rr] + c * c * s[zz] - 2.0 * c * n * s[rz],
              -c * n * s[rr] + c * n * s[zz] + (c * c - n * n) * s[rz], s[th]);
}

double reference_modulus(const ElasticConstants& c, bool isotropic) {
  return isotropic ? c.E1 : (c.E1 + c.E2 + c.E3) / 3.0;
}

bool operator==(const MaterialState& a, const MaterialState& b) {
  if (a.secant_ratio != b.secant_ratio || a.compression != b.compression || a.peaks != b.peaks) return false;
  if (a.unloading.size() == b.unloading.size()) return a.unloading == b.unloading;
  const std::size_t n = std::max(a.unloading.size(), b.unloading.size());
  for (std::size_t e = 0; e < n; ++e) {
    if (a.unloads(e) != b.unloads(e)) return false;
  }
  return true;
}

}  // namespace saasgaps
