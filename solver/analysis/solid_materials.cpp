#include "solver/analysis/solid_materials.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "solver/assembly/element_data.hpp"

namespace saasgaps {

SolidMaterials::SolidMaterials(const Model& model) : model_(model) {
  temperature_.reserve(model.elements.size());
  for (const Element& el : model.elements) {
    temperature_.push_back(element_temperature(model, el.nodes, el.node_count));
  }
  for (const Material& m : model.materials) {
    if (!m.plasticity.empty() || !m.compression_table.empty()) nonlinear_ = true;
  }
}

MaterialState SolidMaterials::initial() const {
  return {std::vector<double>(model_.elements.size(), 1.0),
          std::vector<DirectionChoice>(model_.elements.size(), all_tension), {}, {}};
}

ElasticConstants SolidMaterials::constants(std::size_t e, DirectionChoice choice) const {
  const Material& m = model_.materials[model_.elements[e].material];
  const ElasticConstants tension = interpolate(m.table, temperature_[e], m.isotropic);
  if (choice == all_tension || m.compression_table.empty()) return tension;
  return mix_bimodulus(tension, interpolate(m.compression_table, temperature_[e], m.isotropic), choice);
}

Constitutive SolidMaterials::law(std::size_t e, const MaterialState& s) const {
  const ElasticConstants c = secant(constants(e, s.compression[e]), s.secant_ratio[e]);
  Constitutive law = constitutive(c, model_.analysis, model_.elements[e].angle_deg);
  law.initial_strain = s.initial_strain(e);
  return law;
}

const Constitutive& SolidMaterials::law(std::size_t e, const MaterialState& s, LawMemo& memo) const {
  const Element& el = model_.elements[e];
  if (memo.material != el.material || memo.temperature != temperature_[e] || memo.angle != el.angle_deg ||
      memo.secant_ratio != s.secant_ratio[e] || memo.compression != s.compression[e]) {
    memo = {el.material, temperature_[e], el.angle_deg, s.secant_ratio[e], s.compression[e], law(e, s)};
  }
  // The initial strain is the element's own; everything else the memo's key decides.
  memo.law.initial_strain = s.initial_strain(e);
  return memo.law;
}

void SolidMaterials::update(const MaterialState& used, std::span<const ElementState> states, double tolerance,
                            MaterialUpdate& u) const {
  const std::size_t n = model_.elements.size();
  assert(states.size() == n);
  u.next = used;
  u.yielded.assign(n, false);
  u.converged.assign(n, true);
  u.yielded_count = 0;
  u.nonconverged_count = 0;
  u.bimodulus_changes = 0;
  for (std::size_t e = 0; e < n; ++e) {
    const Element& el = model_.elements[e];
    const Material& m = model_.materials[el.material];
    const Vec4& stress = states[e].stress;

    if (!m.compression_table.empty()) {
      // A direction switches tables only when it carries stress: a component that is zero up to
      // round-off has no sign worth following, and flipping on it would never settle.
      const Vec4 material_stress = stress_in_material_axes(stress, el.angle_deg);
      const double scale = material_stress.cwiseAbs().maxCoeff();
      const DirectionChoice signs = compression_directions(material_stress);
      DirectionChoice choice = used.compression[e];
      const std::array<int, 3> component{0, 1, 3};
      for (int d = 0; d < 3; ++d) {
        if (std::abs(material_stress[component[d]]) <= tolerance * scale) continue;
        const auto bit = static_cast<DirectionChoice>(1U << d);
        choice = static_cast<DirectionChoice>((choice & ~bit) | (signs & bit));
      }
      if (choice != used.compression[e]) ++u.bimodulus_changes;
      u.next.compression[e] = choice;
    }

    if (!m.plasticity.empty()) {
      const PlasticityRow row = interpolate(m.plasticity, temperature_[e]);
      const double E = reference_modulus(constants(e, used.compression[e]), m.isotropic);
      const BilinearCurve curve{E, row.yield_stress, row.hardening_ratio};
      const double sigma_eff = von_mises(stress);
      static const PlasticPeak never_yielded;
      const PlasticBranch branch = next_branch(used.peaks.empty() ? never_yielded : used.peaks[e], curve,
                                               used.unloads(e), used.secant_ratio[e], sigma_eff, tolerance);
      const double ratio = branch.secant_ratio;
      u.next.secant_ratio[e] = ratio;
      if (branch.unloading != used.unloads(e)) {
        if (u.next.unloading.empty()) u.next.unloading.assign(n, 0);
        u.next.unloading[e] = branch.unloading ? 1 : 0;
      }
      u.yielded[e] = sigma_eff > row.yield_stress;
      u.converged[e] = !branch.changed &&
                       std::abs(ratio - used.secant_ratio[e]) <= tolerance * used.secant_ratio[e];
    }
    if (u.yielded[e]) ++u.yielded_count;
    if (!u.converged[e]) ++u.nonconverged_count;
  }
}

void SolidMaterials::record_peaks(const MaterialState& used, std::span<const ElementState> states,
                                  MaterialState& next) const {
  const std::size_t n = model_.elements.size();
  assert(states.size() == n);
  for (std::size_t e = 0; e < n; ++e) {
    const Element& el = model_.elements[e];
    const Material& m = model_.materials[el.material];
    // Below the yield strain the secant law is the elastic one: nothing to keep.
    if (m.plasticity.empty() || used.unloads(e) || !(used.secant_ratio[e] < 1.0)) continue;
    const ElasticConstants elastic = constants(e, used.compression[e]);
    const double sigma_eff = von_mises(states[e].stress);
    const double eps_eff = sigma_eff / (used.secant_ratio[e] * reference_modulus(elastic, m.isotropic));
    if (!next.peaks.empty() && eps_eff <= next.peaks[e].strain) continue;
    if (next.peaks.empty()) next.peaks.assign(n, PlasticPeak{});
    next.peaks[e] = {eps_eff, sigma_eff,
                     plastic_strain(elastic, secant(elastic, used.secant_ratio[e]), el.angle_deg, states[e].stress)};
  }
}

}  // namespace saasgaps
