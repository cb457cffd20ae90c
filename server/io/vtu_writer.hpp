#pragma once
/// A result document as a VTK XML unstructured grid (.vtu, ASCII) for ParaView and other VTK tools.
/// Works from the result document alone (model-format.md "The result document"), so any stored
/// result can be exported.
///
/// Points: every node at (r, z, 0) (in plane analyses (r, z) = (x, y)).
/// Cells: the solid elements, then the gap elements, in document order; 4 nodes VTK_QUAD (9),
/// 3 nodes VTK_TRIANGLE (5).
/// Point data:
///   displacement  (u_r, u_z, 0), the active vector: Warp By Vector shows the deformed shape
///   temperature   T
///   node_id       the model's node id
/// Cell data (element-only values are 0 on gap cells, gap-only values are 0 on solid cells; use
/// is_gap to tell them apart, e.g. with a Threshold filter):
///   element_id, is_gap (0/1), material (the material id; 0 on gap cells)
///   sigma_r, sigma_z, tau_rz, sigma_theta, sigma_1, sigma_2, principal_angle (deg), effective
///   eps_r, eps_z, gamma_rz, eps_theta
///   yield (0/1), plastic_converged (0/1; 1 on gap cells)
///   gap_closure (%), gap_eps_m, gap_sigma_m, gap_modulus, gap_angle (deg, direction M)
///   gap_state     -1 solid, 0 open, 1 partial, 2 closed, 3 overclosed
///   gap_converged -1 solid, 0 no, 1 yes
/// Why 0 rather than NaN for values a cell does not have: VTK's ASCII reader does not parse "nan".
/// Numbers are written in the shortest form that reads back to the same double.

#include <string>

#include <nlohmann/json.hpp>

namespace saasgaps::io {

/// The gap_state code written for a gap state name ("open" -> 0 .. "overclosed" -> 3).
int vtu_gap_state_code(const std::string& state);

/// The VTU document. A failed run, or a result without node coordinates, is a std::invalid_argument.
std::string result_to_vtu(const nlohmann::json& result);

}  // namespace saasgaps::io
