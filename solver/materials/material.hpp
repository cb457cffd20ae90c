#pragma once
/// Material laws: temperature tables, orthotropic stiffness in the element's axes, tension and
/// compression properties (bimodulus), and the bilinear secant-modulus curve of SAAS III.

#include <cstdint>
#include <vector>

#include "solver/base/voigt.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Elastic constants at one temperature, in material axes (1, 2 in-plane; 3 hoop/out-of-plane).
struct ElasticConstants {
  double E1 = 0.0, E2 = 0.0, E3 = 0.0;
  double nu12 = 0.0, nu13 = 0.0, nu23 = 0.0;
  double G12 = 0.0;
  double alpha1 = 0.0, alpha2 = 0.0, alpha3 = 0.0;
};

/// Linear interpolation of a table sorted by T, held constant beyond its ends. For an isotropic
/// material G12 = E / (2 (1 + nu)) from the interpolated E and nu.
ElasticConstants interpolate(const std::vector<PropertyRow>& table, double T, bool isotropic);

/// Conductivities k1, k2, k3 and specific heat c at temperature T, interpolated like the elastic
/// table (zeros for a material whose rows do not give them).
struct ThermalConstants {
  double k1 = 0.0, k2 = 0.0, k3 = 0.0;
  double c = 0.0;
};
ThermalConstants interpolate_thermal(const std::vector<PropertyRow>& table, double T);

/// Plasticity row at temperature T, interpolated like the elastic table.
PlasticityRow interpolate(const std::vector<PlasticityRow>& table, double T);

/// Bimodulus choice: bit i set means material direction i+1 uses the compression table.
using DirectionChoice = std::uint8_t;
inline constexpr DirectionChoice all_tension = 0;

/// The compression choice for a stress in material axes: a direction is compressive when its
/// normal stress is negative.
DirectionChoice compression_directions(const Vec4& material_stress);

/// Per-direction mix: E_i and alpha_i from direction i's table, nu_ij (i < j) from direction i's
/// table (so that S_ij = -nu_ij / E_i stays symmetric), G12 from the common table or the mean.
ElasticConstants mix_bimodulus(const ElasticConstants& tension, const ElasticConstants& compression,
                               DirectionChoice choice);

/// Secant scaling of SAAS III: E_i, G12 times ratio; nu_ij -> 0.5 - (0.5 - nu_ij) * ratio.
ElasticConstants secant(const ElasticConstants& c, double ratio);

/// Compliance in material axes, order (1, 2, 12, 3): strain = S stress.
Mat4 compliance(const ElasticConstants& c);

/// True when the compliance (hence the stiffness) is positive definite.
bool positive_definite(const ElasticConstants& c);

/// Strain transformation from global (rr, zz, rz, th) to material (1, 2, 12, 3) axes with axis 1 at
/// angle_deg from +r. Stresses transform back with its transpose: sigma_global = T^T sigma_mat.
Mat4 strain_rotation(double angle_deg);

/// The constitutive law of one element in global axes: stress = D (strain - initial_strain) - beta dT.
struct Constitutive {
  Mat4 D = Mat4::Zero();
  Vec4 beta = Vec4::Zero();          ///< thermal stress per degree of temperature rise
  Vec4 out_of_plane = Vec4::Zero();  ///< plane stress only: eps_th = out_of_plane . stress + alpha3 dT (+ initial)
  double alpha3 = 0.0;
  /// A strain the element carries without stress, beside the thermal one (global axes rr, zz,
  /// gamma_rz, th): the plastic strain of an element unloading elastically (plastic_history.hpp).
  Vec4 initial_strain = Vec4::Zero();
  [[nodiscard]] bool has_initial_strain() const { return (initial_strain.array() != 0.0).any(); }
};

/// Plane stress keeps sigma_th = 0 (3x3 reduced stiffness); plane strain keeps eps_th = 0 and
/// reports sigma_th; axisymmetry couples the hoop strain u/r.
Constitutive constitutive(const ElasticConstants& c, AnalysisType analysis, double angle_deg);

/// Bilinear effective stress-strain curve: E eps up to yield, then slope hardening_ratio * E.
struct BilinearCurve {
  double E = 0.0;
  double yield_stress = 0.0;
  double hardening_ratio = 0.0;
  [[nodiscard]] double stress(double strain) const;
};

}  // namespace saasgaps
