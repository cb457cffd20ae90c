#include "solver/materials/plastic_history.hpp"

#include <Eigen/LU>

namespace saasgaps {

namespace {

/// Compliance in global axes (rr, zz, gamma_rz, th): eps_g = T^-1 S T^-T sigma_g, since material
/// strains are T eps_g and global stresses T^T sigma_mat (material.hpp's strain_rotation).
Mat4 global_compliance(const ElasticConstants& c, double angle_deg) {
  const Mat4 T_inverse = strain_rotation(angle_deg).inverse();
  return T_inverse * compliance(c) * T_inverse.transpose();
}

/// The report's secant update: the secant ratio E_s / E that the curve gives at effective strain eps.
double secant_ratio_at(const BilinearCurve& curve, double eps) {
  return eps > 0.0 ? curve.stress(eps) / (curve.E * eps) : 1.0;
}

}  // namespace

Vec4 plastic_strain(const ElasticConstants& elastic, const ElasticConstants& loaded, double angle_deg,
                    const Vec4& stress) {
  // In plane stress sigma_th = 0, and the th row of C gives the out-of-plane strain the kernel reports.
  return (global_compliance(loaded, angle_deg) - global_compliance(elastic, angle_deg)) * stress;
}

PlasticBranch next_branch(const PlasticPeak& peak, const BilinearCurve& curve, bool was_unloading, double used_ratio,
                          double sigma_eff, double tolerance) {
  PlasticBranch next;
  if (was_unloading) {
    if (sigma_eff <= (1.0 + tolerance) * peak.stress) {
      next.unloading = true;
      return next;
    }
    // Reloaded past the peak: start the secant iteration where the elastic line would have gone on.
    next.secant_ratio = secant_ratio_at(curve, peak.strain + (sigma_eff - peak.stress) / curve.E);
    next.changed = true;
    return next;
  }
  // The solution's effective stress sits on the secant line E_s = ratio E: its effective
  // (mechanical) strain is sigma_eff / E_s. Read the curve at that same strain.
  const double eps_eff = sigma_eff / (used_ratio * curve.E);
  if (peak.reached() && eps_eff < (1.0 - tolerance) * peak.strain) {
    next.unloading = true;
    next.changed = true;
    return next;
  }
  next.secant_ratio = secant_ratio_at(curve, eps_eff);
  return next;
}

}  // namespace saasgaps
