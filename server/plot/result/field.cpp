#include "plot/result/field.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "plot/draw/number_format.hpp"

namespace saasgaps::plot {

namespace {

constexpr Quantity stress_units = Quantity::stress;
constexpr Quantity strain_units = Quantity::strain;
constexpr Quantity length_units = Quantity::length;

std::string_view quantity_name(Quantity q) {
  switch (q) {
    case Quantity::stress: return "stress";
    case Quantity::strain: return "strain";
    case Quantity::length: return "length";
    case Quantity::temperature: return "temperature";
    case Quantity::heat_flux: return "heat flux";
    case Quantity::percent: return "percent";
    case Quantity::energy_error: return "energy norm";
  }
  return "?";
}

}  // namespace

const std::vector<FieldInfo>& fields() {
  using enum Cylindrical;
  static const std::vector<FieldInfo> all = {
      {"sigma_r", FieldLocation::element, "sigma_r", "Radial stress \u03c3r", "Stress \u03c3x (along r)", stress_units,
       "\u03c3x"},
      {"sigma_z", FieldLocation::element, "sigma_z", "Axial stress \u03c3z", "Stress \u03c3y (along z)", stress_units,
       "\u03c3y"},
      {"tau_rz", FieldLocation::element, "tau_rz", "Shear stress \u03c4rz", "Shear stress \u03c4xy", stress_units,
       "\u03c4xy"},
      {"sigma_theta", FieldLocation::element, "sigma_theta", "Hoop stress \u03c3\u03b8",
       "Out-of-plane stress \u03c3z (not a hoop stress: that is sigma_hoop)", stress_units,
       "\u03c3z, out of plane"},
      {"sigma_1", FieldLocation::element, "sigma_1", "Maximum principal stress in the plane \u03c31",
       "Maximum principal stress in the plane \u03c31", stress_units},
      {"sigma_2", FieldLocation::element, "sigma_2", "Minimum principal stress in the plane \u03c32",
       "Minimum principal stress in the plane \u03c32", stress_units},
      {"effective", FieldLocation::element, "effective", "Effective (von Mises) stress",
       "Effective (von Mises) stress", stress_units},
      {"sigma_radial", FieldLocation::element, "", "", "Radial stress \u03c3rad", stress_units, "", radial},
      {"sigma_hoop", FieldLocation::element, "", "", "Hoop stress \u03c3hoop", stress_units, "", hoop},
      {"tau_radial_hoop", FieldLocation::element, "", "", "Radial-hoop shear stress \u03c4rad,hoop", stress_units, "",
       radial_hoop},
      {"eps_r", FieldLocation::element, "eps_r", "Radial strain \u03b5r", "Strain \u03b5x", strain_units, "\u03b5x"},
      {"eps_z", FieldLocation::element, "eps_z", "Axial strain \u03b5z", "Strain \u03b5y", strain_units, "\u03b5y"},
      {"gamma_rz", FieldLocation::element, "gamma_rz", "Shear strain \u03b3rz", "Shear strain \u03b3xy", strain_units,
       "\u03b3xy"},
      {"eps_theta", FieldLocation::element, "eps_theta", "Hoop strain \u03b5\u03b8",
       "Out-of-plane strain \u03b5z (not a hoop strain: that is eps_hoop)", strain_units, "\u03b5z, out of plane"},
      {"eps_radial", FieldLocation::element, "", "", "Radial strain \u03b5rad", strain_units, "", radial},
      {"eps_hoop", FieldLocation::element, "", "", "Hoop strain \u03b5hoop", strain_units, "", hoop},
      {"gamma_radial_hoop", FieldLocation::element, "", "", "Radial-hoop shear strain \u03b3rad,hoop (engineering)",
       strain_units, "", radial_hoop},
      {"heat_flux", FieldLocation::element, "", "Heat flux magnitude |q|", "Heat flux magnitude |q|", Quantity::heat_flux},
      {"error", FieldLocation::element, "error", "Estimated error of the stresses", "Estimated error of the stresses",
       Quantity::energy_error, "", none, true},
      {"temperature", FieldLocation::node, "T", "Temperature", "Temperature", Quantity::temperature},
      {"displacement", FieldLocation::node, "", "Displacement magnitude |u|", "Displacement magnitude |u|",
       length_units},
      {"u_r", FieldLocation::node, "u_r", "Radial displacement ur", "Displacement ux", length_units, "ux"},
      {"u_z", FieldLocation::node, "u_z", "Axial displacement uz", "Displacement uy", length_units, "uy"},
      {"closure", FieldLocation::gap, "closure", "Gap closure", "Gap closure", Quantity::percent},
      {"contact_pressure", FieldLocation::gap, "contact_pressure", "Contact pressure across the gaps",
       "Contact pressure across the gaps", stress_units},
  };
  return all;
}

const char* source_phrase(FieldSource source) {
  switch (source) {
    case FieldSource::recovered: return "recovered stresses";
    case FieldSource::averaged: return "nodal averages of element values";
    case FieldSource::nodal: return "nodal values";
    case FieldSource::element: return "one value per element";
  }
  return "";
}

std::string field_names() {
  std::string names;
  for (const FieldInfo& f : fields()) names += (names.empty() ? "" : ", ") + std::string(f.name);
  return names;
}

const FieldInfo& find_field(std::string_view name) {
  for (const FieldInfo& f : fields()) {
    if (f.name == name) return f;
  }
  throw std::invalid_argument("unknown field '" + std::string(name) + "'; fields: " + field_names());
}

std::string field_label(const FieldInfo& field, const ResultMesh& mesh, const PlanePoint& centre) {
  if (field.cylindrical != Cylindrical::none) {
    return std::string(field.plane_label) + " about (x, y) = (" + format_value(centre[0]) + ", " +
           format_value(centre[1]) + ")";
  }
  return std::string(mesh.plane() ? field.plane_label : field.axisymmetric_label);
}

std::string field_title(const FieldInfo& field, const ResultMesh& mesh) {
  if (!mesh.plane() || field.plane_meaning.empty()) return std::string(field.name);
  return std::string(field.name) + " (" + std::string(field.plane_meaning) + ")";
}

void require_field_fits(const FieldInfo& field, const ResultMesh& mesh) {
  if (field.cylindrical == Cylindrical::none || mesh.plane()) return;
  throw std::invalid_argument("'" + std::string(field.name) +
                              "' is a component about a centre in a plane model; in this axisymmetric model the "
                              "radial, hoop and shear components are " +
                              (field.quantity == Quantity::stress ? "sigma_r, sigma_theta and tau_rz"
                                                                  : "eps_r, eps_theta and gamma_rz"));
}

double rotate_in_plane(double xx, double yy, double xy, double phi, Cylindrical component) {
  const double c = std::cos(phi), s = std::sin(phi);
  switch (component) {
    case Cylindrical::radial: return xx * c * c + yy * s * s + 2.0 * xy * s * c;
    case Cylindrical::hoop: return xx * s * s + yy * c * c - 2.0 * xy * s * c;
    case Cylindrical::radial_hoop: return (yy - xx) * s * c + xy * (c * c - s * s);
    case Cylindrical::none: break;
  }
  throw std::invalid_argument("rotate_in_plane: no component");
}

std::vector<std::string_view> element_keys(const FieldInfo& field) {
  if (field.location != FieldLocation::element) return {};
  if (field.quantity == Quantity::heat_flux) return {"q_r", "q_z"};
  if (field.cylindrical == Cylindrical::none) return {field.key};
  if (field.quantity == Quantity::stress) return {"sigma_r", "sigma_z", "tau_rz"};
  return {"eps_r", "eps_z", "gamma_rz"};
}

std::string unit_name(Quantity quantity, const UnitNames& units) {
  switch (quantity) {
    case Quantity::stress: return units.stress;
    case Quantity::length: return units.length;
    case Quantity::temperature: return units.temperature;
    case Quantity::heat_flux: return "";  // power / length^2: the model names no unit of power
    case Quantity::percent: return "%";
    case Quantity::strain: return "";
    case Quantity::energy_error: return "";  // the square root of an energy: no unit the model names
  }
  return "";
}

std::string with_unit(std::string_view name, Quantity quantity, const UnitNames& units) {
  const std::string unit = unit_name(quantity, units);
  return unit.empty() ? std::string(name) : std::string(name) + " [" + unit + "]";
}

std::string unit_phrase(Quantity quantity, const UnitNames& units) {
  if (quantity == Quantity::strain) return "strain (dimensionless)";
  if (quantity == Quantity::energy_error) return "in the energy norm (\u221aenergy)";
  const std::string unit = unit_name(quantity, units);
  if (!unit.empty()) return "in " + unit;
  return "in the model's " + std::string(quantity_name(quantity)) + " units";
}

std::vector<double> element_values(const PlotResult& result, const ResultMesh& mesh, const FieldInfo& field,
                                   const PlanePoint& centre) {
  if (field.location != FieldLocation::element) {
    throw std::invalid_argument("'" + std::string(field.name) + "' is not an element field");
  }
  require_field_fits(field, mesh);
  if (field.quantity == Quantity::heat_flux) {
    std::vector<std::vector<double>> q;
    try {
      for (const std::string_view key : element_keys(field)) q.push_back(result.element_member(key));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("'heat_flux' is the heat flux of a thermal run, and this result has none (its "
                                  "model has no thermal section): " + std::string(e.what()));
    }
    std::vector<double> values;
    for (std::size_t e = 0; e < q[0].size(); ++e) values.push_back(std::hypot(q[0][e], q[1][e]));
    return values;
  }
  if (field.quantity == Quantity::energy_error) {
    try {
      return result.element_member(field.key);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("'error' is the estimated error of a solved result (docs/recovery.md), and this "
                                  "result has none (written before the estimate): " + std::string(e.what()));
    }
  }
  std::vector<std::vector<double>> stored;
  for (const std::string_view key : element_keys(field)) stored.push_back(result.element_member(key));
  if (field.cylindrical == Cylindrical::none) return std::move(stored[0]);
  // The stored shear strain is engineering (γ = 2 εxy): rotate the tensor, give γ back.
  const double shear = field.quantity == Quantity::strain ? 0.5 : 1.0;
  const double back = field.quantity == Quantity::strain && field.cylindrical == Cylindrical::radial_hoop ? 2.0 : 1.0;
  std::vector<double> values;
  for (std::size_t e = 0; e < mesh.solids.size(); ++e) {
    double x = 0.0, y = 0.0;
    for (const int n : mesh.solids[e].nodes) {
      x += mesh.nodes[n].r;
      y += mesh.nodes[n].z;
    }
    const double count = static_cast<double>(mesh.solids[e].nodes.size());
    // At the centre itself the direction is undefined; atan2(0, 0) = 0 takes x as radial there.
    const double phi = std::atan2(y / count - centre[1], x / count - centre[0]);
    values.push_back(back * rotate_in_plane(stored[0][e], stored[1][e], shear * stored[2][e], phi, field.cylindrical));
  }
  return values;
}

std::vector<double> gap_values(const ResultMesh& mesh, const FieldInfo& field) {
  if (field.location != FieldLocation::gap) {
    throw std::invalid_argument("'" + std::string(field.name) + "' is not a gap field");
  }
  std::vector<double> values;
  for (const GapElement& g : mesh.gaps) values.push_back(field.name == "closure" ? g.closure : g.contact_pressure);
  return values;
}

std::vector<double> average_to_nodes(const ResultMesh& mesh, const std::vector<double>& per_element) {
  std::vector<double> weighted(mesh.nodes.size(), 0.0);
  std::vector<double> weight(mesh.nodes.size(), 0.0);
  for (std::size_t e = 0; e < mesh.solids.size(); ++e) {
    const double a = mesh.area(mesh.solids[e]);
    for (const int n : mesh.solids[e].nodes) {
      weighted[n] += a * per_element[e];
      weight[n] += a;
    }
  }
  std::vector<double> values(mesh.nodes.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t n = 0; n < values.size(); ++n) {
    if (weight[n] > 0.0) values[n] = weighted[n] / weight[n];
  }
  return values;
}

std::vector<double> nodal_values(const PlotResult& result, const ResultMesh& mesh, const FieldInfo& field,
                                 const PlanePoint& centre) {
  switch (field.location) {
    case FieldLocation::element:
      return average_to_nodes(mesh, element_values(result, mesh, field, centre));
    case FieldLocation::node: {
      const auto value = [&field](const MeshNode& n) {
        if (field.name == "temperature") return n.temperature;
        if (field.name == "u_r") return n.u_r;
        if (field.name == "u_z") return n.u_z;
        return std::hypot(n.u_r, n.u_z);  // displacement
      };
      std::vector<double> values;
      for (const MeshNode& n : mesh.nodes) values.push_back(value(n));
      return values;
    }
    case FieldLocation::gap:
      break;
  }
  throw std::invalid_argument("'" + std::string(field.name) +
                              "' is a gap field, without values at the nodes: plot it along a row of gaps");
}

}  // namespace saasgaps::plot
