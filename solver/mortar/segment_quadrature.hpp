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

/// 6-point Gauss-Legendre on [-1, 1]: exact to degree 11. On half of a 3-node edge the integrands are
/// psi (linear in the half's parameter) x a quadratic shape function of A or of B x w (linear in r)
/// x the curve's Jacobian |X'(s)|: degree 5 where both edges are straight with their mid-side nodes
/// half-way. A mid-side node off the middle (a graded mesh) makes B's parameter a non-polynomial
/// function of A's (the inverse of a quadratic map) and |X'| varies: 4 points left 1e-7 of p in the
/// quad8 patch test, 6 leave round-off (docs/contact-surfaces.md, section 7).
struct CurvedGauss {
  static constexpr std::array<double, 6> point{-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                               0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
  static constexpr std::array<double, 6> weight{0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                                0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
};

/// Calls f(xi, weight) at the Gauss points of [lo, hi] on segment x1 -> x2; weight includes ds and w(r):
///   weight_g = gauss_g (hi - lo) / 2 |x2 - x1| w(r(xi_g)),   xi_g = lo + (hi - lo) (1 + point_g) / 2.
/// Rule: SegmentGauss, or CurvedGauss where the piece faces a half of a 3-node edge.
template <class Rule = SegmentGauss, class F>
void integrate(const Vec2& x1, const Vec2& x2, const ParameterInterval& piece, const SurfaceMeasure& measure, F&& f) {
  const double length = (x2 - x1).norm();
  const double half = 0.5 * (piece.hi - piece.lo);
  for (std::size_t g = 0; g < Rule::point.size(); ++g) {
    const double xi = piece.lo + half * (1.0 + Rule::point[g]);
    const double r = (1.0 - xi) * x1.x() + xi * x2.x();
    f(xi, Rule::weight[g] * half * length * measure.weight(r));
  }
}

/// Calls f(xi, weight) at the Gauss points of [lo, hi] of half h of the 3-node edge whose curve is
/// position(s) with ds-derivative tangent(s) (QuadraticEdge, surface_geometry.hpp), xi being the half's
/// parameter (s = (h + xi) / 2); weight includes the curve's length element and w(r) at the curve:
///   weight_g = gauss_g (hi - lo) / 2 |X'(s_g)| / 2 w(r(X(s_g))).
template <class Curve, class F>
void integrate_curved(const Curve& curve, int h, const ParameterInterval& piece, const SurfaceMeasure& measure,
                      F&& f) {
  const double half = 0.5 * (piece.hi - piece.lo);
  for (std::size_t g = 0; g < CurvedGauss::point.size(); ++g) {
    const double xi = piece.lo + half * (1.0 + CurvedGauss::point[g]);
    const double s = 0.5 * (h + xi);
    const double r = curve.position(s).x();
    f(xi, CurvedGauss::weight[g] * half * 0.5 * curve.tangent(s).norm() * measure.weight(r));
  }
}

}  // namespace saasgaps
