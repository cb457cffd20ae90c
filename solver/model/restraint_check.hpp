#pragma once
/// A cheap check, before any factorization, that a model has no mechanism: every connected body
/// (nodes joined through solid elements and gap elements) must be held by its constraints against
/// every rigid-body motion the analysis allows, and every node must belong to an element or be
/// fully prescribed.
///
/// Rigid-body motions of a body, displacement (u_r, u_z) at (r, z):
/// - plane stress / plane strain: u = (a - theta (z - z_c), b + theta (r - r_c)), three modes
///   (two translations and the in-plane rotation);
/// - axisymmetric: u = (0, b), one mode (a radial shift strains the hoop direction, u_r / r).
/// A prescribed component adds one row to the map (a, b, theta) -> prescribed values; the body is
/// restrained when the rows have full rank (rank 3 plane, a z row axisymmetric). Gap elements join
/// bodies: they always carry some stiffness (the tensile schedule's floor), so a body held only
/// through gaps is restrained. A contact surface pair joins the bodies of its two surfaces the same
/// way (a body held only by contact, pressed onto another, is a valid model). Cost: O(nodes + elements) and one 3x3 eigenvalue problem per body.

#include <vector>

#include "solver/model/model.hpp"

namespace saasgaps {

/// A body the constraints do not hold, or a node no element uses.
struct RestraintIssue {
  enum class Kind { unrestrained_body, orphan_node };
  Kind kind = Kind::unrestrained_body;
  std::vector<int> nodes;            ///< node indices of the body (the orphan node alone)
  std::vector<const char*> motions;  ///< the rigid motions left free: "translation r", "translation z", "rotation"
};

/// Every issue found, bodies in the order of their smallest node index.
std::vector<RestraintIssue> check_restraint(const Model& model);

}  // namespace saasgaps
