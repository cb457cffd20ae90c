#include "solver/fe/saas_kernel.hpp"

#include <cassert>

#include "solver/fe/element_geometry.hpp"

namespace saasgaps {

namespace {

using Mat46 = Eigen::Matrix<double, 4, 6>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat10 = Eigen::Matrix<double, 10, 10>;
using Vec10 = Eigen::Matrix<double, 10, 1>;

/// One constant-strain triangle: strain = B u over its 6 DOFs, volume weight w.
struct Triangle {
  Mat46 B = Mat46::Zero();
  double w = 0.0;
  double area = 0.0;
  double r_centroid = 0.0;
};

Triangle make_triangle(const Vec2& p0, const Vec2& p1, const Vec2& p2, AnalysisType analysis,
                       double thickness) {
  const LinearTriangle g = linear_triangle(p0, p1, p2, analysis, thickness);
  Triangle t;
  t.area = g.area;
  t.r_centroid = g.r_centroid;
  t.w = g.w;
  for (int i = 0; i < 3; ++i) {
    t.B(rr, 2 * i) = g.dN_dr[i];
    t.B(zz, 2 * i + 1) = g.dN_dz[i];
    t.B(rz, 2 * i) = g.dN_dz[i];
    t.B(rz, 2 * i + 1) = g.dN_dr[i];
  }
  if (analysis == AnalysisType::axisymmetric) {
    // Hoop strain u/r at the centroid, where every N_i = 1/3.
    for (int i = 0; i < 3; ++i) t.B(th, 2 * i) = 1.0 / (3.0 * t.r_centroid);
  }
  return t;
}

/// Body-force loads of one triangle: integral of N_i b dV, with b = body + spin * r e_r.
Vec6 triangle_body_loads(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Triangle& t,
                         const ElementData& e) {
  Vec6 f = Vec6::Zero();
  const std::array<double, 3> r{p0.x(), p1.x(), p2.x()};
  const double sum = r[0] + r[1] + r[2];
  const double squares = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const double products = r[0] * r[1] + r[1] * r[2] + r[0] * r[2];
  for (int i = 0; i < 3; ++i) {
    if (e.analysis == AnalysisType::axisymmetric) {
      // int N_i r dA = A (sum r + r_i) / 12;  int N_i r^2 dA = A (sum r^2 + sum r_j r_k + r_i (r_i + sum r)) / 30
      const double n_r = t.area * (sum + r[i]) / 12.0;
      const double n_r2 = t.area * (squares + products + r[i] * (r[i] + sum)) / 30.0;
      f[2 * i] = two_pi * (e.body_force.x() * n_r + e.spin * n_r2);
      f[2 * i + 1] = two_pi * e.body_force.y() * n_r;
    } else {
      f[2 * i] = e.body_force.x() * t.w / 3.0;
      f[2 * i + 1] = e.body_force.y() * t.w / 3.0;
    }
  }
  return f;
}

/// Loads of the initial strain eps0 over strain-displacement B and weight w: w B^T D eps0, the
/// same path as the thermal strain's w B^T beta dT. Called only for a law that has one, so that
/// every other element's loads are computed exactly as before.
Vec6 initial_strain_loads(const Mat46& B, double w, const ElementData& e) {
  return w * (B.transpose() * (e.law_at(0).D * e.law_at(0).initial_strain));
}

/// The corners of a saas quad, and their temperature rises, as the four-triangle geometry takes them.
std::array<Vec2, 4> corners(const ElementData& e) { return {e.x[0], e.x[1], e.x[2], e.x[3]}; }
std::array<double, 4> corner_dT(const ElementData& e) { return {e.dT[0], e.dT[1], e.dT[2], e.dT[3]}; }

/// The corner-and-centre system of a SAAS quad before condensation (DOFs 8, 9: centre).
struct QuadSystem {
  Mat10 K = Mat10::Zero();
  Vec10 f = Vec10::Zero();
};

QuadSystem quad_system(const ElementData& e) {
  const auto p = quad_points(corners(e));
  const auto dT = quad_values(corner_dT(e));
  const bool loaded = e.body_force.x() != 0.0 || e.body_force.y() != 0.0 || e.spin != 0.0;
  QuadSystem q;
  for (const auto& tri : quad_triangles) {
    const Triangle t = make_triangle(p[tri[0]], p[tri[1]], p[tri[2]], e.analysis, e.thickness);
    const Eigen::Matrix<double, 4, 6> DB = e.law_at(0).D * t.B;
    const Mat6 k = t.w * t.B.transpose() * DB;
    const double dT_tri = (dT[tri[0]] + dT[tri[1]] + dT[tri[2]]) / 3.0;
    Vec6 f = (t.w * dT_tri) * (t.B.transpose() * e.law_at(0).beta);
    if (e.law_at(0).has_initial_strain()) f += initial_strain_loads(t.B, t.w, e);
    if (loaded) f += triangle_body_loads(p[tri[0]], p[tri[1]], p[tri[2]], t, e);
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) q.K.block<2, 2>(2 * tri[a], 2 * tri[b]) += k.block<2, 2>(2 * a, 2 * b);
      q.f.segment<2>(2 * tri[a]) += f.segment<2>(2 * a);
    }
  }
  return q;
}

