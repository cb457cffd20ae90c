#include "solver/recovery/boundary_stresses.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/recovery/boundary_edges.hpp"
#include "solver/model/load_schedule.hpp"

namespace saasgaps {

namespace {

/// Two tangents closer than this make a smooth boundary (a circle drawn with 18 or more straight
/// edges per half turn passes; a right-angled corner does not).
const double smooth_cos = std::cos(20.0 * std::numbers::pi / 180.0);
/// An edge meeting a symmetry line within this of a right angle continues smoothly into its mirror
/// image (the kink between them is twice the deviation).
const double perpendicular_sin = std::sin(10.0 * std::numbers::pi / 180.0);

/// Nodes where the traction is not known: a prescribed displacement (but a symmetry line's
/// roller), a nodal force, a gap element, a contact surface.
std::vector<std::uint8_t> unknown_traction(const Model& model, const SymmetryLines& symmetry) {
  std::vector<std::uint8_t> unknown(model.nodes.size(), 0);
  const std::vector<double> prescribed = final_prescribed(model);
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const bool held = !std::isnan(prescribed[2 * n]) || !std::isnan(prescribed[2 * n + 1]);
    if (held && !symmetry.on_line(n)) unknown[n] = 1;
  }
  for (const NodalForce& f : final_loads(model).nodal_forces) {
    if (f.f_r != 0.0 || f.f_z != 0.0) unknown[static_cast<std::size_t>(f.node)] = 1;
  }
  mark_contact_nodes(model, unknown);
  return unknown;
}

/// The edge loads of the last step per edge: (sigma_nn, sigma_nt) = (-normal, shear along the
/// edge's own direction), summed over the loads that name the edge.
using EdgeTractions = std::unordered_map<std::uint64_t, Vec2>;

std::uint64_t edge_key(EdgeRef e) { return static_cast<std::uint64_t>(e.element) * 16U + e.local; }

EdgeTractions edge_tractions(const Model& model) {
  EdgeTractions out;
  for (const EdgePressure& p : final_loads(model).pressures) {
    const Element& el = model.elements[static_cast<std::size_t>(p.element)];
    const auto edges = edges_of(el);
    for (std::size_t l = 0; l < edges.size(); ++l) {
      const int a = el.nodes[static_cast<std::size_t>(edges[l].first())];
      const int b = el.nodes[static_cast<std::size_t>(edges[l].last())];
      if (!((a == p.node_a && b == p.node_b) || (a == p.node_b && b == p.node_a))) continue;
      const double along = a == p.node_a ? 1.0 : -1.0;  // the load's shear runs node_a -> node_b
      const auto [entry, added] = out.try_emplace(edge_key({static_cast<std::uint32_t>(p.element), static_cast<std::uint8_t>(l)}), 0.0, 0.0);
      entry->second += Vec2(-p.normal, along * p.shear);
      break;
    }
  }
  return out;
}

/// One edge seen from one of its nodes: its nodes, the node's place among them, and the direction
/// along the edge (its own, counter-clockwise for the element) and outward normal there.
struct EdgeAtNode {
  std::array<int, max_edge_nodes> nodes{-1, -1, -1};
  int count = 2;
  int position = 0;  ///< the node's index along the edge: 0 first, count - 1 last
  Vec2 t = Vec2::Zero();
  Vec2 n = Vec2::Zero();
};

Vec2 position_of(const Model& model, int node) {
  const Node& n = model.nodes[static_cast<std::size_t>(node)];
  return {n.r, n.z};
}

EdgeAtNode edge_at_node(const Model& model, EdgeRef edge, std::size_t node) {
  EdgeAtNode out;
  out.nodes = edge_nodes(model, edge, out.count);
  while (static_cast<std::size_t>(out.nodes[static_cast<std::size_t>(out.position)]) != node) ++out.position;
  // d x / d s of the edge at the node (s = -1, 1 at the ends, 0 at a 3-node edge's middle).
  const double s = out.count == 3 ? static_cast<double>(out.position - 1) : 2.0 * out.position - 1.0;
  const std::array<double, max_edge_nodes> dN = edge_shape(s, out.count).dN;
  Vec2 dx = Vec2::Zero();
  for (int k = 0; k < out.count; ++k) dx += dN[static_cast<std::size_t>(k)] * position_of(model, out.nodes[static_cast<std::size_t>(k)]);
  out.t = dx.normalized();
  // Outward: away from the element's centroid (whatever way round its nodes run).
  const Element& el = model.elements[edge.element];
  Vec2 centroid = Vec2::Zero();
  for (const int m : el.node_span()) centroid += position_of(model, m);
  centroid /= static_cast<double>(el.node_count);
  out.n = Vec2(out.t.y(), -out.t.x());
  if (out.n.dot(position_of(model, static_cast<int>(node)) - centroid) < 0.0) out.n = -out.n;
  return out;
}

/// Points along the boundary through a node, in the edges' direction: positions and displacements.
struct BoundaryChain {
  static constexpr int capacity = 2 * max_edge_nodes - 1;
  std::array<Vec2, capacity> x{};
  std::array<Vec2, capacity> u{};
  int count = 0;
  int centre = 0;  ///< the node's index in the chain

