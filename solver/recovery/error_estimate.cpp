#include "solver/recovery/error_estimate.hpp"

#include <Eigen/LU>  // inverse
#include <cassert>
#include <cmath>

#include "solver/fe/element_family.hpp"
#include "solver/fe/element_geometry.hpp"
#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/fe/saas_kernel.hpp"

namespace saasgaps {

double complementary_energy_density(const Mat4& D, AnalysisType analysis, const Vec4& sigma) {
  if (analysis == AnalysisType::axisymmetric) return sigma.dot(D.partialPivLu().solve(sigma));
  const Eigen::Matrix3d Dp = D.topLeftCorner<3, 3>();
  const Eigen::Vector3d s = sigma.head<3>();
  return s.dot(Dp.partialPivLu().solve(s));
}

namespace {

/// The compliance C of the file comment, so that sigma : D^-1 : sigma = sigma . C sigma: inverted
/// once per law rather than factorized for every point it is evaluated at.
Mat4 compliance(const Mat4& D, AnalysisType analysis) {
  if (analysis == AnalysisType::axisymmetric) return D.inverse();
  Mat4 C = Mat4::Zero();
  C.topLeftCorner<3, 3>() = D.topLeftCorner<3, 3>().inverse();
  return C;
}

double energy(const Mat4& C, const Vec4& sigma) { return sigma.dot(C * sigma); }

/// A report element's integrals over its constant-strain triangles (saas_triangle_states' geometry
/// and stresses), C its law's compliance.
ElementError triangles_error(const ElementData& e, const Mat4& C, std::span<const TriangleState> tri,
                             std::span<const Vec4> nodal) {
  ElementError out;
  // Vertex values: the corners' recovered stresses and, for a quad, their mean at the centre.
  std::array<Vec4, 5> v{};
  std::array<Vec2, 5> x{};
  for (int a = 0; a < e.node_count; ++a) {
    v[static_cast<std::size_t>(a)] = nodal[static_cast<std::size_t>(a)];
    x[static_cast<std::size_t>(a)] = e.x[static_cast<std::size_t>(a)];
  }
  if (e.node_count == 4) {
    v[4] = (v[0] + v[1] + v[2] + v[3]) / 4.0;
    x[4] = (x[0] + x[1] + x[2] + x[3]) / 4.0;
  }
  for (const TriangleState& t : tri) {
    const Vec4& sigma_h = t.state.stress;
    out.norm2 += t.w * energy(C, sigma_h);
    for (int i = 0; i < 3; ++i) {
      const auto a = static_cast<std::size_t>(t.vertex[static_cast<std::size_t>(i)]);
      const auto b = static_cast<std::size_t>(t.vertex[static_cast<std::size_t>((i + 1) % 3)]);
      const Vec4 diff = 0.5 * (v[a] + v[b]) - sigma_h;
      const double w = e.analysis == AnalysisType::axisymmetric
                           ? two_pi * 0.5 * (x[a].x() + x[b].x()) * t.area / 3.0
                           : t.w / 3.0;
      out.error2 += w * energy(C, diff);
    }
  }
  return out;
}

/// An isoparametric element's integrals at its material points (states: their stresses), D_of(p)
/// the law of point p; the compliance is inverted again only where the law changes.
template <class LawOf>
ElementError points_error(const ElementData& e, const LawOf& D_of, std::span<const ElementState> states,
                          std::span<const Vec4> nodal) {
  ElementError out;
  const auto rule = family(e.type).material_points(e.integration);
  Mat4 D_last;
  Mat4 C;
  for (std::size_t p = 0; p < rule.size(); ++p) {
    const PointGeometry g = point_geometry(e, rule[p].xi, rule[p].eta);
    const double w = volume_weight(e, g, rule[p].weight);
    Vec4 star = Vec4::Zero();
    for (int a = 0; a < e.node_count; ++a) star += g.shape.N[static_cast<std::size_t>(a)] * nodal[static_cast<std::size_t>(a)];
    const Vec4& sigma_h = states[p].stress;
    const Mat4& D = D_of(p);
    if (p == 0 || D != D_last) {
      D_last = D;
      C = compliance(D, e.analysis);
    }
    out.error2 += w * energy(C, star - sigma_h);
    out.norm2 += w * energy(C, sigma_h);
  }
  return out;
}

}  // namespace

ElementError report_element_error(const ElementData& e, std::span<const double> u, std::span<const Vec4> nodal) {
  assert(family(e.type).report_element);
  std::array<TriangleState, 4> tri;
  const int count = saas_triangle_states(e, u, tri);
  return triangles_error(e, compliance(e.law_at(0).D, e.analysis),
                         std::span<const TriangleState>(tri).first(static_cast<std::size_t>(count)), nodal);
}

ElementError element_error(const ElementData& e, const ElementStates& states, std::span<const double> u,
                           std::span<const Vec4> nodal) {
  if (family(e.type).report_element) return report_element_error(e, u, nodal);
  return points_error(
      e, [&](std::size_t p) -> const Mat4& { return e.law_at(static_cast<int>(p)).D; },
      std::span<const ElementState>(states.point).first(static_cast<std::size_t>(states.point_count)), nodal);
}

ElementError element_error(const ElementData& geometry, std::span<const Constitutive> laws,
                           std::span<const ElementState> point_states, std::span<const Vec4> nodal) {
  assert(!family(geometry.type).report_element);
  return points_error(
      geometry, [&](std::size_t p) -> const Mat4& { return (laws.size() == 1 ? laws.front() : laws[p]).D; },
      point_states, nodal);
}

ErrorEstimate total_error(std::span<const ElementError> elements) {
  double e2 = 0.0;
  double n2 = 0.0;
  for (const ElementError& e : elements) {
    e2 += e.error2;
    n2 += e.norm2;
  }
  ErrorEstimate t;
  t.error = std::sqrt(e2);
  t.energy_norm = std::sqrt(n2);
  t.relative = e2 + n2 > 0.0 ? std::sqrt(e2 / (n2 + e2)) : 0.0;
  return t;
}

}  // namespace saasgaps
