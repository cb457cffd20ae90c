#pragma once
/// Symmetry lines: where a recovered field may be continued across the boundary by its mirror image.
///
/// A half model cut along a straight line and held there by rollers (the normal displacement
/// prescribed, the tangential one free, no tangential force) has as its solution the restriction of
/// the whole, mirrored model's solution: the field continues across the line as its mirror image.
/// Patch recovery uses that: a patch at the line is completed by the mirror images of its sampling
/// points, so a node on a symmetry line is recovered as an interior node is (interpolated, not
/// extrapolated from the patches beside it).
///
/// A node lies on a symmetry line when, at the end of the run (the model's constraints, then each
/// step's in order), exactly one displacement component is prescribed there:
///   u_z prescribed           the line z = z_node (every analysis);
///   u_r prescribed           the line r = r_node (plane analyses; in axisymmetry only the axis,
///                            r = 0, where the hoop terms are themselves symmetric);
/// and no tangential force acts there: not a node of a gap element or a contact surface, of an edge
/// load with a shear component, or of a nodal force along the line (in the model's loads or any
/// step's). Two nodes lie on the same line when they have the same kind, coordinate (to 1e-9 of the
/// model's size) and prescribed value.
///
/// Mirror images, (r, z) and Voigt values (rr, zz, rz, th) for stresses:
///   across z = c:  (r, 2c - z), the shear rz changes sign;
///   across r = c:  (2c - r, z), the shear rz changes sign.
/// A field of other components (a heat flux (q_r, q_z)) gives its own signs.

#include <cstdint>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

enum class MirrorKind : std::uint8_t { none, z_line, r_line };

struct SymmetryLines {
  std::vector<MirrorKind> kind;  ///< per node
  std::vector<double> value;     ///< per node: the prescribed normal displacement
  double tolerance = 0.0;        ///< coordinates closer than this are the same line
  /// The sign of each value component under a reflection across a z line, then an r line.
  Vec4 z_sign = Vec4(1.0, 1.0, -1.0, 1.0);
  Vec4 r_sign = Vec4(1.0, 1.0, -1.0, 1.0);

  [[nodiscard]] bool empty() const { return kind.empty(); }
  [[nodiscard]] bool on_line(std::size_t node) const { return !kind.empty() && kind[node] != MirrorKind::none; }
  /// True when nodes a and b lie on one symmetry line.
  [[nodiscard]] bool same_line(const Model& model, std::size_t a, std::size_t b) const;
  /// The mirror image of point x across node n's line.
  [[nodiscard]] Vec2 mirror_point(const Model& model, std::size_t n, const Vec2& x) const;
  /// The mirror image of a value across node n's line.
  [[nodiscard]] Vec4 mirror_value(std::size_t n, const Vec4& v) const;
};

/// Sets marked[n] = 1 at the nodes where another body pushes: the nodes of gap elements and of
/// contact surfaces' edges.
void mark_contact_nodes(const Model& model, std::vector<std::uint8_t>& marked);

/// The symmetry lines of a stress analysis (see the file comment); no line for a model without
/// constraints.
SymmetryLines stress_symmetry_lines(const Model& model);

/// The symmetry lines of heat conduction: an insulated straight boundary is one. Zero normal flux
/// is the condition the temperature's even extension across the line meets, so the conduction
/// solution continues as its mirror image (q_r, q_z): across z = c q_z changes sign, across r = c
/// q_r. The nodes of boundary edges (boundary_edges.hpp) with no thermal.boundary condition, no
/// contact surface or gap element at either end, all of whose nodes lie on one line z = c (every
/// analysis) or r = c (plane analyses; in axisymmetry only the axis); not a node of a conditioned
/// edge along a line of the same kind (a face partly insulated), nor of insulated lines of both
/// kinds (a corner). A conditioned edge across the line (a film on the face the line meets) is
/// mirrored with the rest.
/// Empty without a thermal section.
SymmetryLines heat_symmetry_lines(const Model& model);

}  // namespace saasgaps
