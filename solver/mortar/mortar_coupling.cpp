#include "solver/mortar/mortar_coupling.hpp"

#include <cassert>
#include <map>

#include <Eigen/LU>
#include <optional>

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

/// What the integrals give each node j of A's chain: D_j and the row's entries by node (M_jk, c_jk).
/// D holds the straight segments' shares, whose A entries are left at 0 and get -D_j in the row;
/// D_curved the 3-node edges' shares, whose A entries are integrated (-int psi_j N_i^A dA: -D_j for
/// i = j and 0 for its neighbours where the edge is wholly covered).
struct RowIntegrals {
  std::vector<double> D;
  std::vector<std::map<int, Term>> M;
  std::vector<double> D_curved;
};

/// Adds what a point of B at parameter eta of master segment m (chord y1 -> y2) gives row `row`, with
/// pw = weight x psi_j and v the direction the gap is measured along: a straight segment's two nodes
/// (N = 1 - eta, eta, plus its smooth curve's bend), or a half of a 3-node edge's three nodes with
/// the edge's quadratic shape functions at s = (h + eta) / 2.
/// Where the line x + t v meets master segment m (chord y1 -> y2): its parameter eta, on the chord
/// for a straight segment (its smooth curve enters through the bend), on the curve for a half of a
/// 3-node edge (its points are the curve's).
double master_parameter(const SurfaceGeometry& master_geometry, std::size_t m, const Vec2& y1, const Vec2& y2,
                        const Vec2& x, const Vec2& v) {
  const auto hit = meet(x, v, y1, y2);
  assert(hit);
  const int h = master_geometry.surface().half(m);
  if (h < 0) return hit->first;
  return meet_curve(x, v, master_geometry.quadratic_edge(m), h, hit->first).first;
}

void add_master_point(std::map<int, Term>& row, const SurfaceGeometry& master_geometry, std::size_t m,
                      const Vec2& y1, const Vec2& y2, double eta, double pw, const Vec2& v) {
  const ContactSurface& master = master_geometry.surface();
  if (const int h = master.half(m); h >= 0) {
    const auto at = master.edge_positions(m);
    const auto N = QuadraticEdge::shape(0.5 * (h + eta));
    for (std::size_t k = 0; k < 3; ++k) row[master.nodes[at[k]]].add(pw * N[k], pw * N[k] * v);
    return;
  }
  const auto [b1, b2] = master.segment(m);
  const Vec2 bend_b = bend_gradient(y2 - y1, master.normal[m], master_geometry.offset(m, eta, (y2 - y1).norm()), v);
  row[b1].add(pw * (1.0 - eta), pw * ((1.0 - eta) * v - bend_b));
  row[b2].add(pw * eta, pw * (eta * v + bend_b));
}

