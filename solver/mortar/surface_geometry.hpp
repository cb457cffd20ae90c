#pragma once
/// A contact surface's geometry, computed once per surface from its chain (contact_surface.hpp) and
/// the nodes' reference positions: the normal at each node, which nodes are corners, and the smooth
/// curve through the nodes that initial gaps are measured to. docs/contact-surfaces.md, sections 1
/// and 2.

#include <array>
#include <cstddef>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"
#include "solver/mortar/contact_surface.hpp"

namespace saasgaps {

/// Unit normal at each node of the chain (same order as surface.nodes): the adjacent segments'
/// normals weighted by the inverse of their lengths,
///   n_j = normalize(n_{s-1} / L_{s-1} + n_s / L_s)    (an open chain's end nodes: their one segment's),
/// which for nodes on a circle is exactly radial however unequal the two chords are (chord s of angle
/// a_s has its normal at its mid angle and L_s = 2 R sin(a_s / 2): the tangential parts
/// sin(a_s / 2) / L_s cancel; equal weights would tilt it by about (L_s - L_{s-1}) / 4R). At a
/// corner it lies between the two faces' normals, nearer the shorter segment's.
std::vector<Vec2> nodal_normals(const ContactSurface& surface, const std::vector<Node>& nodes);

/// Per node of the chain: whether it is a corner, not a sample of a smooth curve. A node where the
/// chain turns by at least 60 degrees is one; so is one turning by more than 30 degrees when that is
/// more than 1.5 times the turns at both neighbouring nodes (an open chain's ends are not). The
/// second rule keeps a coarse ring (12 segments turn by exactly 30 degrees at every node, which
/// round-off puts either side of any fixed threshold) smooth, and finds a corner where an arc meets
/// a flat.
std::vector<bool> corners(const ContactSurface& surface);

/// The quadratic curve of a 3-node edge, the element's own geometry: for s in [0, 1] (corner x0 at
/// s = 0, mid-side node xm at 1/2, corner x1 at 1)
///   X(s) = N_0(s) x0 + N_m(s) xm + N_1(s) x1,
///   N_0 = (1 - s)(1 - 2 s),  N_m = 4 s (1 - s),  N_1 = s (2 s - 1),
/// the shape functions the element interpolates its edge with. Half h of the edge (its segment
/// h of the chain) at its chord parameter xi is the curve at s = (h + xi) / 2.
struct QuadraticEdge {
  Vec2 x0 = Vec2::Zero(), xm = Vec2::Zero(), x1 = Vec2::Zero();
  /// (N_0, N_m, N_1) at s.
  [[nodiscard]] static std::array<double, 3> shape(double s) {
    return {(1.0 - s) * (1.0 - 2.0 * s), 4.0 * s * (1.0 - s), s * (2.0 * s - 1.0)};
  }
  [[nodiscard]] Vec2 position(double s) const {
    const auto N = shape(s);
    return N[0] * x0 + N[1] * xm + N[2] * x1;
  }
  /// dX/ds.
  [[nodiscard]] Vec2 tangent(double s) const {
    return (4.0 * s - 3.0) * x0 + (4.0 - 8.0 * s) * xm + (4.0 * s - 1.0) * x1;
  }
};

/// A surface's nodal normals and the smooth curve through its nodes. On segment y1 -> y2 (length L,
/// unit tangent tau, outward chord normal nu) the curve is y1 + eta (y2 - y1) + w(eta) nu, with the
/// offset whose normals at the ends are (to first order) the nodal normals, turned by beta_1, beta_2
/// from nu (the curve's normal is nu - w'(s) tau, so w'(0) = -tan beta_1, w'(L) = -tan beta_2): a
/// circular arc of half-angle (beta_2 - beta_1) / 2 plus a cubic for the rest (offset()). On a circle
/// of radius R and chord angle a the nodal normals are radial, beta = -+a / 2, and the curve is the
/// circle itself: an interference of 1e-4 R is then measured exactly, where a cubic's O(R a^4) error
/// would be a few per cent of it. At a corner (corners()) the curve keeps the segment's direction
/// (beta = 0). An open chain's end segments are arcs. The halves of 3-node edges (ContactSurface::half)
/// are segments like the others here: the nodes, mid-side ones included, sample the part's shape, and
/// an initial gap is measured to the arcs through them, which a circle's nodes give exactly; the
/// quadratic curve through three nodes of a circle departs from it by about R a^4 / 500 (edge angle a),
/// 0.17 % of a 1e-4 R interference at 16 edges on a quarter circle, which would show as +-8 % waves in
/// the pressure (docs/contact-surfaces.md, section 7). The mortar integrals use the quadratic curve.
///
/// Keeps references to the nodes and the surface: both must outlive it.
class SurfaceGeometry {
 public:
  SurfaceGeometry(const std::vector<Node>& nodes, const ContactSurface& surface);

  [[nodiscard]] const std::vector<Node>& nodes() const { return *nodes_; }
  /// The chain: its nodes, segments and segment normals.
  [[nodiscard]] const ContactSurface& surface() const { return *surface_; }
  /// Per node of the chain: n_j (nodal_normals()).
  [[nodiscard]] const std::vector<Vec2>& nodal_normals() const { return nodal_; }

  /// The 3-node edge segment s is a half of (ContactSurface::half(s) >= 0).
  [[nodiscard]] QuadraticEdge quadratic_edge(std::size_t s) const;
  /// w(eta) on segment s (length L): the curve's offset from the chord along its outward normal.
  [[nodiscard]] double offset(std::size_t s, double eta, double length) const;
  /// A bound on |w| over every segment: a segment's curve lies within its chord's box inflated by it.
  [[nodiscard]] double bend() const { return bend_; }
  /// The mean segment length.
  [[nodiscard]] double mean_length() const { return length_; }

 private:
  const std::vector<Node>* nodes_;
  const ContactSurface* surface_;
  std::vector<Vec2> nodal_;
  std::vector<std::array<double, 2>> tan_beta_;  ///< per segment: tan beta at its two ends
  double bend_ = 0.0;    ///< bound on |w| over every segment
  double length_ = 0.0;  ///< mean segment length
};

}  // namespace saasgaps
