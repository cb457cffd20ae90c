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
/// The rule (gap_axis_problem). M runs across the gap when
///   (1) each face is within 30 degrees of perpendicular to M: lean = |cos(face, M)| <= 1/2, and
///   (2) the faces are the gap's long sides: their separation s (quadrilateral: the distance between
///       the faces' midpoints; triangle: the lone corner's distance from the face's line) is at most
///       their mean length L.
/// A gap element fills a thin clearance between two faces; (2) is what tells its faces from its ends.
/// A horizontal strip 0.5 long and 0.01 thick given angle 0 passes (1) with its short ends as "faces"
/// and fails (2): s = 0.5, L = 0.01. A clearance wider than the elements along it are long fails (2)
/// too: such a gap is meshed with elements at least as long as the clearance is wide.

#include <array>
#include <optional>
#include <string>

#include "model.hpp"
#include "voigt.hpp"

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

/// Rules (1) and (2): M runs across the gap whose faces (from gap_faces) these are.
[[nodiscard]] bool runs_across(const GapFaces& faces);

/// Why M does not run across gap element `gap` (rules (1) and (2)), with its faces' nodes by id and the
/// angle across its long sides; nothing when it does.
std::optional<std::string> gap_axis_problem(const Model& model, const GapElement& gap);

/// The area of the gap's contact face, the one its normal stress acts on: the mean of its two faces'
/// areas for a quadrilateral, half its face's for a triangle (in a strip of triangles alternating sides
/// each triangle then stands for half the face it lies on). Plane: length x thickness; axisymmetric:
/// the full ring, 2 pi r length. Equals the sum of the gap's node pair shares (contact_pairs.hpp).
double gap_face_area(const Model& model, const GapElement& gap);

}  // namespace saasgaps
