#pragma once
/// Elastic unloading for the bilinear secant law of SAAS III, across the increments of a stepped run.
///
/// Within one increment the law is the report's total-strain (secant) law, unchanged. Between
/// increments every yielded element keeps the peak of its loading (PlasticPeak): the largest
/// effective strain eps_max it reached at the end of an increment, the effective stress sigma_max
/// there, and the plastic strain the peak leaves when unloaded along the elastic line,
///   eps_p = (C_s - C_E) sigma_peak            (global axes rr, zz, gamma_rz, th)
/// with C_s the compliance of the secant constants the peak was solved with and C_E that of the
/// elastic ones (uniaxially eps_p = eps_max - sigma_max / E). In later increments the element is on
///  - the loading branch while its effective strain sigma_eff / E_s is at least eps_max: the secant
///    law as in one increment (sigma = D_s (eps - eps_th));
///  - the unloading branch once its effective strain falls below eps_max: elastic with the original
///    modulus and eps_p as an initial strain, sigma = D_E (eps - eps_th - eps_p), for as long as its
///    effective stress stays at most sigma_max; beyond it the element is back on the loading branch.
/// The two branches give the same stress at the peak (D_E (eps - eps_p) = D_s eps there), so a
/// reload passes from one to the other without a jump. A switch needs the change to exceed the
/// plastic tolerance (eps_eff < (1 - tol) eps_max, sigma_eff > (1 + tol) sigma_max), which keeps an
/// element at its peak from flipping between the two from one iteration to the next.
///
/// Elements that never yielded keep no peak: below the yield strain the secant law is the elastic
/// one already. A run without steps (one increment), or one in which no element's effective strain
/// falls back below its peak, never unloads and gives the secant law's numbers to the last digit. Reversed loading past sigma_max (compression after
/// tension) is outside this law: the effective stress has no sign, and the element returns to the
/// secant curve as the report's law has it.

#include "solver/base/voigt.hpp"
#include "solver/materials/material.hpp"

namespace saasgaps {

/// What a yielded element keeps of its largest loading (zero: it never yielded at an increment's end).
struct PlasticPeak {
  double strain = 0.0;                 ///< eps_max, the report's effective strain sigma_eff / E_s
  double stress = 0.0;                 ///< sigma_max, the effective (von Mises) stress at eps_max
  Vec4 plastic_strain = Vec4::Zero();  ///< eps_p (rr, zz, gamma_rz, th) left by elastic unloading

  [[nodiscard]] bool reached() const { return strain > 0.0; }
  friend bool operator==(const PlasticPeak&, const PlasticPeak&) = default;
};

/// eps_p = (C_s - C_E) stress: the strain left when `stress`, reached with the constants `loaded`,
/// is removed with the constants `elastic`; both in material axes, axis 1 at angle_deg from +r.
Vec4 plastic_strain(const ElasticConstants& elastic, const ElasticConstants& loaded, double angle_deg,
                    const Vec4& stress);

/// The branch and secant ratio of an element for its next iteration, from its current solution.
struct PlasticBranch {
  bool unloading = false;  ///< elastic with the peak's plastic strain
  double secant_ratio = 1.0;
  bool changed = false;    ///< the branch switched (the element has not converged)
};

/// The branch rule above (an element without a reached peak is always loading: the report's secant
/// update). used_ratio and was_unloading: what the solution was built with; sigma_eff: its effective
/// stress; tolerance: the plastic tolerance.
PlasticBranch next_branch(const PlasticPeak& peak, const BilinearCurve& curve, bool was_unloading, double used_ratio,
                          double sigma_eff, double tolerance);

}  // namespace saasgaps