  void push(const Vec2& xk, const Vec2& uk) {
    x[static_cast<std::size_t>(count)] = xk;
    u[static_cast<std::size_t>(count++)] = uk;
  }

  /// The stretch t . du/ds at the centre, and t: x(s) and u(s) interpolated by the polynomial through
  /// the points in the chord length s, differentiated at the centre:
  ///   dx = sum_k l_k'(s_c) x_k,  du = sum_k l_k'(s_c) u_k,  t = dx / |dx|,  stretch = dx . du / |dx|^2.
  /// The same weights on x and u make it exact for a homogeneous strain (u linear in x) whatever the
  /// points' spacing; through 3 points of straight edges it is the central difference, through the
  /// 5 nodes of two quadratic edges fourth order in the spacing.
  [[nodiscard]] std::pair<double, Vec2> stretch() const {
    std::array<double, capacity> s{};
    for (int k = 1; k < count; ++k) s[static_cast<std::size_t>(k)] = s[static_cast<std::size_t>(k - 1)] + (x[static_cast<std::size_t>(k)] - x[static_cast<std::size_t>(k - 1)]).norm();
    const double sc = s[static_cast<std::size_t>(centre)];
    Vec2 dx = Vec2::Zero(), du = Vec2::Zero();
    for (int j = 0; j < count; ++j) {
      // l_j'(sc) = sum_{k != j} 1 / (s_j - s_k) prod_{m != j, k} (sc - s_m) / (s_j - s_m)
      double w = 0.0;
      for (int k = 0; k < count; ++k) {
        if (k == j) continue;
        double term = 1.0 / (s[static_cast<std::size_t>(j)] - s[static_cast<std::size_t>(k)]);
        for (int m = 0; m < count; ++m) {
          if (m != j && m != k) term *= (sc - s[static_cast<std::size_t>(m)]) / (s[static_cast<std::size_t>(j)] - s[static_cast<std::size_t>(m)]);
        }
        w += term;
      }
      dx += w * x[static_cast<std::size_t>(j)];
      du += w * u[static_cast<std::size_t>(j)];
    }
    return {dx.dot(du) / dx.squaredNorm(), dx.normalized()};
  }
};

/// What the stress at a boundary side is made of: the frame, the stretch and the traction.
struct BoundaryPoint {
  std::uint32_t side = 0;
  std::size_t node = 0;
  EdgeRef edge;  ///< the element whose law it takes
  Vec2 t = Vec2::Zero();
  Vec2 n = Vec2::Zero();
  double stretch = 0.0;
  Vec2 traction = Vec2::Zero();  ///< (sigma_nn, sigma_nt) with t and n above
};

bool same_traction(const Vec2& a, const Vec2& b) {
  return ((a - b).array().abs() <= 1e-9 * a.cwiseAbs().cwiseMax(b.cwiseAbs()).array()).all();
}

/// The traction-boundary points of the file comment (`u` may be empty: the stretch is then zero).
std::vector<BoundaryPoint> boundary_points(const Model& model, const RecoveredField& field, const SymmetryLines& symmetry,
                                           std::span<const double> u) {
  const BoundaryEdges edges = boundary_edges(model);
  const std::vector<std::uint8_t> unknown = unknown_traction(model, symmetry);
  const EdgeTractions loads = edge_tractions(model);
  const std::vector<double> zero(2 * model.nodes.size(), 0.0);
  if (u.empty()) u = zero;

  // An edge whose every node has a known traction and which does not lie along a symmetry line.
  const auto usable = [&](EdgeRef e, bool& along_line) {
    int count = 0;
    const auto nodes = edge_nodes(model, e, count);
    const auto a = static_cast<std::size_t>(nodes[0]), b = static_cast<std::size_t>(nodes[static_cast<std::size_t>(count - 1)]);
    along_line = symmetry.on_line(a) && symmetry.same_line(model, a, b);
    for (int k = 0; k < count; ++k) {
      if (unknown[static_cast<std::size_t>(nodes[static_cast<std::size_t>(k)])] != 0) return false;
    }
    return true;
  };
  const auto traction_of = [&](EdgeRef e) {
    const auto found = loads.find(edge_key(e));
    return found == loads.end() ? Vec2(0.0, 0.0) : found->second;
  };

  std::vector<BoundaryPoint> out;
  double size = 0.0;
  for (const Node& n : model.nodes) size = std::max({size, std::abs(n.r), std::abs(n.z)});
  for (std::size_t i = 0; i < edges.node_edge.size();) {
    // Node n's boundary edges: node_edge[i .. end).
    const std::size_t n = edges.node_edge[i].first;
    std::size_t end = i;
    while (end < edges.node_edge.size() && edges.node_edge[end].first == n) ++end;
    const std::size_t begin = i;
    i = end;
    if (unknown[n] != 0) continue;
    if (model.analysis == AnalysisType::axisymmetric && model.nodes[n].r <= 1e-9 * size) continue;
    for (std::uint32_t s = field.first[n]; s < field.first[n + 1]; ++s) {
      const int m = field.material[s];
      std::array<EdgeRef, 2> mine{};
      int count = 0;
      bool usable_all = true;
      for (std::size_t k = begin; k < end; ++k) {
        const EdgeRef e = edges.edge[edges.node_edge[k].second];
        if (model.elements[e.element].material != m) continue;
        bool along_line = false;
        const bool ok = usable(e, along_line);
        if (along_line) continue;  // inside the mirrored body
        usable_all = usable_all && ok;
        if (count < 2) mine[static_cast<std::size_t>(count)] = e;
        ++count;
      }
      if (!usable_all || count == 0 || count > 2) continue;
      const EdgeAtNode first = edge_at_node(model, mine[0], n);
      BoundaryPoint p{s, n, mine[0], first.t, first.n, 0.0, traction_of(mine[0])};
      const auto displacement_of = [&](int node) {
        return Vec2(u[2 * static_cast<std::size_t>(node)], u[2 * static_cast<std::size_t>(node) + 1]);
      };
      BoundaryChain chain;
      const auto push_edge = [&](const EdgeAtNode& e, int from) {
        for (int k = from; k < e.count; ++k) {
          const int node = e.nodes[static_cast<std::size_t>(k)];
          chain.push(position_of(model, node), displacement_of(node));
        }
      };
      // A mid-side node keeps its patch value (the header says why).
      if (first.position > 0 && first.position < first.count - 1) continue;
      if (count == 2) {
        const EdgeAtNode second = edge_at_node(model, mine[1], n);
        // One edge arrives at the node and the other leaves it, nearly in line.
        if ((first.position == 0) == (second.position == 0) || first.t.dot(second.t) < smooth_cos) continue;
        if (!same_traction(p.traction, traction_of(mine[1]))) continue;
        const EdgeAtNode& arriving = first.position == 0 ? second : first;
        const EdgeAtNode& leaving = first.position == 0 ? first : second;
        push_edge(arriving, 0);
        chain.centre = chain.count - 1;
        push_edge(leaving, 1);
        p.n = (first.n + second.n).normalized();
      } else {
        // One edge: a corner on a symmetry line, the edge nearly perpendicular to the line; the
        // chain runs through the edge's mirror image.
        if (!symmetry.on_line(n)) continue;
        const bool z_line = symmetry.kind[n] == MirrorKind::z_line;
        const double along = z_line ? first.t.x() : first.t.y();  // the tangent's part along the line
        if (std::abs(along) > perpendicular_sin) continue;
        const double v = symmetry.value[n];
        const auto mirrored = [&](int node) {
          const Vec2 w = displacement_of(node);
          return z_line ? Vec2(w.x(), 2.0 * v - w.y()) : Vec2(2.0 * v - w.x(), w.y());
        };
        const bool leaves = first.position == 0;
        // Walk away from the node along the edge, then lay the images before (or after) it.
        std::array<int, max_edge_nodes> away{};
        for (int k = 0; k < first.count; ++k) away[static_cast<std::size_t>(k)] = first.nodes[static_cast<std::size_t>(leaves ? k : first.count - 1 - k)];
        const auto push_image = [&](int k) {
          const int node = away[static_cast<std::size_t>(k)];
          chain.push(symmetry.mirror_point(model, n, position_of(model, node)), mirrored(node));
        };
        const auto push_own = [&](int k) {
          const int node = away[static_cast<std::size_t>(k)];
          chain.push(position_of(model, node), displacement_of(node));
        };
        if (leaves) {
          for (int k = first.count - 1; k >= 1; --k) push_image(k);
          chain.centre = chain.count;
          for (int k = 0; k < first.count; ++k) push_own(k);
        } else {
          for (int k = first.count - 1; k >= 0; --k) push_own(k);
          chain.centre = chain.count - 1;
          for (int k = 1; k < first.count; ++k) push_image(k);
        }
      }
      const auto [stretch, t] = chain.stretch();
      p.stretch = stretch;
      p.t = t;
      // The normal perpendicular to the chain's tangent, on the outward side.
      const Vec2 normal(t.y(), -t.x());
      p.n = normal.dot(p.n) < 0.0 ? Vec2(-normal) : normal;
      out.push_back(p);
    }
  }
  return out;
}

/// The stress of a boundary point with law `law` and temperature rise dT (see the file comment):
/// the total strain eps solves
///   t_r^2 eps_rr + t_z^2 eps_zz + t_r t_z gamma_rz = stretch
///   w_n . (D eps - s0) = sigma_nn,   w_n = (n_r^2, n_z^2, 2 n_r n_z, 0)
///   w_t . (D eps - s0) = sigma_nt,   w_t = (t_r n_r, t_z n_z, t_r n_z + t_z n_r, 0)
///   eps_th = hoop                    (plane stress: any value, D does not read it)
/// with s0 = beta dT + D eps0; then sigma = D eps - s0. nullopt when the law leaves it undetermined.
std::optional<Vec4> boundary_stress(const BoundaryPoint& p, const Constitutive& law, double dT, double hoop) {
  Vec4 s0 = law.beta * dT;
  if (law.has_initial_strain()) s0 += law.D * law.initial_strain;
  const Vec2& t = p.t;
  const Vec2& n = p.n;
  const Vec4 w_n(n.x() * n.x(), n.y() * n.y(), 2.0 * n.x() * n.y(), 0.0);
  const Vec4 w_t(t.x() * n.x(), t.y() * n.y(), t.x() * n.y() + t.y() * n.x(), 0.0);
  Mat4 A = Mat4::Zero();
  Vec4 b = Vec4::Zero();
  A.row(0) << t.x() * t.x(), t.y() * t.y(), t.x() * t.y(), 0.0;
  b[0] = p.stretch;
  A.row(1) = w_n.transpose() * law.D;
  b[1] = p.traction.x() + w_n.dot(s0);
  A.row(2) = w_t.transpose() * law.D;
  b[2] = p.traction.y() + w_t.dot(s0);
  A(3, th) = 1.0;
  b[3] = hoop;
  const Eigen::FullPivLU<Mat4> lu(A);
  if (!lu.isInvertible()) return std::nullopt;
  return Vec4(law.D * lu.solve(b) - s0);
}

}  // namespace

