#include "mortar_coupling.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

#include <Eigen/LU>

namespace saasgaps {

namespace {

/// 3-point Gauss-Legendre on [-1, 1]: exact to degree 5. On a straight overlap the integrands are
/// psi N^B w: linear x linear x linear (w = 2 pi r) = cubic, so 2 points would do; the third keeps
/// curved sides (where N^B(eta(xi)) is only close to linear) accurate too.
constexpr std::array<double, 3> gauss_point{-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr std::array<double, 3> gauss_weight{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

/// Pieces shorter than this (in a segment's parameter) are round-off slivers where nodes project onto
/// nodes.
constexpr double parameter_round_off = 1.0e-12;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 position(const std::vector<Node>& nodes, int i) {
  const Node& n = nodes[static_cast<std::size_t>(i)];
  return {n.r, n.z};
}

/// Calls f(xi, weight) at the Gauss points of [lo, hi] on segment x1 -> x2; weight includes ds and w(r).
template <class F>
void integrate(const Vec2& x1, const Vec2& x2, const ParameterInterval& piece, const SurfaceMeasure& measure, F&& f) {
  const double length = (x2 - x1).norm();
  const double half = 0.5 * (piece.hi - piece.lo);
  for (std::size_t g = 0; g < gauss_point.size(); ++g) {
    const double xi = piece.lo + half * (1.0 + gauss_point[g]);
    const double r = (1.0 - xi) * x1.x() + xi * x2.x();
    f(xi, gauss_weight[g] * half * length * measure.weight(r));
  }
}

/// The segment parameter xi at which the line from x(xi) = x1 + xi (x2 - x1) along the normal field
/// n(xi) = n1 + xi (n2 - n1) passes through y:  (x(xi) - y) x n(xi) = 0, a quadratic
/// c2 xi^2 + c1 xi + c0 = 0. Of its real roots, the one nearest [0, 1] (the other, on a nearly
/// straight side, lies where the normals of the two ends would cross, far outside).
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

/// Where the line x + t n meets the line b1 + eta (b2 - b1): (eta, t), or nothing when parallel.
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

Vec2 normal_at(const Vec2& n1, const Vec2& n2, double xi) { return ((1.0 - xi) * n1 + xi * n2).normalized(); }

/// A piece of a slave segment and the master segment facing it there.
struct Overlap {
  ParameterInterval piece;
  std::size_t master = 0;
};

/// The pieces of slave segment x1 -> x2 (nodal normals n1, n2, segment normal ns) that face the
/// master surface, each with the nearest facing master segment.
std::vector<Overlap> overlaps(const std::vector<Node>& nodes, const Vec2& x1, const Vec2& x2, const Vec2& n1,
                              const Vec2& n2, const Vec2& ns, const ContactSurface& master) {
  std::vector<Overlap> candidates;
  for (std::size_t m = 0; m < master.segment_count(); ++m) {
    if (ns.dot(master.normal[m]) >= 0.0) continue;  // not facing: the back of a closed surface
    const auto [b1, b2] = master.segment(m);
    const auto xa = project_onto_segment(x1, x2, n1, n2, position(nodes, b1));
    const auto xb = project_onto_segment(x1, x2, n1, n2, position(nodes, b2));
    if (!xa || !xb) continue;
    const double lo = std::max(0.0, std::min(*xa, *xb));
    const double hi = std::min(1.0, std::max(*xa, *xb));
    if (hi - lo > parameter_round_off) candidates.push_back({{lo, hi}, m});
  }
  if (candidates.empty()) return {};

  // Split at every candidate's ends; on each elementary piece keep the candidate nearest along n
  // (where two master segments project onto the same piece of A, e.g. a folded master side).
  std::vector<double> breaks{0.0, 1.0};
  for (const Overlap& c : candidates) {
    breaks.push_back(c.piece.lo);
    breaks.push_back(c.piece.hi);
  }
  std::sort(breaks.begin(), breaks.end());
  std::vector<Overlap> chosen;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = breaks[i];
    const double hi = breaks[i + 1];
    if (hi - lo <= parameter_round_off) continue;
    const double mid = 0.5 * (lo + hi);
    const Vec2 x = (1.0 - mid) * x1 + mid * x2;
    const Vec2 n = normal_at(n1, n2, mid);
    double nearest = std::numeric_limits<double>::infinity();
    std::optional<std::size_t> pick;
    for (const Overlap& c : candidates) {
      if (mid < c.piece.lo || mid > c.piece.hi) continue;
      const auto [b1, b2] = master.segment(c.master);
      const auto hit = meet(x, n, position(nodes, b1), position(nodes, b2));
      if (hit && std::abs(hit->second) < nearest) {
        nearest = std::abs(hit->second);
        pick = c.master;
      }
    }
    if (!pick) continue;
    if (!chosen.empty() && chosen.back().master == *pick && chosen.back().piece.hi == lo) {
      chosen.back().piece.hi = hi;  // the same master segment continues
    } else {
      chosen.push_back({{lo, hi}, *pick});
    }
  }
  return chosen;
}

/// Master nodes where the chain turns by more than this are corners, not samples of a smooth curve.
constexpr double corner_angle = 30.0 * std::numbers::pi / 180.0;

/// The master side as a smooth curve through its nodes: on segment y1 -> y2 (length L, unit tangent
/// tau, outward chord normal nu) the curve is y1 + eta (y2 - y1) + w(eta) nu with the cubic Hermite
/// offset whose normals at the ends are the nodal normals, turned by beta_1, beta_2 from nu:
///   w(eta) = L eta (1 - eta) (eta tan beta_2 - (1 - eta) tan beta_1)
/// (the curve's normal is nu - w'(s) tau, so w'(0) = -tan beta_1, w'(L) = -tan beta_2). On a circle
/// of radius R and chord angle a, beta = -+a / 2 and w(1/2) = L tan(a / 2) / 4 = R a^2 / 8: the sag,
/// with an error O(R a^4). A node where the chain turns by more than corner_angle is a corner: there
/// the curve keeps the segment's direction (beta = 0). An open chain's end segments are arcs.
class SmoothCurve {
 public:
  SmoothCurve(const std::vector<Node>& nodes, const ContactSurface& surface) : nodes_(nodes), surface_(surface) {
    const std::vector<Vec2> nodal = nodal_normals(surface, nodes);
    const std::size_t n = surface.nodes.size();
    tan_beta_.assign(surface.segment_count(), {0.0, 0.0});
    for (std::size_t s = 0; s < surface.segment_count(); ++s) {
      const Vec2& nu = surface.normal[s];
      for (std::size_t end = 0; end < 2; ++end) {
        const std::size_t j = (s + end) % n;
        // The other segment at node j (none at an open chain's ends).
        const bool has_other = surface.closed || (end == 0 ? s > 0 : s + 1 < surface.segment_count());
        if (!has_other) continue;
        const std::size_t other = end == 0 ? (s + surface.segment_count() - 1) % surface.segment_count()
                                           : (s + 1) % surface.segment_count();
        if (std::acos(std::clamp(nu.dot(surface.normal[other]), -1.0, 1.0)) > corner_angle) continue;
        tan_beta_[s][end] = cross(nu, nodal[j]) / nu.dot(nodal[j]);
      }
    }
    // An open chain's end segment continues the curvature of its inner end (a circular arc:
    // beta_1 = -beta_2), unless the chain has one segment.
    if (!surface.closed && surface.segment_count() > 1) {
      tan_beta_.front()[0] = -tan_beta_.front()[1];
      tan_beta_.back()[1] = -tan_beta_.back()[0];
    }
  }

  /// The distance t along the unit direction n from x to the nearest facing curve segment
  /// (x + t n on the curve; t < 0 behind x), or nothing when the line meets no segment.
  [[nodiscard]] std::optional<double> distance(const Vec2& x, const Vec2& n) const {
    std::optional<double> best;
    for (std::size_t s = 0; s < surface_.segment_count(); ++s) {
      const Vec2& nu = surface_.normal[s];
      if (n.dot(nu) >= 0.0) continue;
      const auto [a, b] = surface_.segment(s);
      const Vec2 y1 = position(nodes_, a);
      const Vec2 y2 = position(nodes_, b);
      const double length = (y2 - y1).norm();
      const Vec2 tau = (y2 - y1) / length;
      // Fixed point: the line meets the chord offset by w(eta) at t; eta moves by O(w a) per pass.
      double eta = 0.0;
      double t = 0.0;
      for (int pass = 0; pass < 4; ++pass) {
        const double w = pass == 0 ? 0.0 : offset(s, eta, length);
        t = (w - nu.dot(x - y1)) / nu.dot(n);
        eta = tau.dot(x + t * n - y1) / length;
      }
      if (eta < -parameter_round_off || eta > 1.0 + parameter_round_off) continue;
      if (!best || std::abs(t) < std::abs(*best)) best = t;
    }
    return best;
  }

 private:
  [[nodiscard]] double offset(std::size_t s, double eta, double length) const {
    const auto& tb = tan_beta_[s];
    return length * eta * (1.0 - eta) * (tb[1] * eta - tb[0] * (1.0 - eta));
  }

  const std::vector<Node>& nodes_;
  const ContactSurface& surface_;
  std::vector<std::array<double, 2>> tan_beta_;  ///< per segment: tan beta at its two ends
};

}  // namespace

double SurfaceMeasure::weight(double r) const {
  return analysis == AnalysisType::axisymmetric ? 2.0 * std::numbers::pi * r : thickness;
}

DualBasis dual_basis(const Vec2& x1, const Vec2& x2, std::span<const ParameterInterval> covered,
                     const SurfaceMeasure& measure) {
  // Biorthogonality int psi_i N_k dA = delta_ik d_i with psi = A N reads A Me = diag(d); Me is the
  // (weighted) mass matrix of the covered part, symmetric positive definite when that part has length,
  // and d = Me 1 (N_1 + N_2 = 1), which also gives sum_i psi_i = 1^T diag(d) Me^-1 N = 1^T N = 1.
  Eigen::Matrix2d me = Eigen::Matrix2d::Zero();
  for (const ParameterInterval& piece : covered) {
    integrate(x1, x2, piece, measure, [&](double xi, double w) {
      const Vec2 n(1.0 - xi, xi);
      me += w * n * n.transpose();
    });
  }
  DualBasis basis;
  basis.d = me.rowwise().sum();
  basis.A = basis.d.asDiagonal() * me.inverse();
  return basis;
}

double MortarRows::gap(std::size_t row, std::span<const double> displacement) const {
  double g = g0[row];
  for (std::size_t e = start[row]; e < start[row + 1]; ++e) {
    const auto k = static_cast<std::size_t>(node[e]);
    g += coefficient[e].x() * displacement[2 * k] + coefficient[e].y() * displacement[2 * k + 1];
  }
  return g;
}

MortarRows mortar_rows(const std::vector<Node>& nodes, const SurfaceMeasure& measure, const ContactSurface& slave,
                       const ContactSurface& master) {
  // Normals: the nodal (averaged) normals of A, interpolated along each segment. Segment normals would
  // jump at A's nodes: near a convex node of a curved A the two segments' normals fan apart and leave
  // a wedge of B that no point of A sees (near a concave node a wedge seen twice), so sum_k M_jk != D_j
  // and a rigid motion of B would open gaps. The continuous field covers B once, and n_j is the one
  // normal of row j.
  const std::vector<Vec2> normal = nodal_normals(slave, nodes);
  const std::size_t n = slave.nodes.size();
  std::vector<double> D(n, 0.0);
  std::vector<std::map<int, double>> M(n);

  for (std::size_t s = 0; s < slave.segment_count(); ++s) {
    const std::size_t i1 = s;
    const std::size_t i2 = (s + 1) % n;
    const Vec2 x1 = position(nodes, slave.nodes[i1]);
    const Vec2 x2 = position(nodes, slave.nodes[i2]);
    const std::vector<Overlap> pieces = overlaps(nodes, x1, x2, normal[i1], normal[i2], slave.normal[s], master);
    double covered_length = 0.0;
    std::vector<ParameterInterval> covered;
    for (const Overlap& o : pieces) {
      covered_length += o.piece.hi - o.piece.lo;
      covered.push_back(o.piece);
    }
    if (covered_length < min_covered_fraction) continue;

    // The dual basis over the covered part only: D stays diagonal and sum_k M_jk = D_j holds at the
    // ends of a partly covered side too (a basis biorthogonal over the whole segment would count
    // area that faces nothing in D but not in M).
    const DualBasis basis = dual_basis(x1, x2, covered, measure);
    D[i1] += basis.d[0];
    D[i2] += basis.d[1];
    for (const Overlap& o : pieces) {
      const auto [b1, b2] = master.segment(o.master);
      const Vec2 y1 = position(nodes, b1);
      const Vec2 y2 = position(nodes, b2);
      integrate(x1, x2, o.piece, measure, [&](double xi, double w) {
        const Vec2 x = (1.0 - xi) * x1 + xi * x2;
        const auto hit = meet(x, normal_at(normal[i1], normal[i2], xi), y1, y2);
        assert(hit);
        const double eta = hit->first;
        const Vec2 psi = basis.A * Vec2(1.0 - xi, xi);
        M[i1][b1] += w * psi[0] * (1.0 - eta);
        M[i1][b2] += w * psi[0] * eta;
        M[i2][b1] += w * psi[1] * (1.0 - eta);
        M[i2][b2] += w * psi[1] * eta;
      });
    }
  }

  const SmoothCurve curve(nodes, master);
  MortarRows rows;
  for (std::size_t j = 0; j < n; ++j) {
    if (D[j] <= 0.0) continue;
    const int slave_node = slave.nodes[j];
    const Vec2& nj = normal[j];
    std::map<int, double>& entries = M[j];
    const double own = entries.contains(slave_node) ? entries.at(slave_node) : 0.0;
    entries.erase(slave_node);
    auto add = [&](int k, double m) {
      rows.node.push_back(k);
      rows.mortar.push_back(m);
      rows.coefficient.push_back(m * nj);
    };
    add(slave_node, own - D[j]);
    // sum_k m_k x_k = sum_k m_k (x_k - x_j) + (sum_k m_k) x_j: the second sum is round-off
    // (consistency), the first has no cancellation of coordinates far larger than the gap.
    const Vec2 xj = position(nodes, slave_node);
    Vec2 weighted = Vec2::Zero();
    double total = own - D[j];
    for (const auto& [k, m] : entries) {
      add(k, m);
      weighted += m * (position(nodes, k) - xj);
      total += m;
    }
    weighted += total * xj;
    // The initial gap: D_j times the nodal gap to B's smooth curve (see the header); where node j's
    // normal meets no segment of B (a partly covered end), the polygons' own weighted gap.
    const std::optional<double> nodal_gap = curve.distance(xj, nj);
    rows.slave_node.push_back(slave_node);
    rows.normal.push_back(nj);
    rows.g0.push_back(nodal_gap ? D[j] * *nodal_gap : nj.dot(weighted));
    rows.weight.push_back(D[j]);
    rows.start.push_back(rows.node.size());
  }
  return rows;
}

}  // namespace saasgaps
