#pragma once
/// The quadrature on the segments of a contact surface (docs/contact-surfaces.md, section 2,
/// "Quadrature"): the measure of the analysis, pieces of a segment's parameter range, and 3-point
/// Gauss-Legendre on a piece. A segment x_1 -> x_2 is x(xi) = (1 - xi) x_1 + xi x_2, 0 <= xi <= 1.

#include <array>
#include <cstddef>
#include <numbers>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// The measure of a surface: dA = w(r) ds, w = thickness (plane) or 2 pi r (axisymmetric, full ring).
struct SurfaceMeasure {
  AnalysisType analysis = AnalysisType::plane_stress;
  double thickness = 1.0;
  // Inline, so that integrate()'s loop is compiled with it: called out of line it changes how GCC
  // vectorizes and contracts that loop, and the last digits of axisymmetric integrals.
  [[nodiscard]] double weight(double r) const {
    return analysis == AnalysisType::axisymmetric ? 2.0 * std::numbers::pi * r : thickness;
  }
};

/// A piece [lo, hi] of a segment's parameter range [0, 1].
struct ParameterInterval {
  double lo = 0.0;
  double hi = 1.0;
};

/// 3-point Gauss-Legendre on [-1, 1]: exact to degree 5. On a straight overlap the integrands are
/// psi N^B w: linear x linear x linear (w = 2 pi r) = cubic, so 2 points would do; the third keeps
/// curved sides (where N^B(eta(xi)) is only close to linear) accurate too.
struct SegmentGauss {
  static constexpr std::array<double, 3> point{-0.7745966692414834, 0.0, 0.7745966692414834};
  static constexpr std::array<double, 3> weight{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
};

/// Calls f(xi, weight) at the Gauss points of [lo, hi] on segment x1 -> x2; weight includes ds and w(r):
///   weight_g = gauss_g (hi - lo) / 2 |x2 - x1| w(r(xi_g)),   xi_g = lo + (hi - lo) (1 + point_g) / 2.
template <class F>
void integrate(const Vec2& x1, const Vec2& x2, const ParameterInterval& piece, const SurfaceMeasure& measure, F&& f) {
  const double length = (x2 - x1).norm();
  const double half = 0.5 * (piece.hi - piece.lo);
  for (std::size_t g = 0; g < SegmentGauss::point.size(); ++g) {
    const double xi = piece.lo + half * (1.0 + SegmentGauss::point[g]);
    const double r = (1.0 - xi) * x1.x() + xi * x2.x();
    f(xi, SegmentGauss::weight[g] * half * length * measure.weight(r));
  }
}

}  // namespace saasgaps
