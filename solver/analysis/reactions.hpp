#pragma once
/// Support reactions: the force the supports exert on each constrained node of a solved state.
///
/// A node in equilibrium balances its internal forces against everything applied to it:
///   sum_e (K_e u_e - f_e) = f_loads + f_contact + R,
/// with K_e, f_e the stiffness and equivalent loads (thermal strain, body force, spin) of each solid
/// element under the law the state was solved with, f_loads the nodal forces and edge tractions,
/// f_contact what contact puts on the node (gap elements, node pair forces:
/// ContactMethod::add_nodal_forces) and R the reaction. So
///   R = sum_e (K_e u_e - f_e) - f_loads - f_contact     at each prescribed component,
/// and R = 0 at a free component (a support exerts no force along a free direction). Units: force;
/// plane analyses on the whole thickness, axisymmetric ones on the full ring (2 pi radians), like
/// nodal forces. Only elements and loads touching a constrained node are visited.

#include <span>
#include <vector>

#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/model/model.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps {

/// The reactions at every node with a prescribed component (dofs: the state's numbering), in node
/// order. displacement: (u_r, u_z) per node, prescribed ones included; solid_laws: the laws each solid
/// element was solved with; contact_forces: f_contact, 2 per node (empty: none).
std::vector<NodeReaction> support_reactions(const Model& model, const DofMap& dofs, const PointLawsOf& solid_laws,
                                            std::span<const double> displacement,
                                            std::span<const double> contact_forces);
/// The same with one law per element (at every point).
std::vector<NodeReaction> support_reactions(const Model& model, const DofMap& dofs, const LawOf& solid_law,
                                            std::span<const double> displacement,
                                            std::span<const double> contact_forces);

/// The reactions summed per direction, (sum f_r, sum f_z) in force units, in node order (so the same
/// bits wherever it is summed). In equilibrium it balances the applied loads: in plane analyses both
/// components, in axisymmetric ones f_z (docs/results.md).
Vec2 reaction_sum(std::span<const NodeReaction> reactions);

/// The reactions summed over each reaction group's nodes (Model::reaction_groups), in the groups'
/// order; a node of two groups counts in both. reactions: support_reactions' list for `model`.
std::vector<SetReaction> set_reactions(const Model& model, std::span<const NodeReaction> reactions);

}  // namespace saasgaps
