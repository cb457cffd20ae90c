#pragma once
/// A solid element of a result as its family maps it (solver/fe/element_family.hpp): its nodes in
/// the family's order, its shape functions N_a(xi, eta), the map x(xi, eta) = sum_a N_a x_a of the
/// reference cell onto the element (curved edges through the mid-side nodes included), the inverse
/// of that map at a point, and the reference cell cut into triangles for drawing.
///
/// The family comes from the node count, as a result names no family: 3 tri3, 4 saas (piecewise
/// linear on its four triangles, the centre the mean of the corners; a quad4i is drawn the same,
/// which differs from its bilinear map inside only), 6 tri6, 8 quad8, 9 quad9.

#include <array>
#include <optional>
#include <vector>

#include "plot/result/point_locator.hpp"
#include "plot/result/result_mesh.hpp"
#include "solver/fe/element_family.hpp"

namespace saasgaps::plot {

/// The family a solid element of a result is drawn and probed with (see above).
const ElementFamily& element_family(const SolidElement& e);

/// The element's node indices in the family's order (corners, mid-sides, centre).
std::vector<int> family_nodes(const SolidElement& e);

/// The reference point of element e (node positions = the mesh's undeformed coordinates) that maps
/// to (r, z), by Newton's method from the cell's centre; none when (r, z) is not in the element
/// (the reference point lies outside the cell by more than reference_slack, or Newton does not
/// converge: the point is far outside).
std::optional<ReferenceCoordinates> inverse_map(const ResultMesh& mesh, const SolidElement& e, double r, double z);

/// The reference cell cut into small triangles for drawing: `points` and triangles of indices into
/// them, counter-clockwise. A triangle cell in n x n triangles; a quadrilateral cell in n x n
/// squares, each split along the diagonal that points at the centre (so that with n even the
/// triangles of a saas element's four pieces are never cut: its interpolation is exact on them).
struct Subdivision {
  std::vector<ReferenceCoordinates> points;
  std::vector<std::array<int, 3>> triangles;
};
Subdivision subdivide(CellShape cell, int n);

/// The subdivision a picture draws a family with: n = 1 for tri3, 2 for saas (its four pieces), 4
/// for the quadratic families (curved edges in four straight pieces; quadratic values between
/// sub-vertices drawn linearly), 2 for those above `many` elements (memory and time).
const Subdivision& drawing_subdivision(const ElementFamily& family, bool many);

/// The straight pieces an edge of the family is drawn with, those of its drawing subdivision's
/// boundary (1 for the straight edges of tri3, saas and quad4i), so that outlines and mesh lines
/// run along the filled bands' edges.
int drawing_edge_pieces(const ElementFamily& family, bool many);

}  // namespace saasgaps::plot