/// Stiffness of a lone axisymmetric triangle. Its hoop strain u/r varies over the triangle; taken
/// only at the centroid it leaves a spurious zero-energy mode (rank 4 of 6), so a lone triangle
/// samples it at the three interior Gauss points (barycentric 2/3, 1/6, 1/6; never on the axis).
/// Inside the SAAS quad the centroid rule is kept: there the four triangles constrain each other.
Mat6 axisymmetric_triangle_stiffness(const ElementData& e, const Triangle& centroid, Vec6& thermal, double dT) {
  Mat6 k = Mat6::Zero();
  thermal.setZero();
  for (int q = 0; q < 3; ++q) {
    std::array<double, 3> N{1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
    N[q] = 2.0 / 3.0;
    const double r = N[0] * e.x[0].x() + N[1] * e.x[1].x() + N[2] * e.x[2].x();
    Mat46 B = centroid.B;
    for (int i = 0; i < 3; ++i) B(th, 2 * i) = N[i] / r;
    const double w = two_pi * r * centroid.area / 3.0;
    k += w * B.transpose() * (e.law_at(0).D * B);
    thermal += (w * dT) * (B.transpose() * e.law_at(0).beta);
    if (e.law_at(0).has_initial_strain()) thermal += initial_strain_loads(B, w, e);
  }
  return k;
}

/// A triangle's 6 x 6 block and loads.
struct Triangle6 {
  Mat6 K = Mat6::Zero();
  Vec6 f = Vec6::Zero();
};

Triangle6 triangle_matrices(const ElementData& e) {
  const Triangle t = make_triangle(e.x[0], e.x[1], e.x[2], e.analysis, e.thickness);
  const double dT_tri = (e.dT[0] + e.dT[1] + e.dT[2]) / 3.0;
  Triangle6 m;
  Vec6 f;
  if (e.analysis == AnalysisType::axisymmetric) {
    m.K = axisymmetric_triangle_stiffness(e, t, f, dT_tri);
  } else {
    m.K = t.w * t.B.transpose() * (e.law_at(0).D * t.B);
    f = (t.w * dT_tri) * (t.B.transpose() * e.law_at(0).beta);
    if (e.law_at(0).has_initial_strain()) f += initial_strain_loads(t.B, t.w, e);
  }
  f += triangle_body_loads(e.x[0], e.x[1], e.x[2], t, e);
  m.f = f;
  return m;
}

/// Stress and total strain of one triangle with displacements u (6), temperature rise dT.
ElementState triangle_state(const Triangle& t, const Vec6& u, double dT, const ElementData& e) {
  ElementState s;
  s.strain = t.B * u;
  s.stress = e.law_at(0).D * s.strain - e.law_at(0).beta * dT;
  if (e.law_at(0).has_initial_strain()) s.stress -= e.law_at(0).D * e.law_at(0).initial_strain;
  if (e.analysis == AnalysisType::plane_stress) {
    s.strain[th] = e.law_at(0).out_of_plane.dot(s.stress) + e.law_at(0).alpha3 * dT;
    if (e.law_at(0).has_initial_strain()) s.strain[th] += e.law_at(0).initial_strain[th];
  }
  return s;
}

void accumulate_triangle_state(const Triangle& t, const Vec6& u, double dT, const ElementData& e,
                               ElementState& sum) {
  const ElementState s = triangle_state(t, u, dT, e);
  sum.strain += t.w * s.strain;
  sum.stress += t.w * s.stress;
}

/// The displacements of a saas quad's corners and condensed centre (10 values).
Vec10 quad_displacements(const ElementData& e, const Vec8& u) {
  const QuadSystem q = quad_system(e);
  // Kce ue + Kcc uc = fc gives the condensed centre displacement back.
  const Vec2 uc = q.K.bottomRightCorner<2, 2>().inverse() * (q.f.tail<2>() - q.K.bottomLeftCorner<2, 8>() * u);
  Vec10 all;
  all << u, uc;
  return all;
}

}  // namespace

