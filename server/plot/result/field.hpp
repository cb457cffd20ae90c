#pragma once
/// The quantities a plot can show, and their values at the nodes for contouring.
///
/// Element fields (stresses, strains) are constant per element in the result; contouring needs
/// values at the nodes, so they are averaged there, weighted by element area:
///   v_n = sum_e A_e v_e / sum_e A_e   over the solid elements e that use node n.
/// Gap elements take no part: their stresses are fictitious, and averaging them in would smear the
/// contact pressure into both bodies. Nodes that no solid element uses get NaN.
///
/// Cylindrical components (plane analyses only): the result holds the in-plane tensor in x-y
/// (sigma_r = σx, sigma_z = σy, tau_rz = τxy; the strains alike, gamma_rz engineering shear) and
/// sigma_theta, which in a plane model is the OUT-OF-PLANE stress σz, not a hoop stress. The
/// radial, hoop and radial-hoop shear components about a centre c are the in-plane tensor rotated
/// to the direction φ of the element's centroid p from c, (cos φ, sin φ) = (p - c)/|p - c|:
///   σrad = σx cos²φ + σy sin²φ + 2 τxy sinφ cosφ
///   σhoop = σx sin²φ + σy cos²φ − 2 τxy sinφ cosφ
///   τrad,hoop = (σy − σx) sinφ cosφ + τxy (cos²φ − sin²φ)
/// and for strains the same with εx, εy and γxy/2 (γrad,hoop = 2 × the rotated tensor shear).
/// In an axisymmetric model sigma_r and sigma_theta already are the radial and hoop stresses.
///
/// Heat flux (thermal runs): `heat_flux` is the magnitude |q| = sqrt(q_r^2 + q_z^2) of each element's
/// stored flux, averaged to the nodes like any element field (a magnitude of the average would
/// cancel where the flux turns; this is the average of the magnitude).

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/result/plot_result.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

enum class FieldLocation {
  element,  ///< one value per solid element (the document's "elements")
  node,     ///< one value per node
  gap,      ///< one value per gap element
};

/// What a field measures, for its unit.
enum class Quantity { stress, strain, length, temperature, heat_flux, percent, energy_error };

/// A component of the in-plane tensor in polar axes about a centre (see above); none: as stored.
enum class Cylindrical { none, radial, hoop, radial_hoop };

/// A point of the model's plane: (r, z), which are (x, y) in plane analyses.
using PlanePoint = std::array<double, 2>;

struct FieldInfo {
  std::string_view name;   ///< what --field takes
  FieldLocation location;
  std::string_view key;    ///< the result document's key (element and gap fields; "" when derived)
  std::string_view axisymmetric_label;
  std::string_view plane_label;  ///< in plane analyses (r, z) are (x, y) and theta is out of plane
  Quantity quantity;
  /// In plane analyses, what the stored name means in x-y-z: "σx", "σz, out of plane"; "" for none.
  std::string_view plane_meaning = "";
  /// Derived from the stored in-plane stress (Quantity::stress) or strain by rotation about a centre.
  Cylindrical cylindrical = Cylindrical::none;
  /// Drawn and probed as each element's own value, constant in the element (FieldSource::element),
  /// not averaged to the nodes: `error`, whose values belong to elements, not to points.
  bool constant_per_element = false;
};

/// Where the values a picture or a probe interpolates inside the elements come from
/// (element_field.hpp): the recovered nodal stresses, nodal averages of element values, or the
/// nodes' own values.
enum class FieldSource { recovered, averaged, nodal, element };

/// "recovered stresses", "nodal averages of element values", "nodal values" or "one value per
/// element", for subtitles.
const char* source_phrase(FieldSource source);

/// Every field, element fields first.
const std::vector<FieldInfo>& fields();

/// "sigma_r, sigma_z, ..." for messages.
std::string field_names();

/// The field of that name; otherwise std::invalid_argument "unknown field 'x'; fields: ...".
const FieldInfo& find_field(std::string_view name);

/// "Hoop stress σθ" or "Out-of-plane stress σz ...", as the analysis reads; a cylindrical
/// component says its centre ("Hoop stress σhoop about (x, y) = (0, 0)").
std::string field_label(const FieldInfo& field, const ResultMesh& mesh, const PlanePoint& centre = {0.0, 0.0});

/// The field's short name for colour bars, axes and legends: the name --field takes, and in plane
/// analyses what it means there: "sigma_theta (σz, out of plane)", "sigma_r (σx)", "sigma_hoop".
std::string field_title(const FieldInfo& field, const ResultMesh& mesh);

/// A cylindrical component asked of an axisymmetric model: std::invalid_argument saying which
/// stored field is the radial or hoop one there. Other fields and plane models: nothing.
void require_field_fits(const FieldInfo& field, const ResultMesh& mesh);

/// The unit's name for a quantity: the model's name from the result's units ("psi"), "%" for
/// percent, "" for strain (dimensionless) and for a unit the model does not name.
std::string unit_name(Quantity quantity, const UnitNames& units);

/// "name [psi]", or the bare name when the unit is not named (or the quantity has none).
std::string with_unit(std::string_view name, Quantity quantity, const UnitNames& units);

/// For subtitles: "in psi", "strain (dimensionless)", or "in the model's stress units" (not named).
std::string unit_phrase(Quantity quantity, const UnitNames& units);

/// Values per solid element (element fields only), in mesh.solids order; cylindrical components
/// about `centre`, at each element's centroid (the mean of its corners).
std::vector<double> element_values(const PlotResult& result, const ResultMesh& mesh, const FieldInfo& field,
                                   const PlanePoint& centre = {0.0, 0.0});

/// The cylindrical component of an in-plane tensor (xx, yy, xy: the tensor's shear, i.e. half the
/// engineering shear strain) in the direction phi (radians, from +x): see above; radial_hoop gives
/// the tensor shear. Cylindrical::none: std::invalid_argument.
double rotate_in_plane(double xx, double yy, double xy, double phi, Cylindrical component);

/// Values per gap element (gap fields only: closure %, contact_pressure), in mesh.gaps order.
std::vector<double> gap_values(const ResultMesh& mesh, const FieldInfo& field);

/// Area-weighted nodal average of per-element values (see above); NaN at nodes of no solid element.
std::vector<double> average_to_nodes(const ResultMesh& mesh, const std::vector<double>& per_element);

/// Values per node for contouring: node fields directly (displacement = sqrt(u_r^2 + u_z^2)),
/// element fields through average_to_nodes. Gap fields: std::invalid_argument (they have no nodal
/// values; plot them with the closure plot).
std::vector<double> nodal_values(const PlotResult& result, const ResultMesh& mesh, const FieldInfo& field,
                                 const PlanePoint& centre = {0.0, 0.0});

/// The result document's element keys a field reads: its key, or the three in-plane components a
/// cylindrical one is rotated from; none for node and gap fields.
std::vector<std::string_view> element_keys(const FieldInfo& field);

}  // namespace saasgaps::plot
