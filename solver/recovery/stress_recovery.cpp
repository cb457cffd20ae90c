#include "solver/recovery/stress_recovery.hpp"

#include <cmath>

#include "solver/assembly/element_data.hpp"
#include "solver/base/index_ranges.hpp"
#include "solver/recovery/boundary_stresses.hpp"

namespace saasgaps {

namespace {

/// Element e's kernel input and its states at its material points.
struct ElementInput {
  ElementData data;
  ElementStates states;
  ElementVector u;
};

ElementInput element_input(const Model& model, std::size_t e, std::span<const double> displacement,
                           std::span<const Constitutive> laws, std::span<const ElementState> point_states,
                           const MaterialPoints& points) {
  ElementInput in{solid_element_data(model, e, laws), {}, element_displacements(displacement, model.elements[e].node_span())};
  in.states.point_count = points.count(e);
  for (int p = 0; p < in.states.point_count; ++p) {
    in.states.point[static_cast<std::size_t>(p)] = point_states[points.first(e) + static_cast<std::size_t>(p)];
  }
  return in;
}

}  // namespace

StressRecovery recover_stresses(const Model& model, std::span<const double> displacement, const PointLawsOf& laws,
                                std::span<const ElementState> point_states, const MaterialPoints& points) {
  const std::size_t count = model.elements.size();
  std::vector<ElementSamples> samples(count);
  for_each_range(count, [&](std::size_t begin, std::size_t end, unsigned) {
    std::array<Constitutive, max_material_points> scratch;
    for (std::size_t e = begin; e < end; ++e) {
      const ElementInput in = element_input(model, e, displacement, laws(e, scratch), point_states, points);
      samples[e] = stress_samples(in.data, in.states, values(in.u));
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
      const ElementInput in = element_input(model, e, displacement, laws(e, scratch), point_states, points);
      const auto nodal = element_nodal_values(model, out.stress, e);
      errors[e] = element_error(in.data, in.states, values(in.u),
                                std::span<const Vec4>(nodal).first(static_cast<std::size_t>(in.data.node_count)));
    }
  });
  out.element_error.resize(count);
  for (std::size_t e = 0; e < count; ++e) out.element_error[e] = std::sqrt(errors[e].error2);
  out.estimate = total_error(errors);
  return out;
}

}  // namespace saasgaps
