#include "solver/mortar/surface_geometry.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace saasgaps {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// The corner rule's turns (corners()): at least sharp_corner_angle, or more than corner_angle and
/// more than corner_contrast times the neighbours' turns.
constexpr double corner_angle = 30.0 * std::numbers::pi / 180.0;
constexpr double sharp_corner_angle = 60.0 * std::numbers::pi / 180.0;
constexpr double corner_contrast = 1.5;

}  // namespace

std::vector<Vec2> nodal_normals(const ContactSurface& surface, const std::vector<Node>& nodes) {
  const std::size_t n = surface.nodes.size();
  const std::size_t segments = surface.segment_count();
  std::vector<Vec2> sum(n, Vec2::Zero());
  for (std::size_t s = 0; s < segments; ++s) {
    const auto [a, b] = surface.segment(s);
    const double length = (node_position(nodes, b) - node_position(nodes, a)).norm();
    assert(length > 0.0);
    // 1 / L weights: on a circle the two chord normals' tangential parts cancel exactly.
    const Vec2 w = surface.normal[s] / length;
    sum[s] += w;
    sum[(s + 1) % n] += w;
  }
  for (Vec2& v : sum) v.normalize();
  // An open chain ending in a half of a 3-node edge: the end node's normal is its neighbour's
  // reflected in the half's chord normal, as an arc through the two nodes would have it (radial at
  // the end of a circular arc: a quarter ring's end on its plane of symmetry). The chord's own normal
  // there, a quarter of the edge's angle off, made the end rows' gaps and weights disagree by 4e-4
  // and the pressure wave 16 % at the end of a quad8 quarter ring fit. Straight edges keep the
  // chord's normal, as before.
  if (!surface.closed && segments > 1) {
    for (const auto& [end, inner, s] : {std::array<std::size_t, 3>{0, 1, 0}, {n - 1, n - 2, segments - 1}}) {
      const Vec2& nu = surface.normal[s];
      if (surface.half(s) < 0 || sum[inner].dot(nu) < std::cos(corner_angle)) continue;
      sum[end] = (2.0 * sum[inner].dot(nu) * nu - sum[inner]).normalized();
    }
  }
  return sum;
}

std::vector<bool> corners(const ContactSurface& surface) {
  const std::size_t n = surface.nodes.size();
  const std::size_t segments = surface.segment_count();
  std::vector<double> turn(n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const bool inner = surface.closed || (j > 0 && j + 1 < n);
    if (!inner) continue;
    const std::size_t before = (j + segments - 1) % segments;
    const std::size_t after = j % segments;
    turn[j] = std::acos(std::clamp(surface.normal[before].dot(surface.normal[after]), -1.0, 1.0));
  }
  std::vector<bool> corner(n, false);
  for (std::size_t j = 0; j < n; ++j) {
    const double left = surface.closed || j > 0 ? turn[(j + n - 1) % n] : 0.0;
    const double right = surface.closed || j + 1 < n ? turn[(j + 1) % n] : 0.0;
    // A mid-side node is inside its edge's smooth curve, never a corner.
    corner[j] = !surface.mid_side(j) &&
                (turn[j] >= sharp_corner_angle ||
                 (turn[j] > corner_angle && turn[j] > corner_contrast * std::max(left, right)));
  }
  return corner;
}

SurfaceGeometry::SurfaceGeometry(const std::vector<Node>& nodes, const ContactSurface& surface)
    : nodes_(&nodes), surface_(&surface), nodal_(saasgaps::nodal_normals(surface, nodes)) {
  const std::vector<bool> corner = corners(surface);
  const std::size_t n = surface.nodes.size();
  tan_beta_.assign(surface.segment_count(), {0.0, 0.0});
  for (std::size_t s = 0; s < surface.segment_count(); ++s) {
    const Vec2& nu = surface.normal[s];
    for (std::size_t end = 0; end < 2; ++end) {
      const std::size_t j = (s + end) % n;
      // The other segment at node j (none at an open chain's ends).
      const bool has_other = surface.closed || (end == 0 ? s > 0 : s + 1 < surface.segment_count());
      if (!has_other || corner[j]) continue;
      tan_beta_[s][end] = cross(nu, nodal_[j]) / nu.dot(nodal_[j]);
    }
  }
  // An open chain's end segment continues the curvature of its inner end (a circular arc:
  // beta_1 = -beta_2), unless the chain has one segment.
  if (!surface.closed && surface.segment_count() > 1) {
    tan_beta_.front()[0] = -tan_beta_.front()[1];
    tan_beta_.back()[1] = -tan_beta_.back()[0];
  }
  for (std::size_t s = 0; s < surface.segment_count(); ++s) {
    const auto [a, b] = surface.segment(s);
    const double length = (node_position(nodes, b) - node_position(nodes, a)).norm();
    // |w| <= L (|tan beta_1| + |tan beta_2|) / 4 (arc and cubic together), doubled for safety.
    bend_ = std::max(bend_, 0.5 * length * (std::abs(tan_beta_[s][0]) + std::abs(tan_beta_[s][1])));
    length_ += length / static_cast<double>(surface.segment_count());
  }
}

QuadraticEdge SurfaceGeometry::quadratic_edge(std::size_t s) const {
  const auto at = surface_->edge_positions(s);
  const auto x = [&](std::size_t j) { return node_position(*nodes_, surface_->nodes[j]); };
  return {x(at[0]), x(at[1]), x(at[2])};
}

double SurfaceGeometry::offset(std::size_t s, double eta, double length) const {
  const auto& tb = tan_beta_[s];
  // The circular arc of half-angle theta = (beta_2 - beta_1) / 2 (exact on a circle, where the
  // nodal normals are symmetric about the chord's), in the cancellation-free form
  //   w = 2 L sin(theta) eta (1 - eta) / (sqrt(1 - (2 eta - 1)^2 sin^2(theta)) + cos(theta)),
  // plus the cubic of the antisymmetric part mu = (beta_1 + beta_2) / 2 (a curvature that changes
  // along the segment): L eta (1 - eta) (2 eta - 1) tan(mu).
  const double beta1 = std::atan(tb[0]), beta2 = std::atan(tb[1]);
  const double theta = 0.5 * (beta2 - beta1), mu = 0.5 * (beta1 + beta2);
  const double sine = std::sin(theta), c = 2.0 * eta - 1.0;
  const double arc = 2.0 * length * sine * eta * (1.0 - eta) / (std::sqrt(1.0 - c * c * sine * sine) + std::cos(theta));
  return arc + length * eta * (1.0 - eta) * c * std::tan(mu);
}

}  // namespace saasgaps
