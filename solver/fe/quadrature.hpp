#pragma once
/// Gauss rules on the reference cells (element_family.hpp): the line [-1, 1], the triangle
/// (0,0)-(1,0)-(0,1) and the square [-1, 1]^2. Weights sum to the cell's measure (2, 1/2, 4).
///
///   line n = 2: +-1/sqrt(3), weights 1;  n = 3: 0 (8/9), +-sqrt(3/5) (5/9)
///   triangle 1 point: centroid, 1/2;  3 points: (1/6, 1/6), (2/3, 1/6), (1/6, 2/3), 1/6 each
///     (degree 2);  6 points: Strang and Fix's degree-4 rule
///   square n x n: the product of the line rule, xi running fastest

#include <span>

#include "solver/fe/element_family.hpp"

namespace saasgaps {

/// A point on the reference line and its weight.
struct LinePoint {
  double s = 0.0;
  double weight = 0.0;
};

/// Gauss-Legendre on [-1, 1] with n = 1..4 points (exact for polynomials of degree 2n - 1).
std::span<const LinePoint> gauss_line(int n);

/// The square's n x n product rule, n = 1..3 (points ordered with xi fastest).
std::span<const ReferencePoint> gauss_square(int n);

/// The triangle's rules with 1, 3 or 6 points (degrees 1, 2 and 4).
std::span<const ReferencePoint> gauss_triangle(int points);

}  // namespace saasgaps
