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

#include "material.hpp"
#include "model.hpp"

namespace saasgaps {

/// The gap moduli one iteration uses.
struct GapModuli {
  std::vector<double> normal;  ///< E_M per gap
  double tensile = 0.0;        ///< the schedule's current tensile modulus: E_N = E_theta of every gap
  int schedule_step = -1;      ///< schedule entry in use; -1 = the initial modulus
  bool extrapolated = false;   ///< some E_M came from the extrapolation of Fig. 19
};

/// Everything the next iteration's gap moduli depend on, after iteration K.
struct GapHistory {
  GapModuli used;                        ///< moduli of iteration K
  std::vector<double> strain;            ///< eps_M of iteration K
  std::vector<double> previous_normal;   ///< E_M of iteration K-1 (empty when K = 1)
  std::vector<double> previous_strain;   ///< eps_M of iteration K-1 (empty when K = 1)
  double previous_tensile = 0.0;         ///< tensile modulus of iteration K-1
  [[nodiscard]] bool has_previous() const { return !previous_strain.empty(); }
};

/// Why a gap fails test (e); the first failing check is reported.
enum class GapFailure {
  none,
  first_iteration,  ///< nothing to compare with yet
  overclosed,       ///< eps_M <= -(1 + tolerance)
  not_relaxed,      ///< in tension but not yet at the schedule's floor modulus
  not_settled,      ///< eps_M moved by more than the tolerance since the last iteration
  loaded_open,      ///< strict test: does not touch, yet stiffer than the floor modulus
};

const char* describe(GapFailure failure);

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
