#include "solver/mortar/mortar_coupling.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <span>

#include "solver/mortar/dual_basis.hpp"
#include "solver/mortar/normal_projection.hpp"

namespace saasgaps {

namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 position(const std::vector<Node>& nodes, int i) {
  const Node& n = nodes[static_cast<std::size_t>(i)];
  return {n.r, n.z};
}

/// A row's entry for one node: the scalar mortar weight (int psi_j N_k dA, with D_j's sign on A) and
/// the gap's gradient with respect to the node's displacement.
struct Term {
  double mortar = 0.0;
  Vec2 coefficient = Vec2::Zero();
  void add(double m, const Vec2& c) {
    mortar += m;
    coefficient += c;
  }
};

/// The direction along which a displacement at xi changes the gap: the normal field n(xi).
Vec2 gap_direction(const Vec2& n1, const Vec2& n2, double xi) { return normal_at(n1, n2, xi); }

/// A piece of a slave segment and the master segment facing it there.
struct Overlap {
  ParameterInterval piece;
  std::size_t master = 0;
};

/// The pieces of slave segment x1 -> x2 (nodal normals n1, n2, segment normal ns) that face the
/// master surface, each with the nearest facing master segment.
std::vector<Overlap> overlaps(const std::vector<Node>& nodes, const Vec2& x1, const Vec2& x2, const Vec2& n1,
                              const Vec2& n2, const Vec2& ns, const ContactSurface& master,
                              std::span<const std::size_t> near) {
  std::vector<Overlap> candidates;
  for (const std::size_t m : near) {
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

/// The master side's segments with a search over them (bins), or all-against-all without.
class MasterSegments {
 public:
  MasterSegments(const std::vector<Node>& nodes, const ContactSurface& master, Pairing pairing) {
    if (pairing == Pairing::all_against_all) {
      all_.resize(master.segment_count());
      for (std::size_t m = 0; m < all_.size(); ++m) all_[m] = m;
      return;
    }
    std::vector<std::array<Vec2, 2>> ends;
    for (std::size_t m = 0; m < master.segment_count(); ++m) {
      const auto [b1, b2] = master.segment(m);
      ends.push_back({position(nodes, b1), position(nodes, b2)});
    }
    boxes_.reserve(ends.size());
    for (const auto& e : ends) boxes_.push_back(box_of(e[0], e[1]));
    bins_.emplace(ends);
  }

  /// Calls found(near, reach, final) with the master segments near `box` inflated by `reach`, the
  /// reach doubling each time, until found returns true; after max_doublings, or once the box would
  /// cover every segment, a last call (final) with every segment that may come within `line_reach`
  /// of one of `lines` (SegmentBins::query), the only ones the caller can find: so a piece facing
  /// nothing costs the bins its lines cross, not the whole side. Without bins: once, with every
  /// segment (final).
  template <class F>
  void search(const Box& box, double reach, const SweptLines& lines, double line_reach, F&& found) const {
    if (!bins_) {
      candidates_ += all_.size();
      found(std::span<const std::size_t>(all_), reach, true);
      return;
    }
    for (int doubling = 0; doubling < max_doublings; ++doubling, reach *= 2.0) {
      const Box query = box.inflated(reach);
      if (query.contains(bins_->bounds())) break;
      bins_->query(query, near_);
      candidates_ += near_.size();
      if (found(std::span<const std::size_t>(near_), reach, false)) return;
    }
    bins_->query(lines, line_reach, near_);
    candidates_ += near_.size();
    found(std::span<const std::size_t>(near_), reach, true);
  }
  [[nodiscard]] const Box& box(std::size_t m) const { return boxes_[m]; }
  [[nodiscard]] bool searching() const { return bins_.has_value(); }
  /// Master segments handed to the callers so far (each query's, summed).
  [[nodiscard]] std::size_t candidates() const { return candidates_; }

 private:
  /// Pieces facing B near them settle within a reach of one or two segment lengths; past this many
  /// doublings the lines' own bins are cheaper than a box of 2^max_doublings segment lengths.
  static constexpr int max_doublings = 4;

  std::vector<std::size_t> all_;
  std::vector<Box> boxes_;
  std::optional<SegmentBins> bins_;
  mutable std::vector<std::size_t> near_;
  mutable std::size_t candidates_ = 0;
};

/// overlaps() against the whole master side, found by a search: a query box round the slave segment,
/// inflated until every piece of [0, 1] is settled. A piece is settled when its master segment lies
/// inside the query box: another segment nearer along n(xi) would cross the line from x(xi) to that
/// hit, which lies in the box (convex), so its bounding box overlaps the query's and it was a
/// candidate. Pieces facing nothing are settled by the final query, of every segment that meets one of
/// the slave segment's normal lines (only those can face it: overlaps() projects along them).
std::vector<Overlap> facing_pieces(const std::vector<Node>& nodes, const Vec2& x1, const Vec2& x2, const Vec2& n1,
                                   const Vec2& n2, const Vec2& ns, const MasterSegments& master_segments,
                                   const ContactSurface& master) {
  std::vector<Overlap> pieces;
  const Box box = box_of(x1, x2);
  const double length = (x2 - x1).norm();
  // A master end exactly on a line is found with a margin of round-off's order.
  const double margin = 1e3 * parameter_round_off * length;
  master_segments.search(box, length, SweptLines{x1, x2, n1, n2}, margin,
                         [&](std::span<const std::size_t> near, double reach, bool final) {
    pieces = overlaps(nodes, x1, x2, n1, n2, ns, master, near);
    if (final) return true;
    const Box query = box.inflated(reach);
    double settled = 0.0;
    for (const Overlap& o : pieces) {
      if (query.contains(master_segments.box(o.master))) settled += o.piece.hi - o.piece.lo;
    }
    return settled >= 1.0 - 1e3 * parameter_round_off;
  });
  return pieces;
}

/// A master node where the chain turns by at least `sharp_corner_angle` is a corner, not a sample of
/// a smooth curve; so is one turning by more than `corner_angle` when that is well above (more than
/// `corner_contrast` times) the turns at both neighbouring nodes. The second rule keeps a coarse ring
/// (12 segments turn by exactly 30 degrees at every node, which round-off puts either side of any
/// fixed threshold) smooth, and finds a corner where an arc meets a flat.
constexpr double corner_angle = 30.0 * std::numbers::pi / 180.0;
constexpr double sharp_corner_angle = 60.0 * std::numbers::pi / 180.0;
constexpr double corner_contrast = 1.5;

/// Per node of the chain: whether it is a corner by the rules above (an open chain's ends are not).
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
    corner[j] = turn[j] >= sharp_corner_angle ||
                (turn[j] > corner_angle && turn[j] > corner_contrast * std::max(left, right));
  }
  return corner;
}

/// A surface as a smooth curve through its nodes: on segment y1 -> y2 (length L, unit tangent tau,
/// outward chord normal nu) the curve is y1 + eta (y2 - y1) + w(eta) nu, with the offset whose normals
/// at the ends are (to first order) the nodal normals, turned by beta_1, beta_2 from nu (the curve's
/// normal is nu - w'(s) tau, so w'(0) = -tan beta_1, w'(L) = -tan beta_2): a circular arc of
/// half-angle (beta_2 - beta_1) / 2 plus a cubic for the rest (offset()). On a circle of radius R
/// and chord angle a the nodal normals are radial, beta = -+a / 2, and the curve is the circle itself:
/// an interference of 1e-4 R is then measured exactly, where a cubic's O(R a^4) error would be a few
/// per cent of it. At a corner (corners()) the curve keeps the segment's direction (beta = 0). An open
/// chain's end segments are arcs.
class SmoothCurve {
 public:
  SmoothCurve(const std::vector<Node>& nodes, const ContactSurface& surface) : nodes_(nodes), surface_(surface) {
    const std::vector<Vec2> nodal = nodal_normals(surface, nodes);
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
        tan_beta_[s][end] = cross(nu, nodal[j]) / nu.dot(nodal[j]);
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
      const double length = (position(nodes, b) - position(nodes, a)).norm();
      // |w| <= L (|tan beta_1| + |tan beta_2|) / 4 (arc and cubic together), doubled for safety.
      bend_ = std::max(bend_, 0.5 * length * (std::abs(tan_beta_[s][0]) + std::abs(tan_beta_[s][1])));
      length_ += length / static_cast<double>(surface.segment_count());
    }
  }

