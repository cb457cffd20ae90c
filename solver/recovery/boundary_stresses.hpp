#pragma once
/// Recovered stresses at a boundary whose tractions are known, from the tractions and the strain
/// along the boundary, in place of the patch polynomials extrapolated there.
///
/// Patch recovery (patch_recovery.hpp) gives a boundary node the value of patches extrapolated up to
/// one element outwards; where the stress changes fast near the boundary (a hole's edge, a bore)
/// that is the least accurate value of the field. At a boundary node where the traction is known,
/// the stress is instead fixed by quantities that are known, or converge faster than stresses:
///
///   sigma_nn = -p,  sigma_nt = s      the edge load there (pressure p onto the body, shear s along t;
///                                     both zero on a free edge)
///   eps_tt   = t . du/ds              the stretch along the boundary, from the displacements of the
///                                     boundary's nodes (below), which converge faster than stresses
///   eps_th   = u_r / r (axisymmetric), 0 (plane strain); plane stress has sigma_th = 0
///
/// with n the outward normal and t the tangent counter-clockwise around the body. With the law of
/// the element's material point nearest the node, sigma = D eps - beta dT - D eps0 (dT the node's
/// temperature rise, eps0 the point's plastic strain), these four equations in the four total strains
/// give the stress. eps_tt comes from the nodes of the two boundary edges at the node (or of the edge
/// and its mirror image): x(s) and u(s) interpolated in the chord length s by the polynomial through
/// them and differentiated at the node, stretch = dx . du / |dx|^2 (exact for a homogeneous strain;
/// through 3 nodes of straight edges the central difference, through the 5 nodes of two quadratic
/// edges fourth order in the spacing).
///
/// Which nodes, each material side on its own (a side's boundary edges are the edges of its own
/// elements that no other solid element shares; gap elements and contact surfaces excluded below):
///  - a corner with exactly two boundary edges, one arriving and one leaving, whose tangents there
///    differ by at most 20 degrees (a smooth boundary, or a curve drawn with straight edges);
///  - a corner on a symmetry line (symmetry_lines.hpp) with one boundary edge off the line, within
///    10 degrees of perpendicular to it: the mirrored body's boundary is smooth there, and the
///    stretch is taken through the edge and its mirror image;
/// and only where every node of those edges has a known traction: no displacement prescribed (but a
/// symmetry line's roller), no nodal force (a concentrated load, or a distributed one given as
/// forces), no gap element, no contact surface; the edges' loads agree at the node; and, in
/// axisymmetry, not on the axis. Every other node keeps its patch value, mid-side nodes included: the
/// stretch through their own edge's three nodes is second order, and measured on NAFEMS LE1 (quad8,
/// 8 x 8) it raised the estimate's effectivity index to 1.42, where with the corners alone it is
/// 1.34 (tests/verification/recovery_verification_test.cpp). Temperature-dependent and
/// secant (bimodulus, plastic) laws are taken at the nearest material point, not at the node.

#include <span>

#include "solver/assembly/stiffness_system.hpp"
#include "solver/model/model.hpp"
#include "solver/recovery/symmetry_lines.hpp"
#include "solver/state/recovered_field.hpp"

namespace saasgaps {

/// Node n's sides on a boundary with known tractions (see the file comment): per side of `field`,
/// true when the side qualifies.
std::vector<bool> traction_boundary_sides(const Model& model, const RecoveredField& field, const SymmetryLines& symmetry);

/// Replaces the value of every side traction_boundary_sides selects by the stress its traction and
/// boundary strain give. displacement: (u_r, u_z) per node; laws: each element's laws per material
/// point as solved (stiffness_system.hpp).
void recover_boundary_stresses(const Model& model, std::span<const double> displacement, const PointLawsOf& laws,
                               const SymmetryLines& symmetry, RecoveredField& field);

}  // namespace saasgaps
