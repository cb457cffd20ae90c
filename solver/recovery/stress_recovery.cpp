#include "solver/recovery/stress_recovery.hpp"

#include <cmath>

#include "solver/assembly/element_data.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/recovery/boundary_stresses.hpp"

namespace saasgaps {

StressRecovery recover_stresses(const Model& model, std::span<const double> displacement,
                                const PointLawsFactory& laws_for_thread, std::span<const ElementState> point_states,
                                const MaterialPoints& points) {
  const std::size_t count = model.elements.size();
  const auto states_of = [&](std::size_t e) {
    return point_states.subspan(points.first(e), static_cast<std::size_t>(points.count(e)));
  };
  StressRecovery out;
  const SymmetryLines symmetry = stress_symmetry_lines(model);
  // Every family samples its material points' states (the report's elements: their centre), which
  // needs only the geometry: the patches ask for each element's samples as they need them.
  out.stress = recover_field(
      model, [&](std::size_t e) { return stress_samples(solid_element_geometry(model, e), states_of(e)); }, &symmetry);
  recover_boundary_stresses(model, displacement, laws_for_thread(), symmetry, out.stress);

  // The error pass. The model's sums run over the elements in order whatever the threads, so that
  // the estimate's digits do not depend on how many there were.
  std::vector<ElementError> errors(count);
  for_each_range(count, [&](std::size_t begin, std::size_t end, unsigned) {
    const PointLawsOf laws = laws_for_thread();
    std::array<Constitutive, max_material_points> scratch;
    for (std::size_t e = begin; e < end; ++e) {
      const Element& el = model.elements[e];
      const auto nodal = element_nodal_values(model, out.stress, e);
      const std::span<const Vec4> own = std::span<const Vec4>(nodal).first(static_cast<std::size_t>(el.node_count));
      // A report element's stress is constant on each of its triangles: they are solved again (the
      // saas quad's centre condensed back), which needs its law, temperatures, loads and
      // displacements; the isoparametric families' stresses are their material points' states.
      errors[e] = family(el.type).report_element
                      ? report_element_error(solid_element_data(model, e, laws(e, scratch)),
                                             values(element_displacements(displacement, el.node_span())), own)
                      : element_error(solid_element_geometry(model, e), laws(e, scratch), states_of(e), own);
    }
  });
  out.element_error.resize(count);
  for (std::size_t e = 0; e < count; ++e) out.element_error[e] = std::sqrt(errors[e].error2);
  out.estimate = total_error(errors);
  return out;
}

}  // namespace saasgaps
