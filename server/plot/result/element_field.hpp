#pragma once
/// A field as pictures and probes read it: values at each solid element's nodes, interpolated
/// inside the element with its own shape functions (element_map.hpp), so that the value at a point
/// is the same whichever element holds it (the elements' shape functions agree along a shared edge)
/// and the contour plot, `plot --path` and the probe all read one field.
///
/// Where the nodal values come from (FieldSource):
///   recovered: the stress fields (sigma_r, sigma_z, tau_rz, sigma_theta and those derived from
///     them: sigma_1, sigma_2, effective, the cylindrical components) from the recovered nodal
///     stresses (docs/recovery.md), each element from its own material's side where materials meet
///     (the result's node_sides). The four components are interpolated and the field derived at
///     the point: sigma_1,2 = (s_r + s_z)/2 +- sqrt(((s_r - s_z)/2)^2 + t_rz^2), effective the von
///     Mises stress of the four, a cylindrical component rotated to the point's own direction from
///     the centre (field.hpp), so a derived field is exact at every point, not interpolated;
///   averaged: the other element fields (strains, heat flux), and stresses of a result written
///     before recovery: area-weighted nodal averages of the element values (field.hpp);
///   nodal: node fields (temperature, displacements): the nodes' own values;
///   element: `error` (FieldInfo::constant_per_element): each element's own value throughout it.
/// Gap fields have no values inside elements.

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "plot/result/element_map.hpp"
#include "plot/result/field.hpp"
#include "plot/result/plot_result.hpp"
#include "plot/result/point_locator.hpp"
#include "plot/result/result_mesh.hpp"

namespace saasgaps::plot {

/// The recovered stress components (sigma_r, sigma_z, tau_rz, sigma_theta) at the nodes, per
/// material side: the nodes' values, and the result's node_sides where materials meet.
class RecoveredStress {
 public:
  /// Empty (available() false) when a node of a solid element has none (a result written before
  /// recovery). A malformed node_sides entry: std::invalid_argument naming it.
  explicit RecoveredStress(const PlotResult& result);
  [[nodiscard]] bool available() const { return available_; }
  /// The components at node index `node` on the side of material id `material`.
  [[nodiscard]] const std::array<double, 4>& at(int node, int material) const;
  /// The components at a point of solid element e: sum_a N_a s_a over its nodes (family order).
  [[nodiscard]] std::array<double, 4> interpolate(const SolidElement& e, const std::vector<int>& nodes,
                                                  const ShapeValues& N) const;

 private:
  const ResultMesh& mesh_;
  bool available_ = true;
  std::vector<bool> has_sides_;
  std::unordered_map<std::uint64_t, std::array<double, 4>> sides_;  ///< key: node index << 32 | material
};

/// One of the stress fields from the four components at a point (see above); `field` must be a
/// stress field (Quantity::stress, an element field).
double stress_field_value(const FieldInfo& field, const std::array<double, 4>& s, const PlanePoint& at,
                          const PlanePoint& centre);

class ElementField {
 public:
  /// The field of that name (find_field); a gap field: std::invalid_argument. Cylindrical
  /// components about `centre`.
  ElementField(const PlotResult& result, const FieldInfo& field, const PlanePoint& centre = {0.0, 0.0});

  [[nodiscard]] const FieldInfo& info() const { return field_; }
  [[nodiscard]] FieldSource source() const { return source_; }

  /// The value at the point of solid element e with shape functions N (family order, `nodes` =
  /// family_nodes(e)), at model point `at` (the direction of a cylindrical component).
  [[nodiscard]] double value(std::size_t e, const std::vector<int>& nodes, const ShapeValues& N,
                             const PlanePoint& at) const;
  /// The same at a located point.
  [[nodiscard]] double value(const Location& location) const;

 private:
  const ResultMesh& mesh_;
  const FieldInfo& field_;
  PlanePoint centre_;
  FieldSource source_ = FieldSource::nodal;
  std::optional<RecoveredStress> recovered_;
  std::vector<double> nodal_;  ///< averaged and nodal sources: the value per node
  std::vector<double> per_element_;  ///< the element source: the value per solid element
};

/// The model point of a located point: sum_a N_a x_a.
PlanePoint located_point(const ResultMesh& mesh, const Location& location);


}  // namespace saasgaps::plot
