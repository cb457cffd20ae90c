#pragma once
/// The faces of a gap element: which of its edges its M axis (`angle`) runs across, and the rule that
/// M must run across the gap, not along it. The model reader (both methods), the exact mode's node
/// pairs (contact_pairs.cpp) and the classic method's floor-share check all take the faces from here,
/// so they agree on them.
///
/// Faces. A quadrilateral's faces are its pair of opposite edges most nearly perpendicular to M,
/// 0-1 / 2-3 or 1-2 / 3-0 (counter-clockwise order makes opposite edges run opposite ways, so corner
/// one[k] faces corner two[k]). A triangle's face is its edge most nearly perpendicular to M; the lone
/// corner opposite it is the other side.
///
/// The rule (gap_axis_problems). M runs across the gap when
///   (1) each face is within 30 degrees of perpendicular to M: lean = |cos(face, M)| <= 1/2
///       (runs_across), and
///   (2) the edges M crosses are faces, not ends: no other gap element has one of them (a gap runs on
///       through its ends into its neighbours), and when a quadrilateral's other two sides both lie on
///       solid elements, so do the edges M crosses.
/// A strip of horizontal gaps given angle 0 passes (1) with its short ends as "faces" and fails (2):
/// its neighbours share those ends. Geometry alone cannot tell faces from ends (a curved gap is
/// wider than its elements are long far from contact, as in Hertz's problem); the mesh can. (2)
/// cannot judge a lone gap element between constrained nodes: there only (1) holds.

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Rule (1): the largest lean, |sin| of the angle between a face and the perpendicular to M (30 degrees).
constexpr double max_face_lean = 0.5;

struct GapFaces {
  std::array<int, 2> one{};  ///< corners of face one
  std::array<int, 2> two{};  ///< quadrilateral: the other face, two[k] facing one[k]; triangle: the lone corner twice
  double lean = 0.0;         ///< the larger lean of the faces (triangle: of its face)
  double separation = 0.0;   ///< s of rule (2)
  double length = 0.0;       ///< L of rule (2): the faces' mean length (triangle: its face's)
};

/// The faces of the gap element with corners x[0..node_count) and M at angle_deg from +r.
GapFaces gap_faces(const std::array<Vec2, 4>& x, int node_count, double angle_deg);

/// Rule (1): the faces (from gap_faces) lie across M.
[[nodiscard]] bool runs_across(const GapFaces& faces);

/// Per gap element of `gaps` (node indices into model.nodes; model.elements are the solids): why M does
/// not run across it (rules (1) and (2)), naming the edges M crosses, the faces and the angle across
/// them; nothing when it does. One pass over the solids, memory O(gaps).
std::vector<std::optional<std::string>> gap_axis_problems(const Model& model, std::span<const GapElement> gaps);

/// The area of the gap's contact face, the one its normal stress acts on: the mean of its two faces'
/// areas for a quadrilateral, half its face's for a triangle (in a strip of triangles alternating sides
/// each triangle then stands for half the face it lies on). Plane: length x thickness; axisymmetric:
/// the full ring, 2 pi r length. Equals the sum of the gap's node pair shares (contact_pairs.hpp).
double gap_face_area(const Model& model, const GapElement& gap);

}  // namespace saasgaps
