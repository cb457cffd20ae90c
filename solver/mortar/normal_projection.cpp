#include "solver/mortar/normal_projection.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace saasgaps {

namespace {
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

Vec2 normal_at(const Vec2& n1, const Vec2& n2, double xi) { return ((1.0 - xi) * n1 + xi * n2).normalized(); }

std::optional<double> project_onto_segment(const Vec2& x1, const Vec2& x2, const Vec2& n1, const Vec2& n2,
                                           const Vec2& y) {
  const Vec2 d = x2 - x1;
  const Vec2 dn = n2 - n1;
  const Vec2 e = x1 - y;
  const double c0 = cross(e, n1);
  const double c1 = cross(e, dn) + cross(d, n1);
  const double c2 = cross(d, dn);
  std::array<double, 2> roots{};
  std::size_t count = 0;
  if (c2 == 0.0) {
    if (c1 == 0.0) return std::nullopt;
    roots[count++] = -c0 / c1;
  } else {
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) return std::nullopt;
    // The cancellation-free pair of roots: q / c2 and c0 / q.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    roots[count++] = q / c2;
    if (q != 0.0) roots[count++] = c0 / q;
  }
  const auto outside = [](double xi) { return std::max({0.0, -xi, xi - 1.0}); };
  double best = roots[0];
  for (std::size_t i = 1; i < count; ++i) {
    if (outside(roots[i]) < outside(best)) best = roots[i];
  }
  return best;
}

double project_onto_curve(const QuadraticEdge& curve, int h, const Vec2& n1, const Vec2& n2, const Vec2& y,
                          double start) {
  // F(xi) = (X(s) - y) x n(xi), s = (h + xi) / 2; F' = X'(s) / 2 x n + (X(s) - y) x (n2 - n1).
  double xi = start;
  for (int pass = 0; pass < 30; ++pass) {
    const double s = 0.5 * (h + xi);
    const Vec2 n = (1.0 - xi) * n1 + xi * n2;
    const Vec2 e = curve.position(s) - y;
    const double f = cross(e, n);
    const double df = cross(0.5 * curve.tangent(s), n) + cross(e, n2 - n1);
    if (df == 0.0) break;
    const double step = f / df;
    xi -= step;
    if (std::abs(step) <= 1e-15) break;
  }
  return xi;
}

std::pair<double, double> meet_curve(const Vec2& x, const Vec2& n, const QuadraticEdge& curve, int h, double start) {
  // G(eta) = (X(s) - x) x n, s = (h + eta) / 2; G' = X'(s) / 2 x n.
  double eta = start;
  for (int pass = 0; pass < 30; ++pass) {
    const double s = 0.5 * (h + eta);
    const double df = cross(0.5 * curve.tangent(s), n);
    if (df == 0.0) break;
    const double step = cross(curve.position(s) - x, n) / df;
    eta -= step;
    if (std::abs(step) <= 1e-15) break;
  }
  return {eta, n.dot(curve.position(0.5 * (h + eta)) - x) / n.squaredNorm()};
}

std::optional<std::pair<double, double>> meet(const Vec2& x, const Vec2& n, const Vec2& b1, const Vec2& b2) {
  // x + t n = b1 + eta e  <=>  t n - eta e = b1 - x; Cramer's rule on [n, -e].
  const Vec2 e = b2 - b1;
  const Vec2 rhs = b1 - x;
  const double det = cross(n, -e);
  if (det == 0.0) return std::nullopt;
  const double t = cross(rhs, -e) / det;
  const double eta = cross(n, rhs) / det;
  return std::make_pair(eta, t);
}

std::optional<double> distance_to_curve(const SurfaceGeometry& surface, const Vec2& x, const Vec2& n,
                                        std::span<const std::size_t> near) {
  const ContactSurface& chain = surface.surface();
  std::optional<double> best;
  for (const std::size_t s : near) {
    const Vec2& nu = chain.normal[s];
    if (n.dot(nu) >= 0.0) continue;
    const auto [a, b] = chain.segment(s);
    const Vec2 y1 = node_position(surface.nodes(), a);
    const Vec2 y2 = node_position(surface.nodes(), b);
    const double length = (y2 - y1).norm();
    const Vec2 tau = (y2 - y1) / length;
    // Fixed point: the line meets the chord offset by w(eta) at t; each pass shrinks the change in t
    // by about the chord's angle, so a few passes reach round-off (the interference of a press fit
    // can be 1e-4 of the radius, a sag's 1e-2: t must be exact to far better than a sag).
    double eta = 0.0;
    double t = (0.0 - nu.dot(x - y1)) / nu.dot(n);
    for (int pass = 0; pass < 60; ++pass) {
      // Beyond its ends a segment's curve is not defined (nor needed): hold eta in [0, 1].
      eta = std::clamp(tau.dot(x + t * n - y1) / length, 0.0, 1.0);
      const double next = (surface.offset(s, eta, length) - nu.dot(x - y1)) / nu.dot(n);
      const bool settled = std::abs(next - t) <= 1e-15 * (std::abs(t) + length);
      t = next;
      if (settled) break;
    }
    eta = tau.dot(x + t * n - y1) / length;
    if (!std::isfinite(t) || !(eta >= -parameter_round_off && eta <= 1.0 + parameter_round_off)) continue;
    if (!best || std::abs(t) < std::abs(*best)) best = t;
  }
  return best;
}

}  // namespace saasgaps
