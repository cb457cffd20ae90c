#pragma once
/// Hertz line contact, plane strain (Johnson, Contact Mechanics, 4.3): two bodies whose initial gap is
/// g(x) = x^2 / (2 R), pressed together by P per unit length, touch over |x| < a with
///   p(x) = p0 sqrt(1 - x^2 / a^2),  p0 = sqrt(P E* / (pi R)),  a = sqrt(4 P R / (pi E*)),
///   1 / E* = (1 - nu1^2) / E1 + (1 - nu2^2) / E2.
/// The contact tests' setting: both bodies of one material, the load chosen for a = 0.2 on R = 10,
/// bodies 20 a across (large against a).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace saasgaps::testing {

constexpr double hertz_E = 1.0e7, hertz_nu = 0.3, hertz_R = 10.0, hertz_a = 0.2, hertz_size = 20.0 * hertz_a;
inline const double hertz_E_star = hertz_E / (2.0 * (1.0 - hertz_nu * hertz_nu));
inline const double hertz_P = hertz_a * hertz_a * std::numbers::pi * hertz_E_star / (4.0 * hertz_R);  // full model
inline const double hertz_p0 = std::sqrt(hertz_P * hertz_E_star / (std::numbers::pi * hertz_R));

/// Node coordinates 0..hertz_size: uniform steps h up to 1.6 a, then growing by 15 % per element.
inline std::vector<double> hertz_graded(double h) {
  std::vector<double> x{0.0};
  while (x.back() < 1.6 * hertz_a - 1e-12) x.push_back(x.back() + h);
  double step = h;
  while (x.back() + step < hertz_size) {
    step *= 1.15;
    x.push_back(std::min(x.back() + step, hertz_size));
  }
  if (hertz_size - x.back() < 0.5 * step) {
    x.back() = hertz_size;
  } else {
    x.push_back(hertz_size);
  }
  return x;
}

/// Both sides of x = 0 from one side's coordinates 0, x_1, ..., x_k: -x_k, ..., -x_1, 0, x_1, ..., x_k.
inline std::vector<double> hertz_mirrored(const std::vector<double>& half) {
  std::vector<double> x;
  for (std::size_t k = half.size() - 1; k > 0; --k) x.push_back(-half[k]);
  x.insert(x.end(), half.begin(), half.end());
  return x;
}

}  // namespace saasgaps::testing
