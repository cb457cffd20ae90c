#pragma once
/// A result document as a VTK XML unstructured grid (.vtu) for ParaView and other VTK tools, binary
/// (zlib-compressed appended data) by default or ASCII (io/vtu_encoding.hpp). Works from the result
/// document alone (the result document of docs/results.md), so any stored result can be exported.
///
/// Points: every node at (r, z, 0) (in plane analyses (r, z) = (x, y)).
/// Cells: the solid elements, then the gap elements, in document order, each as its family's VTK
/// cell (element_family.hpp): 3 nodes VTK_TRIANGLE (5), 4 VTK_QUAD (9), 6 VTK_QUADRATIC_TRIANGLE
/// (22), 8 VTK_QUADRATIC_QUAD (23), 9 VTK_BIQUADRATIC_QUAD (28); the node order of the model is VTK's.
/// Point data:
///   displacement  (u_r, u_z, 0), the active vector: Warp By Vector shows the deformed shape
///   temperature   T
///   node_id       the model's node id
///   reaction      (fr, fz, 0): the supports' force on the node, 0 at free nodes (only when the
///                 result has `reactions`)
/// and, when the result has contact surfaces (result `contact`), their points on side A's nodes
/// (a point is at its node's reference position); nodes that are no pair's side A hold 0 and -1:
///   contact_pressure, contact_gap, contact_shear, contact_slip  the point's values
///   contact_state -1 not a side-A node, 0 open, 1 stick, 2 slip
///   contact_pair  1, 2, .. the pair (in the result's order), 0 not a side-A node
///   (a node on side A of two pairs holds the later pair's values). Point data rather than a second
///   piece of vertices: one piece keeps every VTK reader's view of the file, and the contact values
///   then deform, threshold and plot over a line with the mesh.
/// Cell data (element-only values are 0 on gap cells, gap-only values are 0 on solid cells; use
/// is_gap to tell them apart, e.g. with a Threshold filter):
///   element_id, is_gap (0/1), material (the material id; 0 on gap cells)
///   sigma_r, sigma_z, tau_rz, sigma_theta, sigma_1, sigma_2, principal_angle (deg), effective
///   eps_r, eps_z, gamma_rz, eps_theta
///   yield (0/1), plastic_converged (0/1; 1 on gap cells)
///   gap_closure (%), gap_eps_m, gap_sigma_m, gap_contact_pressure, gap_modulus, gap_angle (deg)
///   gap_state     -1 solid, 0 open, 1 partial, 2 closed, 3 overclosed
///   gap_converged -1 solid, 0 no, 1 yes
/// When the result names its units, the names of dimensional arrays carry them: "sigma_r [psi]",
/// "displacement [in]", "temperature [degF]" (stresses, the gap's sigma_m, contact pressure and
/// modulus in the stress unit).
/// Why 0 rather than NaN for values a cell does not have: the ASCII form must read back in VTK,
/// whose ASCII reader does not parse "nan", and both forms carry the same values.

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/results/result_arrays.hpp"
#include "io/results/vtu_encoding.hpp"

namespace saasgaps::io {

/// The gap_state code written for a gap state name ("open" -> 0 .. "overclosed" -> 3).
int vtu_gap_state_code(const std::string& state);

/// " [psi]" when the result (its "units") names the unit of that kind ("stress", "length",
/// "temperature"), the suffix of the arrays' names; "" otherwise.
std::string vtu_unit_suffix(const nlohmann::json& result, const char* kind);

/// What the VTU reads of a result (io/result_arrays.hpp): the mesh and the element members above.
const ResultSelection& vtu_result_selection();

/// The VTU document, from the arrays read with vtu_result_selection(). A failed run, or a result
/// without node coordinates, is a std::invalid_argument.
std::string result_to_vtu(const ResultArrays& result, VtuFormat format = VtuFormat::binary);
/// The same from a tree (small in-memory documents and tests: it is dumped and read as text).
std::string result_to_vtu(const nlohmann::json& result, VtuFormat format = VtuFormat::binary);

/// The iterations as a ParaView collection: for each history row that holds every gap's closure,
/// a file "<stem>_iter<NNNN>.vtu" with the mesh, element_id, is_gap and that iteration's
/// gap_closure; the last iteration's file is the whole result (result_to_vtu). Then "<stem>.pvd",
/// listing them with the iteration as the time step, so ParaView's time slider steps through the
/// gap iteration. Only closures are kept per iteration (the history rows); displacements and
/// stresses exist for the final state only. write(file name, bytes) is called once per file, the
/// .pvd last; a result without per-iteration closures gives one file, the result.
void write_vtu_series(const ResultArrays& result, const std::string& stem, VtuFormat format,
                      const std::function<void(const std::string& file, const std::string& bytes)>& write);
/// The collection's layout, for any writer of the files (this one, and the tree writer the tests keep
/// as its reference): which history rows get a file, their names, the .pvd. whole() makes the last
/// (or only) file, iteration_file(closures, iteration) the others.
void write_vtu_collection(const nlohmann::json& document, const std::string& stem,
                          const std::function<std::string()>& whole,
                          const std::function<std::string(const nlohmann::json& closures, int iteration)>& iteration_file,
                          const std::function<void(const std::string& file, const std::string& bytes)>& write);
/// The same from a tree, as result_to_vtu.
void write_vtu_series(const nlohmann::json& result, const std::string& stem, VtuFormat format,
                      const std::function<void(const std::string& file, const std::string& bytes)>& write);

}  // namespace saasgaps::io
