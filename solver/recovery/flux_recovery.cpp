#include "solver/recovery/flux_recovery.hpp"

#include <Eigen/LU>
#include <cmath>

#include "solver/assembly/element_data.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/fe/element_geometry.hpp"
#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/recovery/patch_recovery.hpp"
#include "solver/recovery/symmetry_lines.hpp"

namespace saasgaps {

namespace {

/// A linear triangle of a report element: its vertices (indices into the element's corners, 4 the
/// centre), area and constant flux.
struct FluxTriangle {
  std::array<int, 3> vertex{};
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  Vec2 q = Vec2::Zero();
};

/// The triangles of a saas (four around the centre) or tri3 (one) element with temperatures t.
int flux_triangles(const ElementData& e, std::span<const double> t, const Eigen::Matrix2d& k,
                   std::array<Vec2, 5>& x, std::array<double, 5>& T, std::array<FluxTriangle, 4>& out) {
  for (int a = 0; a < e.node_count; ++a) {
    x[static_cast<std::size_t>(a)] = e.x[static_cast<std::size_t>(a)];
    T[static_cast<std::size_t>(a)] = t[static_cast<std::size_t>(a)];
  }
  int count = 0;
  auto add = [&](int i, int j, int m) {
    const Vec2& a = x[static_cast<std::size_t>(i)];
    const Vec2& b = x[static_cast<std::size_t>(j)];
    const Vec2& c = x[static_cast<std::size_t>(m)];
    const double twice = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    // grad T of the linear interpolant: (sum T_i (y_j - y_k), sum T_i (x_k - x_j)) / (2 A).
    const double Ti = T[static_cast<std::size_t>(i)], Tj = T[static_cast<std::size_t>(j)], Tm = T[static_cast<std::size_t>(m)];
    const Vec2 grad((Ti * (b.y() - c.y()) + Tj * (c.y() - a.y()) + Tm * (a.y() - b.y())) / twice,
                    (Ti * (c.x() - b.x()) + Tj * (a.x() - c.x()) + Tm * (b.x() - a.x())) / twice);
    FluxTriangle& f = out[static_cast<std::size_t>(count++)];
    f.vertex = {i, j, m};
    f.area = 0.5 * std::abs(twice);
    f.centroid = (a + b + c) / 3.0;
    f.q = -(k * grad);
  };
  if (e.node_count == 3) {
    add(0, 1, 2);
    return count;
  }
  x[4] = (x[0] + x[1] + x[2] + x[3]) / 4.0;
  T[4] = (T[0] + T[1] + T[2] + T[3]) / 4.0;
  for (int a = 0; a < 4; ++a) add(a, (a + 1) % 4, 4);
  return count;
}

/// The flux -k grad T at reference point (xi, eta) of an isoparametric element.
Vec2 point_flux(const PointGeometry& g, int nodes, std::span<const double> t, const Eigen::Matrix2d& k) {
  Vec2 grad = Vec2::Zero();
  for (int a = 0; a < nodes; ++a) {
    const auto i = static_cast<std::size_t>(a);
    grad += t[i] * Vec2(g.dN_dr[i], g.dN_dz[i]);
  }
  return -(k * grad);
}

std::span<const ReferencePoint> flux_sampling_rule(ElementType type) {
  static const double g = 1.0 / std::sqrt(3.0);
  static const std::array<ReferencePoint, 4> gauss2{{{-g, -g, 1.0}, {g, -g, 1.0}, {-g, g, 1.0}, {g, g, 1.0}}};
  static const std::array<ReferencePoint, 3> tri3pt{{{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                                     {1.0 / 6, 2.0 / 3, 1.0 / 6}}};
  if (type == ElementType::tri6) return tri3pt;
  return gauss2;
}

double energy(const Eigen::Matrix2d& k_inverse, const Vec2& q) { return q.dot(k_inverse * q); }

}  // namespace

FluxRecovery recover_heat_flux(const Model& model, std::span<const double> T, std::span<const Eigen::Matrix2d> k) {
  const std::size_t count = model.elements.size();
  auto element_T = [&](std::size_t e) {
    std::array<double, max_element_nodes> t{};
    const Element& el = model.elements[e];
    for (int a = 0; a < el.node_count; ++a) {
      t[static_cast<std::size_t>(a)] = T[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(a)])];
    }
    return t;
  };
  std::vector<ElementSamples> samples(count);
  for_each_range(count, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t e = begin; e < end; ++e) {
      const ElementData d = solid_element_geometry(model, e);
      const auto t = element_T(e);
      ElementSamples& s = samples[e];
      if (family(d.type).report_element) {
        std::array<Vec2, 5> x{};
        std::array<double, 5> Tv{};
        std::array<FluxTriangle, 4> tri;
        s.count = flux_triangles(d, t, k[e], x, Tv, tri);
        for (int i = 0; i < s.count; ++i) {
          const FluxTriangle& f = tri[static_cast<std::size_t>(i)];
          s.point[static_cast<std::size_t>(i)] = {f.centroid, Vec4(f.q.x(), f.q.y(), 0.0, 0.0)};
        }
        continue;
      }
      const auto rule = flux_sampling_rule(d.type);
      s.count = static_cast<int>(rule.size());
      for (std::size_t p = 0; p < rule.size(); ++p) {
        const PointGeometry g = point_geometry(d, rule[p].xi, rule[p].eta);
        const Vec2 q = point_flux(g, d.node_count, t, k[e]);
        s.point[p] = {Vec2(g.r, g.z), Vec4(q.x(), q.y(), 0.0, 0.0)};
      }
    }
  });
  FluxRecovery out;
  const SymmetryLines lines = heat_symmetry_lines(model);
  out.flux = recover_field(model, samples, &lines);
  std::vector<ElementError> errors(count);
  for_each_range(count, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t e = begin; e < end; ++e) {
      const ElementData d = solid_element_geometry(model, e);
      const auto t = element_T(e);
      const auto nodal = element_nodal_values(model, out.flux, e);
      const Eigen::Matrix2d k_inverse = k[e].inverse();
      const bool axisymmetric = d.analysis == AnalysisType::axisymmetric;
      ElementError& err = errors[e];
      if (family(d.type).report_element) {
        std::array<Vec2, 5> x{};
        std::array<double, 5> Tv{};
        std::array<FluxTriangle, 4> tri;
        const int n = flux_triangles(d, t, k[e], x, Tv, tri);
        std::array<Vec2, 5> v{};
        for (int a = 0; a < d.node_count; ++a) v[static_cast<std::size_t>(a)] = nodal[static_cast<std::size_t>(a)].head<2>();
        if (d.node_count == 4) v[4] = (v[0] + v[1] + v[2] + v[3]) / 4.0;
        for (int i = 0; i < n; ++i) {
          const FluxTriangle& f = tri[static_cast<std::size_t>(i)];
          const double w_centre = axisymmetric ? two_pi * f.centroid.x() * f.area : d.thickness * f.area;
          err.norm2 += w_centre * energy(k_inverse, f.q);
          // Edge-midpoint rule: exact for the quadratic integrand of a linear q* (axisymmetric: for
          // its product with r, which is cubic, the rule weights each midpoint by its own r).
          for (int j = 0; j < 3; ++j) {
            const auto a = static_cast<std::size_t>(f.vertex[static_cast<std::size_t>(j)]);
            const auto b = static_cast<std::size_t>(f.vertex[static_cast<std::size_t>((j + 1) % 3)]);
            const double w = axisymmetric ? two_pi * 0.5 * (x[a].x() + x[b].x()) * f.area / 3.0 : d.thickness * f.area / 3.0;
            err.error2 += w * energy(k_inverse, 0.5 * (v[a] + v[b]) - f.q);
          }
        }
        continue;
      }
      const auto rule = family(d.type).stiffness_rule(Integration::full);
      for (const ReferencePoint& p : rule) {
        const PointGeometry g = point_geometry(d, p.xi, p.eta);
        const double w = volume_weight(d, g, p.weight);
        const Vec2 q_h = point_flux(g, d.node_count, t, k[e]);
        Vec2 star = Vec2::Zero();
        for (int a = 0; a < d.node_count; ++a) {
          star += g.shape.N[static_cast<std::size_t>(a)] * nodal[static_cast<std::size_t>(a)].head<2>();
        }
        err.error2 += w * energy(k_inverse, star - q_h);
        err.norm2 += w * energy(k_inverse, q_h);
      }
    }
  });
  out.element_error.resize(count);
  for (std::size_t e = 0; e < count; ++e) out.element_error[e] = std::sqrt(errors[e].error2);
  out.estimate = total_error(errors);
  return out;
}

}  // namespace saasgaps
