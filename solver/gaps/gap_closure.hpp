#pragma once
/// Section II of the report: how SAASGAPS sets the moduli of its gap elements from one iteration to
/// the next ("stress invariance"), and when the gaps have converged.
///
/// A gap element is an orthotropic element in the gap whose M axis points across it. Its strain
/// along M, eps_M, measures how far the gap has closed: closure (%) = -100 eps_M; eps_M = -1 means
/// the faces touch, below -1 they overlap. Its properties are set here, not by the user:
/// Poisson ratios 0, no thermal expansion, E_N = E_theta = the current tensile modulus, and a
/// negligible shear modulus.

#include <vector>

#include "solver/materials/material.hpp"
#include "solver/model/model.hpp"
#include "solver/state/gap_history.hpp"

namespace saasgaps {

/// The verdict of test (e) on iteration K.
struct GapVerdict {
  std::vector<GapFailure> failure;  ///< per gap; GAP-CONV? = YES where none
  std::vector<bool> converged;  ///< GAP-CONV? per gap
  int nonconverged = 0;
  int closed = 0;                ///< gaps with closure > 100 % (the report's "closed gaps")
  double average_closure = 0.0;  ///< mean closure (%) of those gaps; 0 when none
  double max_closure = 0.0;      ///< largest closure (%) of all gaps
  [[nodiscard]] bool all_converged() const { return nonconverged == 0; }
};

class GapClosure {
 public:
  explicit GapClosure(const GapSettings& settings);

  /// (a) Iteration 1: every gap at the input modulus E0, in both M and N.
  [[nodiscard]] GapModuli initial() const;

  /// (b)-(d) and Fig. 19: the moduli of iteration K+1 from iterations K and K-1.
  [[nodiscard]] GapModuli next(const GapHistory& after) const;

  /// (e) Convergence of iteration K.
  [[nodiscard]] GapVerdict test(const GapHistory& after) const;

  /// The fictitious material of gap g under the given moduli (global axes).
  [[nodiscard]] Constitutive law(std::size_t g, const GapModuli& moduli, AnalysisType analysis) const;

  /// The schedule's last value: the "essentially zero" stiffness of a relaxed gap.
  [[nodiscard]] double floor_modulus() const { return settings_.tensile_schedule.back(); }

  /// The stress-invariance target eps_gap: closure_K / target is the factor on E_K (decoded from
  /// Tables I and II: 0.90 beyond 200 % closure, 0.99 below; Eq. 1 of the text is target 1).
  static double invariance_target(double closure);

 private:
  /// Fig. 19: E_X where the line through (E_K-1, eps_K-1) and (E_K, eps_K) reaches eps = -1;
  /// 0 when the line does not give a positive modulus.
  [[nodiscard]] static double extrapolated_modulus(double E_previous, double eps_previous, double E_current,
                                                   double eps_current);
  [[nodiscard]] bool extrapolation_allowed(const GapHistory& after) const;

  GapSettings settings_;
};

}  // namespace saasgaps