std::vector<bool> traction_boundary_sides(const Model& model, const RecoveredField& field, const SymmetryLines& symmetry) {
  std::vector<bool> out(field.material.size(), false);
  for (const BoundaryPoint& p : boundary_points(model, field, symmetry, {})) out[p.side] = true;
  return out;
}

void recover_boundary_stresses(const Model& model, std::span<const double> displacement, const PointLawsOf& laws,
                               const SymmetryLines& symmetry, RecoveredField& field) {
  std::array<Constitutive, max_material_points> scratch;
  for (const BoundaryPoint& p : boundary_points(model, field, symmetry, displacement)) {
    const Element& el = model.elements[p.edge.element];
    const std::span<const Constitutive> point_laws = laws(p.edge.element, scratch);
    // The law of the material point nearest the node, in the reference cell.
    const auto a = static_cast<std::size_t>(std::find(el.nodes.begin(), el.nodes.end(), static_cast<int>(p.node)) - el.nodes.begin());
    std::size_t nearest = 0;
    if (point_laws.size() > 1) {
      const ElementFamily& f = family(el.type);
      const auto points = f.material_points(el.integration);
      const std::array<double, 2> x = f.node_positions[a];
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t q = 0; q < points.size() && q < point_laws.size(); ++q) {
        const double d = std::hypot(points[q].xi - x[0], points[q].eta - x[1]);
        if (d < best) {
          best = d;
          nearest = q;
        }
      }
    }
    // The node's temperature rise, as the kernels take it (element_data.cpp).
    const double dT = model.loads.node_temperature[p.node] - model.reference_temperature;
    const double hoop = model.analysis == AnalysisType::axisymmetric ? displacement[2 * p.node] / model.nodes[p.node].r : 0.0;
    if (const std::optional<Vec4> sigma = boundary_stress(p, point_laws[nearest], dT, hoop)) field.value[p.side] = *sigma;
  }
}

}  // namespace saasgaps
