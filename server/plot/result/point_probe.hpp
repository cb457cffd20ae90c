#pragma once
/// The values of a result at a point (r, z): `saasgaps probe RESULT.json --at R,Z` and
/// GET /v1/jobs/{id}/probe?at=R,Z. The point is located and the fields interpolated as the contour
/// plot and `plot --path` read them (element_field.hpp: stresses from the recovered nodal stresses
/// with the element's shape functions, each element from its own material's side), so the three
/// agree. A point on an interface between materials (held by elements of several materials) gets
/// each material's side; a point on an edge inside one material has one value whichever element
/// holds it, and names the first of them in the order of elements[].

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/result/field.hpp"
#include "plot/result/plot_result.hpp"

namespace saasgaps::plot {

/// The point lies in no solid element of the result (outside the body, in a hole, in a gap).
class PointOutsideMesh : public std::invalid_argument {
 public:
  explicit PointOutsideMesh(const PlanePoint& at);
  PlanePoint at;
};

struct ProbeSide {
  int element = 0;   ///< id of the element the values were interpolated in
  int material = 0;  ///< its material's id
  std::vector<double> values;  ///< one per field of the probe, in its order
};

struct Probe {
  PlanePoint at{};
  std::vector<std::string> fields;   ///< the fields' names (find_field)
  std::vector<ProbeSide> sides;      ///< the first element holding the point, then one per other material
  FieldSource stress_source = FieldSource::recovered;  ///< where its stresses came from
};

/// What a probe shows without a list of fields: sigma_r, sigma_z, tau_rz, sigma_theta, effective,
/// u_r, u_z, and temperature when a node of the result has a temperature other than 0.
std::vector<std::string> default_probe_fields(const ResultMesh& mesh);

/// The result document's element keys a probe of these fields reads (the stresses of a result
/// without recovered ones fall back to element values): for io::ResultSelection.
std::vector<std::string> probe_element_keys(const std::vector<std::string>& fields);

/// The probe. An unknown or gap field: std::invalid_argument naming it (and the fields); a point
/// outside the mesh: PointOutsideMesh.
Probe probe_point(const PlotResult& result, const PlanePoint& at, std::vector<std::string> fields = {});

/// {"at": {"r", "z"}, "element", "material", "stresses": "recovered" | "averaged" ...,
///  "values": {field: value}, "units": {...} (when the result names them), "sides": [{"element",
///  "material", "values"}] (other materials' sides at an interface; empty elsewhere)}; (r, z) are
/// named x, y in plane analyses too (the result's r, z).
nlohmann::json probe_json(const Probe& probe, const ResultMesh& mesh);

/// Lines for a terminal: the point, the element, each field with its plane meaning and unit, and
/// the other sides at an interface.
std::string probe_text(const Probe& probe, const ResultMesh& mesh);

}  // namespace saasgaps::plot
