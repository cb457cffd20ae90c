#include "solver/thermal/isoparametric_conduction.hpp"

#include <cassert>

#include "solver/fe/edge_loads.hpp"
#include "solver/fe/isoparametric_kernel.hpp"
#include "solver/fe/quadrature.hpp"

namespace saasgaps {

bool conducts_isoparametrically(ElementType type) { return type != ElementType::saas && type != ElementType::tri3; }

std::span<const ReferencePoint> conduction_rule(ElementType type) {
  const ElementFamily& f = family(type);
  assert(conducts_isoparametrically(type));
  if (f.cell == CellShape::triangle) return gauss_triangle(6);
  return gauss_square(f.quadratic() ? 3 : 2);
}

namespace {

PointGeometry geometry(const IsoConductionData& e, const ReferencePoint& p) {
  return point_geometry(e.type, e.node_count, e.x, p.xi, p.eta);
}

double area_weight(const IsoConductionData& e, const PointGeometry& g, double weight) {
  return weight * g.det_J * (e.analysis == AnalysisType::axisymmetric ? two_pi * g.r : e.thickness);
}

}  // namespace

IsoConductionParts isoparametric_conduction_parts(const IsoConductionData& e) {
  const int n = e.node_count;
  const Eigen::Matrix2d k = e.k.tensor();
  IsoConductionParts parts;
  parts.K = ConductionMatrix::Zero(n, n);
  parts.C = ConductionMatrix::Zero(n, n);
  parts.source = ConductionVector::Zero(n);
  Eigen::Matrix<double, 2, Eigen::Dynamic, Eigen::ColMajor, 2, max_element_nodes> G(2, n);
  ConductionVector N(n);
  for (const ReferencePoint& p : conduction_rule(e.type)) {
    const PointGeometry g = geometry(e, p);
    const double w = area_weight(e, g, p.weight);
    for (int a = 0; a < n; ++a) {
      const auto i = static_cast<std::size_t>(a);
      G(0, a) = g.dN_dr[i];
      G(1, a) = g.dN_dz[i];
      N[a] = g.shape.N[i];
    }
    parts.K.noalias() += (w * G.transpose()) * (k * G);
    parts.C.noalias() += (w * N) * N.transpose();
    parts.source += w * N;
  }
  return parts;
}

ConductionVector isoparametric_conduction_load(const ConductionMatrix& C, const ConductionVector& source,
                                               const ConductionLoad& load) {
  ConductionVector f = load.source * source;
  if (load.capacity_rate > 0.0) {
    const Eigen::Map<const Eigen::VectorXd> previous(load.previous.data(), source.size());
    f += load.capacity_rate * (C * previous);
  }
  return f;
}

IsoConductionBlock isoparametric_conduction_block(const IsoConductionParts& parts, const ConductionLoad& load) {
  IsoConductionBlock out;
  out.K = parts.K;
  if (load.capacity_rate > 0.0) out.K += load.capacity_rate * parts.C;
  out.f = isoparametric_conduction_load(parts.C, parts.source, load);
  return out;
}

IsoConductionBlock isoparametric_conduction_block(const IsoConductionData& e, const ConductionLoad& load) {
  return isoparametric_conduction_block(isoparametric_conduction_parts(e), load);
}

Vec2 isoparametric_conduction_flux(const IsoConductionData& e, std::span<const double> T) {
  const auto c = reference_centre(family(e.type).cell);
  const PointGeometry g = point_geometry(e.type, e.node_count, e.x, c[0], c[1]);
  Vec2 gradient = Vec2::Zero();
  for (int a = 0; a < e.node_count; ++a) {
    const auto i = static_cast<std::size_t>(a);
    gradient += Vec2(g.dN_dr[i], g.dN_dz[i]) * T[i];
  }
  return -(e.k.tensor() * gradient);
}

std::array<double, max_edge_nodes> edge_flux_weights(const std::array<Vec2, max_edge_nodes>& nodes, int count,
                                                     AnalysisType analysis, double thickness) {
  std::array<double, max_edge_nodes> w{};
  for (const EdgePoint& p : edge_points(nodes, count)) {
    const double dS = edge_area_weight(p, analysis, thickness);
    for (std::size_t a = 0; a < static_cast<std::size_t>(count); ++a) w[a] += dS * p.N[a];
  }
  return w;
}

CurvedEdgeBlock curved_film_block(const std::array<Vec2, max_edge_nodes>& nodes, int count, AnalysisType analysis,
                                  double thickness, double film, double ambient) {
  CurvedEdgeBlock out;
  for (const EdgePoint& p : edge_points(nodes, count)) {
    const double dS = edge_area_weight(p, analysis, thickness);
    for (int a = 0; a < count; ++a) {
      const double wa = dS * p.N[static_cast<std::size_t>(a)];
      out.f[a] += film * ambient * wa;
      for (int b = 0; b < count; ++b) out.K(a, b) += film * wa * p.N[static_cast<std::size_t>(b)];
    }
  }
  return out;
}

}  // namespace saasgaps
