#include "solver/mortar/mortar_coupling.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <span>

#include "solver/mortar/dual_basis.hpp"
#include "solver/mortar/normal_projection.hpp"

namespace saasgaps {

namespace {

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
    const auto xa = project_onto_segment(x1, x2, n1, n2, node_position(nodes, b1));
    const auto xb = project_onto_segment(x1, x2, n1, n2, node_position(nodes, b2));
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
      const auto hit = meet(x, n, node_position(nodes, b1), node_position(nodes, b2));
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
  MasterSegments(const SurfaceGeometry& master, Pairing pairing) : master_(&master) {
    const ContactSurface& surface = master.surface();
    if (pairing == Pairing::all_against_all) {
      all_.resize(surface.segment_count());
      for (std::size_t m = 0; m < all_.size(); ++m) all_[m] = m;
      return;
    }
    std::vector<std::array<Vec2, 2>> ends;
    for (std::size_t m = 0; m < surface.segment_count(); ++m) {
      const auto [b1, b2] = surface.segment(m);
      ends.push_back({node_position(master.nodes(), b1), node_position(master.nodes(), b2)});
    }
    boxes_.reserve(ends.size());
    for (const auto& e : ends) boxes_.push_back(box_of(e[0], e[1]));
    bins_.emplace(ends);
  }

  [[nodiscard]] const SurfaceGeometry& master() const { return *master_; }

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
  /// Master segments handed to the callers so far (each query's, summed).
  [[nodiscard]] std::size_t candidates() const { return candidates_; }

 private:
  /// Pieces facing B near them settle within a reach of one or two segment lengths; past this many
  /// doublings the lines' own bins are cheaper than a box of 2^max_doublings segment lengths.
  static constexpr int max_doublings = 4;

  const SurfaceGeometry* master_;
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

/// The distance t along the unit direction n from x to the master's smooth curve (x + t n on it,
/// t < 0 behind x; distance_to_curve()), searched like facing_pieces() with the curves' largest offset
/// from their chords as the margin; nothing when the line meets no facing segment.
std::optional<double> curve_distance(const Vec2& x, const Vec2& n, const MasterSegments& master_segments) {
  const SurfaceGeometry& curve = master_segments.master();
  const double bend = curve.bend();
  const double length = curve.mean_length();
  // A curve segment lies within its chord's box inflated by max |w| <= bend; one meeting the line
  // nearer than the best hit so far comes within |t| of x. So a hit with |t| <= reach settles it.
  std::optional<double> best;
  // The final query: chords within bend (their curves' largest offset) of the line.
  master_segments.search(box_of(x, x), 2.0 * bend + length, SweptLines{x, x, n, n}, bend + length * 1e-9,
                         [&](std::span<const std::size_t> near, double reach, bool) {
                           best = distance_to_curve(curve, x, n, near);
                           return best && std::abs(*best) + bend <= reach;
                         });
  return best;
}

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

MortarRows mortar_rows(const SurfaceMeasure& measure, const SurfaceGeometry& slave_geometry,
                       const SurfaceGeometry& master_geometry, Pairing pairing, std::size_t* candidate_checks) {
  // Both sides are of one model: a row's entries index its nodes.
  assert(&slave_geometry.nodes() == &master_geometry.nodes());
  const std::vector<Node>& nodes = slave_geometry.nodes();
  const ContactSurface& slave = slave_geometry.surface();
  const ContactSurface& master = master_geometry.surface();
  const MasterSegments master_segments(master_geometry, pairing);
  // Normals: the nodal (averaged) normals of A, interpolated along each segment. Segment normals would
  // jump at A's nodes: near a convex node of a curved A the two segments' normals fan apart and leave
  // a wedge of B that no point of A sees (near a concave node a wedge seen twice), so sum_k M_jk != D_j
  // and a rigid motion of B would open gaps. The continuous field covers B once, and n_j is the one
  // normal of row j.
  const std::vector<Vec2>& normal = slave_geometry.nodal_normals();
  const std::size_t n = slave.nodes.size();
  std::vector<double> D(n, 0.0);
  std::vector<std::map<int, Term>> M(n);

  for (std::size_t s = 0; s < slave.segment_count(); ++s) {
    const std::size_t i1 = s;
    const std::size_t i2 = (s + 1) % n;
    const int a1 = slave.nodes[i1];
    const int a2 = slave.nodes[i2];
    const Vec2 x1 = node_position(nodes, a1);
    const Vec2 x2 = node_position(nodes, a2);
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
      const Vec2 y1 = node_position(nodes, b1);
      const Vec2 y2 = node_position(nodes, b2);
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
        const Vec2 bend_b = bend_gradient(y2 - y1, master.normal[o.master], master_geometry.offset(o.master, eta, (y2 - y1).norm()), v);
        const Vec2 bend_a = bend_gradient(x2 - x1, slave.normal[s], slave_geometry.offset(s, xi, (x2 - x1).norm()), v);
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
    const Vec2 xj = node_position(nodes, slave_node);
    Vec2 weighted = Vec2::Zero();
    double total = own.mortar;
    for (const auto& [k, t] : entries) {
      add(k, t);
      weighted += t.mortar * (node_position(nodes, k) - xj);
      total += t.mortar;
    }
    weighted += total * xj;
    // The initial gap: D_j times the nodal gap to B's smooth curve (see the header); where node j's
    // normal meets no segment of B (a partly covered end), the polygons' own weighted gap.
    const std::optional<double> nodal_gap = curve_distance(xj, nj, master_segments);
    rows.slave_node.push_back(slave_node);
    rows.normal.push_back(nj);
    rows.g0.push_back(nodal_gap ? D[j] * *nodal_gap : nj.dot(weighted));
    rows.weight.push_back(D[j]);
    rows.start.push_back(rows.node.size());
  }
  if (candidate_checks != nullptr) *candidate_checks += master_segments.candidates();
  return rows;
}

MortarRows mortar_rows(const std::vector<Node>& nodes, const SurfaceMeasure& measure, const ContactSurface& slave,
                       const ContactSurface& master, Pairing pairing, std::size_t* candidate_checks) {
  const SurfaceGeometry slave_geometry(nodes, slave);
  const SurfaceGeometry master_geometry(nodes, master);
  return mortar_rows(measure, slave_geometry, master_geometry, pairing, candidate_checks);
}

}  // namespace saasgaps
