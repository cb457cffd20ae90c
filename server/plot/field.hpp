#pragma once
/// The quantities a plot can show, and their values at the nodes for contouring.
///
/// Element fields (stresses, strains) are constant per element in the result; contouring needs
/// values at the nodes, so they are averaged there, weighted by element area:
///   v_n = sum_e A_e v_e / sum_e A_e   over the solid elements e that use node n.
/// Gap elements take no part: their stresses are fictitious, and averaging them in would smear the
/// contact pressure into both bodies. Nodes that no solid element uses get NaN.

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/result_mesh.hpp"

namespace saasgaps::plot {

enum class FieldLocation {
  element,  ///< one value per solid element (the document's "elements")
  node,     ///< one value per node
  gap,      ///< one value per gap element
};

/// What a field measures, for its unit.
enum class Quantity { stress, strain, length, temperature, percent };

struct FieldInfo {
  std::string_view name;   ///< what --field takes
  FieldLocation location;
  std::string_view key;    ///< the result document's key (element and gap fields)
  std::string_view axisymmetric_label;
  std::string_view plane_label;  ///< in plane analyses (r, z) are (x, y) and theta is out of plane
  Quantity quantity;
};

/// Every field, element fields first.
const std::vector<FieldInfo>& fields();

/// "sigma_r, sigma_z, ..." for messages.
std::string field_names();

/// The field of that name; otherwise std::invalid_argument "unknown field 'x'; fields: ...".
const FieldInfo& find_field(std::string_view name);

/// "Hoop stress σθ" or "Out-of-plane stress σθ", as the analysis reads.
std::string_view field_label(const FieldInfo& field, const ResultMesh& mesh);

/// The unit's name for a quantity: the model's name from the result's units ("psi"), "%" for
/// percent, "" for strain (dimensionless) and for a unit the model does not name.
std::string unit_name(Quantity quantity, const UnitNames& units);

/// "name [psi]", or the bare name when the unit is not named (or the quantity has none).
std::string with_unit(std::string_view name, Quantity quantity, const UnitNames& units);

/// For subtitles: "in psi", "strain (dimensionless)", or "in the model's stress units" (not named).
std::string unit_phrase(Quantity quantity, const UnitNames& units);

/// Values per solid element (element fields only), in mesh.solids order.
std::vector<double> element_values(const nlohmann::json& result, const FieldInfo& field);

/// Values per gap element (gap fields only: closure %, contact_pressure), in mesh.gaps order.
std::vector<double> gap_values(const ResultMesh& mesh, const FieldInfo& field);

/// Area-weighted nodal average of per-element values (see above); NaN at nodes of no solid element.
std::vector<double> average_to_nodes(const ResultMesh& mesh, const std::vector<double>& per_element);

/// Values per node for contouring: node fields directly (displacement = sqrt(u_r^2 + u_z^2)),
/// element fields through average_to_nodes. Gap fields: std::invalid_argument (they have no nodal
/// values; plot them with the closure plot).
std::vector<double> nodal_values(const nlohmann::json& result, const ResultMesh& mesh, const FieldInfo& field);

}  // namespace saasgaps::plot
