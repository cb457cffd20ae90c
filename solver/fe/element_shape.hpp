#pragma once
/// Whether an element's nodes make an element its family can integrate: the corners counter-
/// clockwise around a positive area, each mid-side node near the middle of its edge, and (for the
/// isoparametric families) det J > 0 at every point of the stiffness rule, which is what an
/// inverted, twisted or excessively curved element breaks. The report's elements keep their own
/// rule: positive area (tri3), all four triangles around the centre of the corners positive (saas).

#include <array>
#include <optional>
#include <string>

#include "solver/base/voigt.hpp"
#include "solver/fe/element_family.hpp"

namespace saasgaps {

struct ShapeProblem {
  enum class Kind {
    clockwise,          ///< the corners run clockwise (they would be fine the other way round)
    degenerate,         ///< the corners enclose no area, or a saas quad is not convex enough
    midside_off_edge,   ///< a mid-side node is far from the middle of its edge (or out of order)
    jacobian,           ///< det J <= 0 at a point of the stiffness rule
  };
  Kind kind = Kind::degenerate;
  int node = -1;      ///< midside_off_edge: the local node
  int point = -1;     ///< jacobian: the rule point (0-based)
  double xi = 0.0, eta = 0.0;
  double value = 0.0; ///< the signed area, the offset ratio or det J
  std::string detail; ///< the finding in words (no ids: the caller names the element)
};

/// The first problem of an element of `type` with nodes at x (node_count of them), or none.
std::optional<ShapeProblem> element_shape_problem(ElementType type, Integration integration,
                                                  const std::array<Vec2, max_element_nodes>& x);

/// The node order that lists the same element counter-clockwise: corner 0 first, the other corners
/// and the mid-side nodes reversed, the centre node last.
std::array<int, max_element_nodes> reversed_order(ElementType type);

/// A mid-side node may sit anywhere whose projection on its chord lies in the middle half (1/4 to
/// 3/4 of the chord) and whose distance from the chord is at most this fraction of the chord: a
/// quarter-circle's mid-side node is 0.21 off, a half circle's 0.5.
inline constexpr double max_midside_offset = 0.5;

}  // namespace saasgaps
