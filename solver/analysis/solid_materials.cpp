#include "solver/analysis/solid_materials.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "solver/assembly/element_data.hpp"

namespace saasgaps {

namespace {

/// The temperature at each material point: the report's elements read the mean of their nodes, the
/// others the temperature their shape functions interpolate at the point.
std::vector<double> point_temperatures(const Model& model, const MaterialPoints& points) {
  std::vector<double> T;
  T.reserve(points.size());
  for (const Element& el : model.elements) {
    const ElementFamily& f = family(el.type);
    if (f.point_count(el.integration) == 1 && f.report_element) {
      T.push_back(element_temperature(model, el.node_span()));
      continue;
    }
    for (const ReferencePoint& q : f.material_points(el.integration)) {
      ShapeValues v;
      f.shape(q.xi, q.eta, v);
      double t = 0.0;
      for (int a = 0; a < el.node_count; ++a) {
        t += v.N[static_cast<std::size_t>(a)] *
             model.loads.node_temperature[static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(a)])];
      }
      T.push_back(t);
    }
  }
  return T;
}

}  // namespace

SolidMaterials::SolidMaterials(const Model& model)
    : model_(model), points_(model), temperature_(point_temperatures(model, points_)) {
  for (const Material& m : model.materials) {
    if (!m.plasticity.empty() || !m.compression_table.empty()) nonlinear_ = true;
  }
}

MaterialState SolidMaterials::initial() const {
  return {std::vector<double>(points_.size(), 1.0), std::vector<DirectionChoice>(points_.size(), all_tension), {}, {}};
}

ElasticConstants SolidMaterials::constants(std::size_t e, std::size_t p, DirectionChoice choice) const {
  const Material& m = model_.materials[static_cast<std::size_t>(model_.elements[e].material)];
  const ElasticConstants tension = interpolate(m.table, temperature_[p], m.isotropic);
  if (choice == all_tension || m.compression_table.empty()) return tension;
  return mix_bimodulus(tension, interpolate(m.compression_table, temperature_[p], m.isotropic), choice);
}

Constitutive SolidMaterials::point_law(std::size_t e, std::size_t p, const MaterialState& s) const {
  const ElasticConstants c = secant(constants(e, p, s.compression[p]), s.secant_ratio[p]);
  Constitutive law = constitutive(c, model_.analysis, model_.elements[e].angle_deg);
  law.initial_strain = s.initial_strain(p);
  return law;
}

const Constitutive& SolidMaterials::point_law(std::size_t e, std::size_t p, const MaterialState& s,
                                              LawMemo& memo) const {
  const Element& el = model_.elements[e];
  if (memo.material != el.material || memo.temperature != temperature_[p] || memo.angle != el.angle_deg ||
      memo.secant_ratio != s.secant_ratio[p] || memo.compression != s.compression[p]) {
    memo = {el.material, temperature_[p], el.angle_deg, s.secant_ratio[p], s.compression[p], point_law(e, p, s)};
  }
  // The initial strain is the point's own; everything else the memo's key decides.
  memo.law.initial_strain = s.initial_strain(p);
  return memo.law;
}

Constitutive SolidMaterials::law(std::size_t e, const MaterialState& s) const { return point_law(e, points_.first(e), s); }

Constitutive SolidMaterials::law(std::size_t e, int point, const MaterialState& s) const {
  return point_law(e, points_.first(e) + static_cast<std::size_t>(point), s);
}

const Constitutive& SolidMaterials::law(std::size_t e, const MaterialState& s, LawMemo& memo) const {
  return point_law(e, points_.first(e), s, memo);
}

std::span<const Constitutive> SolidMaterials::laws(std::size_t e, const MaterialState& s, LawMemo& memo,
                                                   std::span<Constitutive> out) const {
  const std::size_t first = points_.first(e);
  const auto n = static_cast<std::size_t>(points_.count(e));
  for (std::size_t k = 0; k < n; ++k) out[k] = point_law(e, first + k, s, memo);
  return out.first(n);
}