/// The rows' integrals over the 3-node edge whose first half is slave segment s0 (docs/contact-
/// surfaces.md, section 7): the edge's quadratic curve X(s) and shape functions N_i(s) for A, the
/// multiplier piecewise linear on its two halves, psi_j = sum_i A_ji phi_i (phi the hats of corner,
/// mid-side node, corner), biorthogonal to N over the whole edge with the measure:
///   H_ki = int_edge N_k phi_i dA,  d_k = int_edge N_k dA,  A = diag(d) H^-T,
/// so int psi_j N_k dA = delta_jk d_k, d = (1/6, 2/3, 1/6) x the edge's area on a straight plane edge,
/// and sum_j psi_j = 1 (H 1 = d). Its points are the curve's: the pieces end where B's nodes project
/// onto the curve, and a point's partner on B is where its normal line meets B's curve (B's chord, for
/// a straight segment of B, whose smooth curve enters through the bend).
void integrate_curved_edge(const SurfaceMeasure& measure, const SurfaceGeometry& slave_geometry,
                           const SurfaceGeometry& master_geometry, const std::vector<std::vector<Overlap>>& facing,
                           std::size_t s0, RowIntegrals& sums) {
  const ContactSurface& slave = slave_geometry.surface();
  const std::vector<Vec2>& normal = slave_geometry.nodal_normals();
  const auto at = slave.edge_positions(s0);
  double covered_length = 0.0;
  for (std::size_t h = 0; h < 2; ++h) {
    for (const Overlap& o : facing[s0 + h]) covered_length += 0.5 * (o.piece.hi - o.piece.lo);
  }
  if (covered_length < min_covered_fraction) return;
  const QuadraticEdge curve = slave_geometry.quadratic_edge(s0);
  const auto hats = [](int h, double xi) {
    return h == 0 ? Eigen::Vector3d(1.0 - xi, xi, 0.0) : Eigen::Vector3d(0.0, 1.0 - xi, xi);
  };
  const auto shape = [](int h, double xi) {
    const auto N = QuadraticEdge::shape(0.5 * (h + xi));
    return Eigen::Vector3d(N[0], N[1], N[2]);
  };
  // The basis over the whole edge, covered or not: over a covered part alone the hat of a corner
  // whose half faces nothing would vanish (H singular), and a corner's d_k could be <= 0.
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int h = 0; h < 2; ++h) {
    integrate_curved(curve, h, ParameterInterval{0.0, 1.0}, measure, [&](double xi, double w) {
      const Eigen::Vector3d N = shape(h, xi);
      H += w * N * hats(h, xi).transpose();
      d += w * N;
    });
  }
  const Eigen::Matrix3d A = d.asDiagonal() * H.transpose().inverse();
  for (std::size_t k = 0; k < 3; ++k) sums.D_curved[at[k]] += d[static_cast<Eigen::Index>(k)];
  for (int h = 0; h < 2; ++h) {
    const std::size_t s = s0 + static_cast<std::size_t>(h);
    const std::size_t i1 = at[static_cast<std::size_t>(h)], i2 = at[static_cast<std::size_t>(h) + 1];
    for (const Overlap& o : facing[s]) {
      const auto [b1, b2] = master_geometry.surface().segment(o.master);
      const Vec2 y1 = node_position(master_geometry.nodes(), b1);
      const Vec2 y2 = node_position(master_geometry.nodes(), b2);
      integrate_curved(curve, h, o.piece, measure, [&](double xi, double w) {
        const Vec2 x = curve.position(0.5 * (h + xi));  // the edge's own point
        const Vec2 v = normal_at(normal[i1], normal[i2], xi);
        const double eta = master_parameter(master_geometry, o.master, y1, y2, x, v);
        const Eigen::Vector3d psi = A * hats(h, xi);
        const Eigen::Vector3d N = shape(h, xi);
        for (std::size_t j = 0; j < 3; ++j) {
          std::map<int, Term>& row = sums.M[at[j]];
          const double pw = w * psi[static_cast<Eigen::Index>(j)];
          add_master_point(row, master_geometry, o.master, y1, y2, eta, pw, v);
          for (std::size_t i = 0; i < 3; ++i) {
            const double pn = pw * N[static_cast<Eigen::Index>(i)];
            row[slave.nodes[at[i]]].add(-pn, -pn * v);
          }
        }
      });
    }
  }
}

