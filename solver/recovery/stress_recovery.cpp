#include "solver/recovery/stress_recovery.hpp"

#include <cmath>

#include "solver/assembly/element_data.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/recovery/boundary_stresses.hpp"

namespace saasgaps {

StressRecovery recover_stresses(const Model& model, std::span<const double> displacement, const PointLawsOf& laws,
                                std::span<const ElementState> point_states, const MaterialPoints& points) {
  const std::size_t count = model.elements.size();
  const auto states_of = [&](std::size_t e) {
    return point_states.subspan(points.first(e), static_cast<std::size_t>(points.count(e)));
  };
  // Each element is evaluated once: the report's elements solve their four triangles here (their
  // centre is condensed out: law, temperatures, loads and displacements needed), and the error pass
  // reads those triangles' stresses back from the samples; the isoparametric families need only
  // their geometry and their material points' states, here and in the error pass.
  std::vector<ElementSamples> samples(count);
  for_each_range(count, [&](std::size_t begin, std::size_t end, unsigned) {
    std::array<Constitutive, max_material_points> scratch;
    for (std::size_t e = begin; e < end; ++e) {
      const Element& el = model.elements[e];
      if (family(el.type).report_element) {
        const ElementData data = solid_element_data(model, e, laws(e, scratch));
        samples[e] = stress_samples(data, std::span<const ElementState>(), values(element_displacements(displacement, el.node_span())));
      } else {
        samples[e] = stress_samples(solid_element_geometry(model, e), states_of(e), std::span<const double>());
      }
    }
  });
  StressRecovery out;
  const SymmetryLines symmetry = stress_symmetry_lines(model);
  out.stress = recover_field(model, samples, &symmetry);
  recover_boundary_stresses(model, displacement, laws, symmetry, out.stress);
  std::vector<ElementError> errors(count);
  for_each_range(count, [&](std::size_t begin, std::size_t end, unsigned) {
    std::array<Constitutive, max_material_points> scratch;
    for (std::size_t e = begin; e < end; ++e) {
      const ElementData geometry = solid_element_geometry(model, e);
      const auto nodal = element_nodal_values(model, out.stress, e);
      errors[e] = element_error(geometry, laws(e, scratch), states_of(e), samples[e],
                                std::span<const Vec4>(nodal).first(static_cast<std::size_t>(geometry.node_count)));
    }
  });
  out.element_error.resize(count);
  for (std::size_t e = 0; e < count; ++e) out.element_error[e] = std::sqrt(errors[e].error2);
  out.estimate = total_error(errors);
  return out;
}

}  // namespace saasgaps
