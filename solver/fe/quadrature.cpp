#include "solver/fe/quadrature.hpp"

#include <array>
#include <cassert>
#include <cmath>

namespace saasgaps {

namespace {

const std::array<std::array<LinePoint, 4>, 4> line_rules = [] {
  std::array<std::array<LinePoint, 4>, 4> r{};
  r[0][0] = {0.0, 2.0};
  const double a = 1.0 / std::sqrt(3.0);
  r[1][0] = {-a, 1.0};
  r[1][1] = {a, 1.0};
  const double b = std::sqrt(0.6);
  r[2][0] = {-b, 5.0 / 9.0};
  r[2][1] = {0.0, 8.0 / 9.0};
  r[2][2] = {b, 5.0 / 9.0};
  // n = 4: +-sqrt(3/7 -+ 2/7 sqrt(6/5)), weights (18 +- sqrt(30)) / 36.
  const double inner = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
  const double outer = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
  const double w_inner = (18.0 + std::sqrt(30.0)) / 36.0;
  const double w_outer = (18.0 - std::sqrt(30.0)) / 36.0;
  r[3][0] = {-outer, w_outer};
  r[3][1] = {-inner, w_inner};
  r[3][2] = {inner, w_inner};
  r[3][3] = {outer, w_outer};
  return r;
}();

const std::array<std::array<ReferencePoint, 9>, 3> square_rules = [] {
  std::array<std::array<ReferencePoint, 9>, 3> r{};
  for (int n = 1; n <= 3; ++n) {
    const auto line = std::span(line_rules[static_cast<std::size_t>(n - 1)]).first(static_cast<std::size_t>(n));
    int k = 0;
    for (const LinePoint& eta : line) {
      for (const LinePoint& xi : line) r[static_cast<std::size_t>(n - 1)][static_cast<std::size_t>(k++)] = {xi.s, eta.s, xi.weight * eta.weight};
    }
  }
  return r;
}();

constexpr std::array<ReferencePoint, 1> triangle_1{{{1.0 / 3.0, 1.0 / 3.0, 0.5}}};
constexpr std::array<ReferencePoint, 3> triangle_3{{{1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0},
                                                    {2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0},
                                                    {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0}}};
// Strang and Fix (1973), degree 4: two orbits of three points.
constexpr double a6 = 0.445948490915965, wa6 = 0.223381589678011 / 2.0;
constexpr double b6 = 0.091576213509771, wb6 = 0.109951743655322 / 2.0;
constexpr std::array<ReferencePoint, 6> triangle_6{{{a6, a6, wa6},
                                                    {1.0 - 2.0 * a6, a6, wa6},
                                                    {a6, 1.0 - 2.0 * a6, wa6},
                                                    {b6, b6, wb6},
                                                    {1.0 - 2.0 * b6, b6, wb6},
                                                    {b6, 1.0 - 2.0 * b6, wb6}}};

}  // namespace

std::span<const LinePoint> gauss_line(int n) {
  assert(n >= 1 && n <= 4);
  return std::span(line_rules[static_cast<std::size_t>(n - 1)]).first(static_cast<std::size_t>(n));
}

std::span<const ReferencePoint> gauss_square(int n) {
  assert(n >= 1 && n <= 3);
  return std::span(square_rules[static_cast<std::size_t>(n - 1)]).first(static_cast<std::size_t>(n * n));
}

std::span<const ReferencePoint> gauss_triangle(int points) {
  switch (points) {
    case 1: return triangle_1;
    case 3: return triangle_3;
    case 6: return triangle_6;
    default: assert(false && "triangle rules have 1, 3 or 6 points"); return triangle_1;
  }
}

}  // namespace saasgaps
