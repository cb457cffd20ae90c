#pragma once
/// The mesh of a result document (docs/results.md), read for drawing: node
/// coordinates and displacements, solid and gap element connectivity as node indices, gap states.
/// Works from the JSON alone, so that any stored result can be plotted without the solver.

#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/results/result_arrays.hpp"
#include "solver/base/name_table.hpp"

namespace saasgaps::plot {

/// A node without recovered stresses (see MeshNode::stress).
inline constexpr std::array<double, 4> no_stress{
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};

struct MeshNode {
  int id = 0;
  double r = 0.0, z = 0.0;      ///< undeformed coordinates ((x, y) in plane analyses)
  double temperature = 0.0;
  double u_r = 0.0, u_z = 0.0;  ///< displacement
  /// The recovered stress (docs/results.md, nodes[]): sigma_r, sigma_z, tau_rz, sigma_theta; NaN
  /// where the node has none (no solid element, or a result written before recovery). Where
  /// materials meet, the mean of the sides (each side: RecoveredStress, element_field.hpp).
  std::array<double, 4> stress = no_stress;
};

struct SolidElement {
  int id = 0;
  int material = 0;
  /// Node indices of the outline, counter-clockwise: the corners of a linear element; for a
  /// quadratic one corner, mid-side, corner, ... (6 or 8; a quad9's centre node is left out).
  std::vector<int> nodes;
  int centre = -1;  ///< a quad9's centre node (index); -1 for the other families
};

enum class GapState { open, partial, closed, overclosed };
inline constexpr std::array<GapState, 4> all_gap_states{GapState::closed, GapState::overclosed, GapState::partial,
                                                        GapState::open};
/// "open", "partial", "closed", "overclosed" as in the result document.
inline constexpr NameTable<GapState, 4> gap_state_names{{{{GapState::open, "open"},
                                                          {GapState::partial, "partial"},
                                                          {GapState::closed, "closed"},
                                                          {GapState::overclosed, "overclosed"}}}};
inline std::string_view to_string(GapState state) { return gap_state_names.name(state); }

struct GapElement {
  int id = 0;
  /// Node indices of the outline, counter-clockwise: the corners of a linear element; for a
  /// quadratic one corner, mid-side, corner, ... (6 or 8; a quad9's centre node is left out).
  std::vector<int> nodes;
  double angle_deg = 0.0;  ///< direction M across the gap, from +r
  double closure = 0.0;    ///< percent; 100 = faces touching
  double sigma_m = 0.0;    ///< normal stress across the gap, negative in compression
  /// max(0, -sigma_m): the document's contact_pressure, or computed from sigma_m for results
  /// written before it was added.
  double contact_pressure = 0.0;
  GapState state = GapState::open;
  bool converged = true;
};

/// document[key] when it is an array, else an empty array (no copy either way).
const nlohmann::json& array_member(const nlohmann::json& document, const char* key);

/// The model's names of its units (the result's "units" object); empty: not named.
struct UnitNames {
  std::string length;
  std::string force;
  std::string stress;
  std::string temperature;
};

struct ResultMesh {
  std::string title;
  UnitNames units;
  std::string analysis;  ///< plane_stress | plane_strain | axisymmetric
  std::string status;    ///< converged | not_converged
  int iterations = 0;
  std::vector<MeshNode> nodes;
  std::vector<SolidElement> solids;  ///< in the order of the document's "elements"
  std::vector<GapElement> gaps;      ///< in the order of the document's "gaps"

  /// Reads the mesh. A failed run (no mesh) or a malformed document is a std::invalid_argument that
  /// says what is missing.
  static ResultMesh from_result(const nlohmann::json& result);
  /// The same from the typed arrays of io::read_result_arrays (read with the mesh selected), with
  /// the same checks and messages.
  static ResultMesh from_arrays(const io::ResultArrays& result);

  bool plane() const { return analysis != "axisymmetric"; }
  /// Area of a solid element in the undeformed configuration (shoelace formula), length^2.
  double area(const SolidElement& e) const;
  /// Node coordinates (r + s u_r, z + s u_z): the undeformed mesh for s = 0.
  std::array<double, 2> position(int node, double scale) const;
};

}  // namespace saasgaps::plot