  /// The distance t along the unit direction n from x to the nearest facing curve segment
  /// (x + t n on the curve; t < 0 behind x), or nothing when the line meets no segment.
  [[nodiscard]] std::optional<double> distance(const Vec2& x, const Vec2& n, const MasterSegments& segments) const {
    // A curve segment lies within its chord's box inflated by max |w| <= bend_; one meeting the line
    // nearer than the best hit so far comes within |t| of x. So a hit with |t| <= reach settles it.
    std::optional<double> best;
    // The final query: chords within bend_ (their curves' largest offset) of the line.
    segments.search(box_of(x, x), 2.0 * bend_ + length_, SweptLines{x, x, n, n}, bend_ + length_ * 1e-9,
                    [&](std::span<const std::size_t> near, double reach, bool) {
                      best = nearest(x, n, near);
                      return best && std::abs(*best) + bend_ <= reach;
                    });
    return best;
  }

  /// distance() among the segments `near`.
  [[nodiscard]] std::optional<double> nearest(const Vec2& x, const Vec2& n, std::span<const std::size_t> near) const {
    std::optional<double> best;
    for (const std::size_t s : near) {
      const Vec2& nu = surface_.normal[s];
      if (n.dot(nu) >= 0.0) continue;
      const auto [a, b] = surface_.segment(s);
      const Vec2 y1 = position(nodes_, a);
      const Vec2 y2 = position(nodes_, b);
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
        const double next = (offset(s, eta, length) - nu.dot(x - y1)) / nu.dot(n);
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

  /// w(eta) on segment s (length L): the curve's offset from the chord along its outward normal.
  [[nodiscard]] double offset(std::size_t s, double eta, double length) const {
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

 private:
  const std::vector<Node>& nodes_;
  const ContactSurface& surface_;
  std::vector<std::array<double, 2>> tan_beta_;  ///< per segment: tan beta at its two ends
  double bend_ = 0.0;    ///< bound on |w| over every segment
  double length_ = 0.0;  ///< mean segment length
};

/// A curve point at offset w along the chord normal nu of segment p_1 -> p_2 (d = p_2 - p_1) moves
/// with the chord's interpolated displacement plus the offset carried by the chord's own stretch s and
/// rotation omega,  s w nu + omega w perp(nu),  s = d . (u_2 - u_1) / L^2,  omega = perp(d) . (u_2 - u_1) / L^2
/// (perp(a) = (-a_z, a_r)): exact for any similarity motion, so a circle's curve point moves radially
/// by exactly the nodes' radial motion, where the chord's point moves by that times cos. Returns the
/// gradient of v . (that extra motion) with respect to u_2 (minus it: u_1).
Vec2 bend_gradient(const Vec2& d, const Vec2& nu, double w, const Vec2& v) {
  const Vec2 perp_nu(-nu.y(), nu.x());
  const Vec2 perp_d(-d.y(), d.x());
  return w / d.squaredNorm() * (v.dot(nu) * d + v.dot(perp_nu) * perp_d);
}

}  // namespace

double MortarRows::gap(std::size_t row, std::span<const double> displacement) const {
  double g = g0[row];
  for (std::size_t e = start[row]; e < start[row + 1]; ++e) {
    const auto k = static_cast<std::size_t>(node[e]);
    g += coefficient[e].x() * displacement[2 * k] + coefficient[e].y() * displacement[2 * k + 1];
  }
  return g;
}

MortarRows mortar_rows(const std::vector<Node>& nodes, const SurfaceMeasure& measure, const ContactSurface& slave,
                       const ContactSurface& master, Pairing pairing, std::size_t* candidate_checks) {
  const MasterSegments master_segments(nodes, master, pairing);
  // Normals: the nodal (averaged) normals of A, interpolated along each segment. Segment normals would
  // jump at A's nodes: near a convex node of a curved A the two segments' normals fan apart and leave
  // a wedge of B that no point of A sees (near a concave node a wedge seen twice), so sum_k M_jk != D_j
  // and a rigid motion of B would open gaps. The continuous field covers B once, and n_j is the one
  // normal of row j.
  const std::vector<Vec2> normal = nodal_normals(slave, nodes);
  const std::size_t n = slave.nodes.size();
  std::vector<double> D(n, 0.0);
  std::vector<std::map<int, Term>> M(n);
  const SmoothCurve slave_curve(nodes, slave);
  const SmoothCurve curve(nodes, master);

  for (std::size_t s = 0; s < slave.segment_count(); ++s) {
    const std::size_t i1 = s;
    const std::size_t i2 = (s + 1) % n;
    const int a1 = slave.nodes[i1];
    const int a2 = slave.nodes[i2];
    const Vec2 x1 = position(nodes, a1);
    const Vec2 x2 = position(nodes, a2);
    const std::vector<Overlap> pieces =
        facing_pieces(nodes, x1, x2, normal[i1], normal[i2], slave.normal[s], master_segments, master);
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
        const Vec2 nx = normal_at(normal[i1], normal[i2], xi);
        const auto hit = meet(x, nx, y1, y2);
        assert(hit);
        const double eta = hit->first;
        const Vec2 psi = basis.A * Vec2(1.0 - xi, xi);
        // The gap at xi is measured along n(xi): its change is n(xi) . (u_B(eta) - u_A(xi)), so every
        // node of both segments gets a vector coefficient (A's neighbour too: psi_j N_i n(xi) does not
        // vanish for i != j, only its scalar part does, by biorthogonality).
        const Vec2 v = gap_direction(normal[i1], normal[i2], xi);
        const Vec2 bend_b = bend_gradient(y2 - y1, master.normal[o.master], curve.offset(o.master, eta, (y2 - y1).norm()), v);
        const Vec2 bend_a = bend_gradient(x2 - x1, slave.normal[s], slave_curve.offset(s, xi, (x2 - x1).norm()), v);
        for (std::size_t j = 0; j < 2; ++j) {
          std::map<int, Term>& row = M[j == 0 ? i1 : i2];
          const double pw = w * psi[j];
          row[b1].add(pw * (1.0 - eta), pw * ((1.0 - eta) * v - bend_b));
          row[b2].add(pw * eta, pw * (eta * v + bend_b));
          row[a1].add(0.0, -pw * ((1.0 - xi) * v - bend_a));
          row[a2].add(0.0, -pw * (xi * v + bend_a));
        }
      });
    }
  }

  MortarRows rows;
  for (std::size_t j = 0; j < n; ++j) {
    if (D[j] <= 0.0) continue;
    const int slave_node = slave.nodes[j];
    const Vec2& nj = normal[j];
    std::map<int, Term>& entries = M[j];
    Term own = entries[slave_node];
    entries.erase(slave_node);
    own.mortar -= D[j];
    auto add = [&](int k, const Term& t) {
      rows.node.push_back(k);
      rows.mortar.push_back(t.mortar);
      rows.coefficient.push_back(t.coefficient);
    };
    add(slave_node, own);
    // sum_k m_k x_k = sum_k m_k (x_k - x_j) + (sum_k m_k) x_j: the second sum is round-off
    // (consistency), the first has no cancellation of coordinates far larger than the gap.
    const Vec2 xj = position(nodes, slave_node);
    Vec2 weighted = Vec2::Zero();
    double total = own.mortar;
    for (const auto& [k, t] : entries) {
      add(k, t);
      weighted += t.mortar * (position(nodes, k) - xj);
      total += t.mortar;
    }
    weighted += total * xj;
    // The initial gap: D_j times the nodal gap to B's smooth curve (see the header); where node j's
    // normal meets no segment of B (a partly covered end), the polygons' own weighted gap.
    const std::optional<double> nodal_gap = curve.distance(xj, nj, master_segments);
    rows.slave_node.push_back(slave_node);
    rows.normal.push_back(nj);
    rows.g0.push_back(nodal_gap ? D[j] * *nodal_gap : nj.dot(weighted));
    rows.weight.push_back(D[j]);
    rows.start.push_back(rows.node.size());
  }
  if (candidate_checks != nullptr) *candidate_checks += master_segments.candidates();
  return rows;
}

}  // namespace saasgaps
