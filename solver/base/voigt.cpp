#include "solver/base/voigt.hpp"

#include <cmath>
#include <numbers>

namespace saasgaps {

Principal principal_in_plane(const Vec4& s) {
  const double mean = 0.5 * (s[rr] + s[zz]);
  const double half_diff = 0.5 * (s[rr] - s[zz]);
  const double radius = std::hypot(half_diff, s[rz]);
  Principal p;
  p.s1 = mean + radius;
  p.s2 = mean - radius;
  p.angle_deg = 0.5 * std::atan2(2.0 * s[rz], s[rr] - s[zz]) * 180.0 / std::numbers::pi;
  if (p.angle_deg <= -90.0) p.angle_deg += 180.0;
  return p;
}

double von_mises(const Vec4& s) {
  const double a = s[rr] - s[zz];
  const double b = s[zz] - s[th];
  const double c = s[th] - s[rr];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * s[rz] * s[rz]);
}

double normal_component(const Vec4& v, double angle_deg, double shear_factor) {
  const double t = angle_deg * std::numbers::pi / 180.0;
  const double c = std::cos(t);
  const double s = std::sin(t);
  return c * c * v[rr] + s * s * v[zz] + shear_factor * c * s * v[rz];
}

}  // namespace saasgaps
