#pragma once
/// Heat conduction on the element families with shape functions of their own: tri6, quad8, quad9
/// (isoparametric, curved edges allowed) and quad4i (the bilinear quadrilateral; a temperature
/// needs no incompatible modes). The report's elements keep conduction_kernel.hpp.
///
/// At each point of the conduction rule, with the family's shape functions N_a and their (r, z)
/// gradients G (isoparametric_kernel.hpp's point geometry) and dV = w det J t (plane) or
/// w det J 2 pi r (axisymmetric, the full ring):
///   K = sum G^T k G dV                      conductance (k the (r, z) tensor of Conductivity)
///   C = sum N N^T dV                        consistent capacity (times density c; never lumped:
///                                           quad8's row sums are negative at its corners)
///   s = sum N dV                            a uniform source's consistent nodal weights
/// The conduction rule: triangles the 6-point rule of degree 4 (exact for K and C of a straight-sided
/// tri6 in plane; for the source in axisymmetry), quad8 and quad9 3 x 3 Gauss (exact for K, C and s of
/// a parallelogram, plane or axisymmetric), quad4i 2 x 2 (exact for the bilinear element's K, C, s).
/// An element's `integration` setting is its stiffness's; its conduction always uses these rules.
///
/// Edges of 3 nodes (a, m, b) are the quadratic curve through them (edge_loads.hpp); films and
/// fluxes on them are integrated along that curve with its own shape functions by 4-point Gauss:
///   film:  K_ab = h sum N_a N_b dS,  f_a = h T_ambient sum N_a dS;   flux: f_a = q sum N_a dS,
/// dS = w |dx/ds| t or w |dx/ds| 2 pi r (edge_area_weight).

#include <array>
#include <span>

#include <Eigen/Core>

#include "solver/base/voigt.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/model/model.hpp"
#include "solver/thermal/conduction_kernel.hpp"

namespace saasgaps {

/// Whether elements of this type conduct here (tri6, quad8, quad9, quad4i), not in conduction_kernel.hpp.
bool conducts_isoparametrically(ElementType type);

/// The points the conduction of a family is integrated with (see the file comment).
std::span<const ReferencePoint> conduction_rule(ElementType type);

using ConductionMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, max_element_nodes, max_element_nodes>;
using ConductionVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, max_element_nodes, 1>;

/// Everything the kernel depends on: the family, its nodes (r, z) in the family's order, the analysis.
struct IsoConductionData {
  ElementType type = ElementType::quad8;
  int node_count = 8;
  std::array<Vec2, max_element_nodes> x{};
  AnalysisType analysis = AnalysisType::plane_stress;
  double thickness = 1.0;
  Conductivity k;
};

/// The element's conductance, capacity and source weights (n x n, n x n, n; n = node_count).
struct IsoConductionParts {
  ConductionMatrix K;
  ConductionMatrix C;
  ConductionVector source;  ///< sum N dV: times the power density, the source's nodal heat
};
IsoConductionParts isoparametric_conduction_parts(const IsoConductionData& e);

/// The element block of one conduction solve, as conduction_block's:
///   A = K + m C,  f = source s + m C T_previous   (m = density c / dt, 0 in a steady solve).
struct IsoConductionBlock {
  ConductionMatrix K;
  ConductionVector f;
};
IsoConductionBlock isoparametric_conduction_block(const IsoConductionData& e, const ConductionLoad& load);
/// The same from the element's parts.
IsoConductionBlock isoparametric_conduction_block(const IsoConductionParts& parts, const ConductionLoad& load);

/// f of isoparametric_conduction_block from the parts it depends on (C, source; K is not read): the
/// same operations, so the same bits, without the kernel.
ConductionVector isoparametric_conduction_load(const ConductionMatrix& C, const ConductionVector& source,
                                               const ConductionLoad& load);

/// The heat flux q = -k grad T at the element's reference centre (power / area); T one per node.
Vec2 isoparametric_conduction_flux(const IsoConductionData& e, std::span<const double> T);

/// sum N_a dS along the edge through `nodes` (2 or 3, from a to b): the nodal weights of a uniform flux.
std::array<double, max_edge_nodes> edge_flux_weights(const std::array<Vec2, max_edge_nodes>& nodes, int count,
                                                     AnalysisType analysis, double thickness);

/// A film h to ambient T_a on the edge through `nodes`: K_ab = h sum N_a N_b dS, f_a = h T_a sum N_a dS.
struct CurvedEdgeBlock {
  Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
};
CurvedEdgeBlock curved_film_block(const std::array<Vec2, max_edge_nodes>& nodes, int count, AnalysisType analysis,
                                  double thickness, double film, double ambient);

}  // namespace saasgaps
