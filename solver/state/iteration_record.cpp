#include "solver/state/iteration_record.hpp"

namespace saasgaps {

namespace {
bool same(const WatchedElement& a, const WatchedElement& b) {
  return a.id == b.id && a.sigma_r == b.sigma_r && a.sigma_z == b.sigma_z && a.tau_rz == b.tau_rz &&
         a.sigma_theta == b.sigma_theta && a.effective == b.effective;
}
bool same(const WatchedGap& a, const WatchedGap& b) {
  return a.id == b.id && a.modulus == b.modulus && a.closure == b.closure && a.sigma_m == b.sigma_m;
}
bool same(const SetReaction& a, const SetReaction& b) { return a.set == b.set && a.f_r == b.f_r && a.f_z == b.f_z; }
bool same(const PairForce& a, const PairForce& b) {
  return a.surfaces == b.surfaces && a.f_r == b.f_r && a.f_z == b.f_z;
}
template <class T>
bool same_rows(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same(a[i], b[i])) return false;
  }
  return true;
}
}  // namespace

bool IterationRecord::same_numbers(const IterationRecord& o) const {
  return iteration == o.iteration && step == o.step && increment == o.increment && tensile_modulus == o.tensile_modulus && closed_gaps == o.closed_gaps &&
         nonconverged_gaps == o.nonconverged_gaps && average_closure == o.average_closure &&
         max_closure == o.max_closure && yielded_elements == o.yielded_elements &&
         nonconverged_plastic == o.nonconverged_plastic && bimodulus_changes == o.bimodulus_changes &&
         extrapolated == o.extrapolated && contact_pairs == o.contact_pairs &&
         complementarity == o.complementarity && active_set_iterations == o.active_set_iterations &&
         stick_points == o.stick_points && slip_points == o.slip_points &&
         friction_residual == o.friction_residual && same_rows(watch_elements, o.watch_elements) &&
         same_rows(watch_gaps, o.watch_gaps) && gap_closures == o.gap_closures &&
         same_rows(set_reactions, o.set_reactions) && same_rows(pair_forces, o.pair_forces);
}

}  // namespace saasgaps
