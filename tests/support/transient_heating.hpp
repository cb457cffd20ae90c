#pragma once
/// Example models turned into transient heat conduction runs, for the restart tests of every layer
/// (solver, CLI, service): the model's given temperatures are dropped, the surface of its solid
/// elements nearest the origin (the inner surface of a ring) is held at `hot` from t = 0 (the rest
/// insulated, everything starting at the reference temperature 0),
/// and the stress analysis runs at each of `output_times` (a load step each) with the conduction's
/// temperatures, carrying gap, contact and plastic state from one to the next.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace saasgaps::testing {

struct TransientHeating {
  double hot = 1100.0;             ///< temperature held on the top surface
  double alpha = 0.0;              ///< expansion coefficient to set on every table row (0: keep the model's)
  /// With a yield stress > 0: bilinear plasticity of every material (this yield stress, hardening
  /// ratio 1/3), so that plastic state carries from one output time to the next.
  double yield_stress = 0.0;
  double time_step = 0.05;
  std::vector<double> output_times = {0.25, 0.5, 0.75, 1.0};
};

/// schemas/examples/<name> as such a run. Its conductivity k = 1, specific heat c = 1 and density 1
/// on every material (model units).
nlohmann::json transient_heating(const std::string& name, const TransientHeating& heating = {});

}  // namespace saasgaps::testing