void SolidMaterials::update(const MaterialState& used, std::span<const ElementState> states, double tolerance,
                            MaterialUpdate& u) const {
  const std::size_t n = points_.size();
  assert(states.size() == n);
  u.next = used;
  u.yielded.assign(n, false);
  u.converged.assign(n, true);
  u.yielded_count = 0;
  u.nonconverged_count = 0;
  u.bimodulus_changes = 0;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const Element& el = model_.elements[e];
    const Material& m = model_.materials[static_cast<std::size_t>(el.material)];
    bool yielded = false;
    bool converged = true;
    for (std::size_t p = points_.first(e), end = p + static_cast<std::size_t>(points_.count(e)); p < end; ++p) {
      const Vec4& stress = states[p].stress;

      if (!m.compression_table.empty()) {
        // A direction switches tables only when it carries stress: a component that is zero up to
        // round-off has no sign worth following, and flipping on it would never settle.
        const Vec4 material_stress = stress_in_material_axes(stress, el.angle_deg);
        const double scale = material_stress.cwiseAbs().maxCoeff();
        const DirectionChoice signs = compression_directions(material_stress);
        DirectionChoice choice = used.compression[p];
        const std::array<int, 3> component{0, 1, 3};
        for (int d = 0; d < 3; ++d) {
          if (std::abs(material_stress[component[static_cast<std::size_t>(d)]]) <= tolerance * scale) continue;
          const auto bit = static_cast<DirectionChoice>(1U << d);
          choice = static_cast<DirectionChoice>((choice & ~bit) | (signs & bit));
        }
        if (choice != used.compression[p]) ++u.bimodulus_changes;
        u.next.compression[p] = choice;
      }

      if (!m.plasticity.empty()) {
        const PlasticityRow row = interpolate(m.plasticity, temperature_[p]);
        const double E = reference_modulus(constants(e, p, used.compression[p]), m.isotropic);
        const BilinearCurve curve{E, row.yield_stress, row.hardening_ratio};
        const double sigma_eff = von_mises(stress);
        static const PlasticPeak never_yielded;
        const PlasticBranch branch = next_branch(used.peaks.empty() ? never_yielded : used.peaks[p], curve,
                                                 used.unloads(p), used.secant_ratio[p], sigma_eff, tolerance);
        const double ratio = branch.secant_ratio;
        u.next.secant_ratio[p] = ratio;
        if (branch.unloading != used.unloads(p)) {
          if (u.next.unloading.empty()) u.next.unloading.assign(n, 0);
          u.next.unloading[p] = branch.unloading ? 1 : 0;
        }
        u.yielded[p] = sigma_eff > row.yield_stress;
        u.converged[p] = !branch.changed &&
                         std::abs(ratio - used.secant_ratio[p]) <= tolerance * used.secant_ratio[p];
      }
      yielded = yielded || u.yielded[p];
      converged = converged && u.converged[p];
    }
    if (yielded) ++u.yielded_count;
    if (!converged) ++u.nonconverged_count;
  }
}

void SolidMaterials::record_peaks(const MaterialState& used, std::span<const ElementState> states,
                                  MaterialState& next) const {
  const std::size_t n = points_.size();
  assert(states.size() == n);
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const Element& el = model_.elements[e];
    const Material& m = model_.materials[static_cast<std::size_t>(el.material)];
    if (m.plasticity.empty()) continue;
    for (std::size_t p = points_.first(e), end = p + static_cast<std::size_t>(points_.count(e)); p < end; ++p) {
      // Below the yield strain the secant law is the elastic one: nothing to keep.
      if (used.unloads(p) || !(used.secant_ratio[p] < 1.0)) continue;
      const ElasticConstants elastic = constants(e, p, used.compression[p]);
      const double sigma_eff = von_mises(states[p].stress);
      const double eps_eff = sigma_eff / (used.secant_ratio[p] * reference_modulus(elastic, m.isotropic));
      if (!next.peaks.empty() && eps_eff <= next.peaks[p].strain) continue;
      if (next.peaks.empty()) next.peaks.assign(n, PlasticPeak{});
      next.peaks[p] = {eps_eff, sigma_eff,
                       plastic_strain(elastic, secant(elastic, used.secant_ratio[p]), el.angle_deg, states[p].stress)};
    }
  }
}

}  // namespace saasgaps
