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

/// A saas quad's corners and centre, their temperature rises, and its four triangles (i, i+1,
/// centre): made once for whichever of the system, the condensation and the states a call needs.
struct QuadTriangles {
  std::array<Vec2, 5> p;
  std::array<double, 5> dT;
  std::array<Triangle, 4> t;

  /// The mean temperature rise of triangle k.
  [[nodiscard]] double triangle_dT(std::size_t k) const {
    const auto& tri = quad_triangles[k];
    return (dT[tri[0]] + dT[tri[1]] + dT[tri[2]]) / 3.0;
  }
};

QuadTriangles quad_triangles_of(const ElementData& e) {
  QuadTriangles q{quad_points(corners(e)), quad_values(corner_dT(e)), {}};
  for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
    const auto& tri = quad_triangles[k];
    q.t[k] = make_triangle(q.p[tri[0]], q.p[tri[1]], q.p[tri[2]], e.analysis, e.thickness);
  }
  return q;
}

bool has_body_loads(const ElementData& e) { return e.body_force.x() != 0.0 || e.body_force.y() != 0.0 || e.spin != 0.0; }

/// The corner-and-centre system of a SAAS quad before condensation (DOFs 8, 9: centre).
struct QuadSystem {
  Mat10 K = Mat10::Zero();
  Vec10 f = Vec10::Zero();
};

QuadSystem quad_system(const ElementData& e) {
  const QuadTriangles q = quad_triangles_of(e);
  const bool loaded = has_body_loads(e);
  QuadSystem s;
  for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
    const auto& tri = quad_triangles[k];
    const Triangle& t = q.t[k];
    const Eigen::Matrix<double, 4, 6> DB = e.law_at(0).D * t.B;
    const Mat6 K = t.w * t.B.transpose() * DB;
    Vec6 f = (t.w * q.triangle_dT(k)) * (t.B.transpose() * e.law_at(0).beta);
    if (e.law_at(0).has_initial_strain()) f += initial_strain_loads(t.B, t.w, e);
    if (loaded) f += triangle_body_loads(q.p[tri[0]], q.p[tri[1]], q.p[tri[2]], t, e);
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) s.K.block<2, 2>(2 * tri[a], 2 * tri[b]) += K.block<2, 2>(2 * a, 2 * b);
      s.f.segment<2>(2 * tri[a]) += f.segment<2>(2 * a);
    }
  }
  return s;
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

/// The centre's rows of a SAAS quad's system (DOFs 8, 9), all that recovering its displacement
/// needs: [K_ce K_cc] (2 x 10) and f_c, the rows quad_system sums, without its corner blocks.
struct CentreRows {
  Eigen::Matrix<double, 2, 10> K = Eigen::Matrix<double, 2, 10>::Zero();
  Vec2 f = Vec2::Zero();
};

CentreRows centre_rows(const ElementData& e, const QuadTriangles& q) {
  const bool loaded = has_body_loads(e);
  CentreRows c;
  for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
    const auto& tri = quad_triangles[k];
    const Triangle& t = q.t[k];
    // The centre is each triangle's third vertex: its rows of w B^T D B are w B_c^T D B.
    assert(tri[2] == 4);
    const auto Bc = t.B.rightCols<2>();
    const Eigen::Matrix<double, 2, 6> K = t.w * Bc.transpose() * (e.law_at(0).D * t.B);
    Vec2 f = (t.w * q.triangle_dT(k)) * (Bc.transpose() * e.law_at(0).beta);
    if (e.law_at(0).has_initial_strain()) f += initial_strain_loads(t.B, t.w, e).tail<2>();
    if (loaded) f += triangle_body_loads(q.p[tri[0]], q.p[tri[1]], q.p[tri[2]], t, e).tail<2>();
    for (int a = 0; a < 3; ++a) c.K.block<2, 2>(0, 2 * tri[a]) += K.block<2, 2>(0, 2 * a);
    c.f += f;
  }
  return c;
}

/// The displacements of a saas quad's corners and condensed centre (10 values).
Vec10 quad_displacements(const ElementData& e, const QuadTriangles& q, const Vec8& u) {
  const CentreRows c = centre_rows(e, q);
  // Kce ue + Kcc uc = fc gives the condensed centre displacement back.
  const Vec2 uc = c.K.rightCols<2>().inverse() * (c.f - c.K.leftCols<8>() * u);
  Vec10 all;
  all << u, uc;
  return all;
}

/// Triangle k's six displacements from the quad's ten.
Vec6 triangle_displacements(std::size_t k, const Vec10& all) {
  Vec6 ut;
  for (int a = 0; a < 3; ++a) ut.segment<2>(2 * a) = all.segment<2>(2 * quad_triangles[k][static_cast<std::size_t>(a)]);
  return ut;
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
    const QuadTriangles q = quad_triangles_of(e);
    const Vec10 all = quad_displacements(e, q, u);
    for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
      accumulate_triangle_state(q.t[k], triangle_displacements(k, all), q.triangle_dT(k), e, sum);
      weight += q.t[k].w;
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
  const QuadTriangles q = quad_triangles_of(e);
  const Vec10 all = quad_displacements(e, q, u);
  for (std::size_t k = 0; k < quad_triangles.size(); ++k) {
    const auto& tri = quad_triangles[k];
    const Triangle& t = q.t[k];
    out[k] = {tri, (q.p[tri[0]] + q.p[tri[1]] + q.p[tri[2]]) / 3.0, t.area, t.w,
              triangle_state(t, triangle_displacements(k, all), q.triangle_dT(k), e)};
  }
  return 4;
}

}  // namespace saasgaps
