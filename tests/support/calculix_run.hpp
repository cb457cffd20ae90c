// CalculiX (Debian's calculix-ccx, `ccx` 2.20) run on the same model document, for side-by-side
// verification: the same nodes, elements, material, constraints and nodal forces, solved by an
// independent program in the same test run.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace saasgaps::testing {

/// What CalculiX printed for every node: displacements (u_r, u_z, *NODE PRINT) and its nodal
/// stresses, extrapolated from the integration points and averaged over the elements around the
/// node (*NODE FILE, read from the .frd), in the model's plane: (sigma_r, sigma_z, sigma_theta, tau_rz) = CalculiX's (S11, S22,
/// S33, S12).
struct CalculixNodes {
  std::map<int, std::array<double, 2>> u;
  std::map<int, std::array<double, 4>> sigma;
};

/// The model as a CalculiX deck: plane_stress or plane_strain (thickness from the analysis), the
/// first row of the first isotropic material (E, nu), quad8 elements as CPS8/CPE8 (CPS8R/CPE8R for
/// "integration": "reduced") and tri6 as CPS6/CPE6, constraints as *BOUNDARY (fixed or
/// prescribed), `loads.nodal_forces` as *CLOAD, normal `loads.pressures` on [a, b] edges as *DLOAD
/// on the element's face. Anything else in the model is an error
/// (std::invalid_argument): the comparison must run the same problem.
std::string calculix_deck(const nlohmann::json& model);

/// Runs `ccx` on calculix_deck(model) in a fresh temporary folder; nullopt when ccx is not
/// installed (deploy/test.sh installs it). Throws std::runtime_error when ccx fails.
std::optional<CalculixNodes> run_calculix(const nlohmann::json& model);

}  // namespace saasgaps::testing
