#include "solver/mortar/overlap_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/mortar/normal_projection.hpp"

namespace saasgaps {

namespace {

/// The pieces of slave segment x1 -> x2 (nodal normals n1, n2, segment normal ns) that face the
/// master surface, each with the nearest facing master segment among `near`.
std::vector<Overlap> overlaps(const Vec2& x1, const Vec2& x2, const Vec2& n1, const Vec2& n2, const Vec2& ns,
                              const SurfaceGeometry& master_geometry, std::span<const std::size_t> near,
                              const QuadraticEdge* curve, int half) {
  const std::vector<Node>& nodes = master_geometry.nodes();
  const ContactSurface& master = master_geometry.surface();
  std::vector<Overlap> candidates;
  for (const std::size_t m : near) {
    if (ns.dot(master.normal[m]) >= 0.0) continue;  // not facing: the back of a closed surface
    const auto [b1, b2] = master.segment(m);
    auto xa = project_onto_segment(x1, x2, n1, n2, node_position(nodes, b1));
    auto xb = project_onto_segment(x1, x2, n1, n2, node_position(nodes, b2));
    if (!xa || !xb) continue;
    if (curve != nullptr) {
      // Onto the curve, near the chord's root; a node projecting well off the half stays off it (the
      // curve's extrapolation beyond its edge may turn back), where its chord root is as good.
      const auto refine = [&](double chord_root, int b) {
        if (chord_root < -0.25 || chord_root > 1.25) return chord_root;
        const double on_curve = project_onto_curve(*curve, half, n1, n2, node_position(nodes, b), chord_root);
        return std::isfinite(on_curve) && on_curve >= -0.5 && on_curve <= 1.5 ? on_curve : chord_root;
      };
      xa = refine(*xa, b1);
      xb = refine(*xb, b2);
    }
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

}  // namespace

MasterSegments::MasterSegments(const SurfaceGeometry& master, Pairing pairing) : master_(&master) {
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

std::vector<Overlap> facing_pieces(const Vec2& x1, const Vec2& x2, const Vec2& n1, const Vec2& n2, const Vec2& ns,
                                   const MasterSegments& master_segments, const QuadraticEdge* curve, int half) {
  std::vector<Overlap> pieces;
  const Box box = box_of(x1, x2);
  const double length = (x2 - x1).norm();
  // A master end exactly on a line is found with a margin of round-off's order.
  const double margin = 1e3 * parameter_round_off * length;
  master_segments.search(box, length, SweptLines{x1, x2, n1, n2}, margin,
                         [&](std::span<const std::size_t> near, double reach, bool final) {
    pieces = overlaps(x1, x2, n1, n2, ns, master_segments.master(), near, curve, half);
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

}  // namespace saasgaps