/// D and M over the pieces of each segment of A (`facing`, per segment) with the dual basis of the
/// part each segment has covered.
RowIntegrals integrate_rows(const SurfaceMeasure& measure, const SurfaceGeometry& slave_geometry,
                            const SurfaceGeometry& master_geometry, const std::vector<std::vector<Overlap>>& facing) {
  const std::vector<Node>& nodes = slave_geometry.nodes();
  const ContactSurface& slave = slave_geometry.surface();
  const ContactSurface& master = master_geometry.surface();
  const std::vector<Vec2>& normal = slave_geometry.nodal_normals();
  const std::size_t n = slave.nodes.size();
  RowIntegrals sums{std::vector<double>(n, 0.0), std::vector<std::map<int, Term>>(n), std::vector<double>(n, 0.0)};
  std::vector<double>& D = sums.D;
  std::vector<std::map<int, Term>>& M = sums.M;

  for (std::size_t s = 0; s < slave.segment_count(); ++s) {
    if (const int h = slave.half(s); h >= 0) {
      // A 3-node edge: both halves at once, from its first.
      if (h == 0) integrate_curved_edge(measure, slave_geometry, master_geometry, facing, s, sums);
      continue;
    }
    const std::size_t i1 = s;
    const std::size_t i2 = (s + 1) % n;
    const int a1 = slave.nodes[i1];
    const int a2 = slave.nodes[i2];
    const Vec2 x1 = node_position(nodes, a1);
    const Vec2 x2 = node_position(nodes, a2);
    const std::vector<Overlap>& pieces = facing[s];
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
      const Vec2 y1 = node_position(master_geometry.nodes(), b1);
      const Vec2 y2 = node_position(master_geometry.nodes(), b2);
      const auto point = [&](double xi, double w) {
        const Vec2 x = (1.0 - xi) * x1 + xi * x2;
        const Vec2 nx = normal_at(normal[i1], normal[i2], xi);
        const double eta = master_parameter(master_geometry, o.master, y1, y2, x, nx);
        const Vec2 psi = basis.A * Vec2(1.0 - xi, xi);
        // The gap at xi is measured along n(xi): its change is n(xi) . (u_B(eta) - u_A(xi)), so every
        // node of both segments gets a vector coefficient (A's neighbour too: psi_j N_i n(xi) does not
        // vanish for i != j, only its scalar part does, by biorthogonality).
        const Vec2 v = gap_direction(normal[i1], normal[i2], xi);
        const Vec2 bend_a = bend_gradient(x2 - x1, slave.normal[s], slave_geometry.offset(s, xi, (x2 - x1).norm()), v);
        for (std::size_t j = 0; j < 2; ++j) {
          std::map<int, Term>& row = M[j == 0 ? i1 : i2];
          const double pw = w * psi[j];
          add_master_point(row, master_geometry, o.master, y1, y2, eta, pw, v);
          row[a1].add(0.0, -pw * ((1.0 - xi) * v - bend_a));
          row[a2].add(0.0, -pw * (xi * v + bend_a));
        }
      };
      // Facing a half of a 3-node edge, B's parameter is not a polynomial of xi: the curved rule.
      if (master.half(o.master) >= 0) {
        integrate<CurvedGauss>(x1, x2, o.piece, measure, point);
      } else {
        integrate(x1, x2, o.piece, measure, point);
      }
    }
  }
  return sums;
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
  // Normals: the nodal (averaged) normals of A, interpolated along each segment. Segment normals would
  // jump at A's nodes: near a convex node of a curved A the two segments' normals fan apart and leave
  // a wedge of B that no point of A sees (near a concave node a wedge seen twice), so sum_k M_jk != D_j
  // and a rigid motion of B would open gaps. The continuous field covers B once, and n_j is the one
  // normal of row j.
  const std::vector<Vec2>& normal = slave_geometry.nodal_normals();
  const std::size_t n = slave.nodes.size();

  // Pairing: the pieces of each segment of A that face B, each with its segment of B.
  const MasterSegments master_segments(master_geometry, pairing);
  std::vector<std::vector<Overlap>> facing(slave.segment_count());
  for (std::size_t s = 0; s < slave.segment_count(); ++s) {
    const Vec2 x1 = node_position(nodes, slave.nodes[s]);
    const Vec2 x2 = node_position(nodes, slave.nodes[(s + 1) % n]);
    const int h = slave.half(s);
    const std::optional<QuadraticEdge> curve =
        h >= 0 ? std::optional<QuadraticEdge>(slave_geometry.quadratic_edge(s)) : std::nullopt;
    facing[s] = facing_pieces(x1, x2, normal[s], normal[(s + 1) % n], slave.normal[s], master_segments,
                              curve ? &*curve : nullptr, h);
  }

  // Integrals: D_j and the entries of each node's row.
  RowIntegrals sums = integrate_rows(measure, slave_geometry, master_geometry, facing);
  const std::vector<double>& D = sums.D;

  // Rows: one per node of A with a share of the covered area.
  MortarRows rows;
  for (std::size_t j = 0; j < n; ++j) {
    // Straight segments' share (their A entries get -D_j here) and 3-node edges' (integrated).
    const double weight = D[j] + sums.D_curved[j];
    if (weight <= 0.0) continue;
    const int slave_node = slave.nodes[j];
    const Vec2& nj = normal[j];
    std::map<int, Term>& entries = sums.M[j];
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
    rows.g0.push_back(nodal_gap ? weight * *nodal_gap : nj.dot(weighted));
    rows.weight.push_back(weight);
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
