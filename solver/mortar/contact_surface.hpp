#pragma once
/// A contact surface (model format `contact.surfaces`): a chain of boundary edges of solid elements,
/// given as node-index pairs [a, b] in any order and direction: the chain, validated and oriented. Its
/// geometry (nodal normals, corners, the smooth curve through the nodes) is surface_geometry.hpp's;
/// docs/contact-surfaces.md.
///
/// Each edge must be a side of exactly one solid element (gap elements do not count: a face of a
/// solid that touches a gap element is still a boundary of the solid mesh). The edges must form one
/// chain, open or closed, with the material of every edge on the same side. The chain is oriented
/// with the material on its left (counter-clockwise around the body, as elements list their nodes),
/// so segment s runs nodes[s] -> nodes[s + 1] and its outward normal is the tangent turned clockwise:
///   n_s = (t_z, -t_r) / |t|,   t = x(nodes[s + 1]) - x(nodes[s]).
/// An open chain starts at its free end; a closed one at the first listed edge.
///
/// A 3-node edge (of tri6, quad8, quad9: named by its corners, its mid-side node goes with it) is
/// two segments of the chain, corner -> mid-side node -> corner, its two halves: the chain's nodes
/// are every node of the surface, mid-side nodes included, and a segment's normal is that of its
/// chord. The halves know their edge (half(), edge_nodes()): the mortar rows integrate over the edge's
/// quadratic curve and interpolate with its quadratic shape functions (docs/contact-surfaces.md,
/// section 7).

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "solver/base/errors.hpp"
#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Why an edge of a surface is refused.
enum class SurfaceEdgeProblem {
  empty,          ///< the surface has no edges (reported at edge 0)
  degenerate,     ///< both ends are the same node
  not_a_side,     ///< no solid element has a side joining the two nodes
  interior,       ///< a side of two or more solid elements: not on the boundary
  repeated,       ///< the same two nodes as an earlier edge (either direction)
  branch,         ///< a third edge at one node: the edges do not form a chain
  opposite_side,  ///< its element lies on the other side of the chain than its neighbour's
  disconnected,   ///< not on the chain of the first edge: the edges form more than one chain
};

/// The name of a problem as the io layer words it ("not a boundary edge", ...).
const char* describe(SurfaceEdgeProblem problem);

/// One refused edge: `edge` indexes the edge list given (the io layer turns it into the JSON Pointer
/// /contact/surfaces/<i>/edges/<edge>).
struct SurfaceEdgeIssue {
  std::size_t edge = 0;
  SurfaceEdgeProblem problem = SurfaceEdgeProblem::not_a_side;
  std::string detail;  ///< names the nodes (by user id) and elements involved
};

/// Every refused edge of one surface. Edge-level problems (degenerate .. repeated) are all reported;
/// chain-level ones (branch, opposite_side, disconnected) only when every edge passed, and only the
/// first one found, since one misplaced edge makes the rest of the chain ambiguous.
class ContactSurfaceError : public SolverError {
 public:
  explicit ContactSurfaceError(std::vector<SurfaceEdgeIssue> issues);
  [[nodiscard]] const std::vector<SurfaceEdgeIssue>& issues() const { return issues_; }

 private:
  std::vector<SurfaceEdgeIssue> issues_;
};

struct ContactSurface {
  std::vector<int> nodes;          ///< node indices along the chain; a closed chain does not repeat nodes[0]
  bool closed = false;
  std::vector<int> element;        ///< per segment: the solid element (index) whose side it is
  std::vector<std::size_t> edge;   ///< per segment: index into the edge list given
  std::vector<Vec2> normal;        ///< per segment: unit outward normal of its element (of its chord)
  /// Per segment: -1 for a straight 2-node edge; 0 or 1 for the first or second half of a 3-node edge
  /// (corner -> mid-side node, mid-side node -> corner). Empty when every edge is straight.
  std::vector<std::int8_t> halves;

  [[nodiscard]] std::size_t segment_count() const { return element.size(); }
  /// Node indices of segment s, in chain order.
  [[nodiscard]] std::array<int, 2> segment(std::size_t s) const {
    return {nodes[s], nodes[(s + 1) % nodes.size()]};
  }
  /// -1 when segment s is a straight edge, else which half of its 3-node edge it is.
  [[nodiscard]] int half(std::size_t s) const { return halves.empty() ? -1 : halves[s]; }
  /// Chain positions (indices into `nodes`) of the 3-node edge segment s is a half of: corner,
  /// mid-side node, corner in chain order. Only for segments with half(s) >= 0.
  [[nodiscard]] std::array<std::size_t, 3> edge_positions(std::size_t s) const {
    const std::size_t n = nodes.size();
    const std::size_t first = half(s) == 0 ? s : (s + n - 1) % n;
    return {first, (first + 1) % n, (first + 2) % n};
  }
  /// Whether chain position j is the mid-side node of a 3-node edge.
  [[nodiscard]] bool mid_side(std::size_t j) const { return j < element.size() && half(j) == 1; }
};

/// The position (r, z) of node i.
inline Vec2 node_position(const std::vector<Node>& nodes, int i) {
  const Node& n = nodes[static_cast<std::size_t>(i)];
  return {n.r, n.z};
}

/// Validates and orients the chain. Node indices must be valid (the io layer resolves ids).
/// Throws ContactSurfaceError naming every refused edge.
ContactSurface contact_surface(const Model& model, std::span<const std::array<int, 2>> edges);

}  // namespace saasgaps