ElementMatrices saas_matrices(const ElementData& e) {
  ElementMatrices m;
  if (e.node_count == 3) {
    const Triangle6 t = triangle_matrices(e);
    m.K = t.K;
    m.f = t.f;
    return m;
  }
  const QuadSystem q = quad_system(e);
  const Condensed<8, 2> c = condense<8, 2>(q.K, q.f);
  Mat8 K = c.K;
  // In place, as it always was: Eigen evaluates this without a temporary, so entries written first
  // feed the later ones; only the upper triangle is assembled and the results are pinned to it.
  K = 0.5 * (K + K.transpose());
  m.K = K;
  m.f = c.f;
  return m;
}

ElementStates saas_states(const ElementData& e, std::span<const double> u_span) {
  Vec8 u = Vec8::Zero();
  for (int i = 0; i < e.dof_count(); ++i) u[i] = u_span[static_cast<std::size_t>(i)];
  ElementState sum;
  double weight = 0.0;
  if (e.node_count == 3) {
    const Triangle t = make_triangle(e.x[0], e.x[1], e.x[2], e.analysis, e.thickness);
    accumulate_triangle_state(t, u.head<6>(), (e.dT[0] + e.dT[1] + e.dT[2]) / 3.0, e, sum);
    weight = t.w;
  } else {
    const Vec10 all = quad_displacements(e, u);
    const auto p = quad_points(corners(e));
    const auto dT = quad_values(corner_dT(e));
    for (const auto& tri : quad_triangles) {
      const Triangle t = make_triangle(p[tri[0]], p[tri[1]], p[tri[2]], e.analysis, e.thickness);
      Vec6 ut;
      for (int a = 0; a < 3; ++a) ut.segment<2>(2 * a) = all.segment<2>(2 * tri[a]);
      accumulate_triangle_state(t, ut, (dT[tri[0]] + dT[tri[1]] + dT[tri[2]]) / 3.0, e, sum);
      weight += t.w;
    }
  }
  sum.strain /= weight;
  sum.stress /= weight;
  ElementStates out;
  out.point_count = 1;
  out.point[0] = sum;
  out.centre = sum;
  return out;
}

int saas_triangle_states(const ElementData& e, std::span<const double> u_span, std::array<TriangleState, 4>& out) {
  Vec8 u = Vec8::Zero();
  for (int i = 0; i < e.dof_count(); ++i) u[i] = u_span[static_cast<std::size_t>(i)];
  if (e.node_count == 3) {
    const Triangle t = make_triangle(e.x[0], e.x[1], e.x[2], e.analysis, e.thickness);
    out[0] = {{0, 1, 2}, (e.x[0] + e.x[1] + e.x[2]) / 3.0, t.area, t.w,
              triangle_state(t, u.head<6>(), (e.dT[0] + e.dT[1] + e.dT[2]) / 3.0, e)};
    return 1;
  }
  const Vec10 all = quad_displacements(e, u);
  const auto p = quad_points(corners(e));
  const auto dT = quad_values(corner_dT(e));
  for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
    const auto& tri = quad_triangles[k];
    const Triangle t = make_triangle(p[tri[0]], p[tri[1]], p[tri[2]], e.analysis, e.thickness);
    Vec6 ut;
    for (int a = 0; a < 3; ++a) ut.segment<2>(2 * a) = all.segment<2>(2 * tri[a]);
    out[k] = {tri, (p[tri[0]] + p[tri[1]] + p[tri[2]]) / 3.0, t.area, t.w,
              triangle_state(t, ut, (dT[tri[0]] + dT[tri[1]] + dT[tri[2]]) / 3.0, e)};
  }
  return 4;
}

int saas_triangles(const ElementData& e, std::array<TriangleState, 4>& out) {
  if (e.node_count == 3) {
    const LinearTriangle g = linear_triangle(e.x[0], e.x[1], e.x[2], e.analysis, e.thickness);
    out[0] = {{0, 1, 2}, (e.x[0] + e.x[1] + e.x[2]) / 3.0, g.area, g.w, {}};
    return 1;
  }
  const auto p = quad_points(corners(e));
  for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
    const auto& tri = quad_triangles[k];
    const LinearTriangle g = linear_triangle(p[tri[0]], p[tri[1]], p[tri[2]], e.analysis, e.thickness);
    out[k] = {tri, (p[tri[0]] + p[tri[1]] + p[tri[2]]) / 3.0, g.area, g.w, {}};
  }
  return 4;
}

}  // namespace saasgaps
