#pragma once
/// `saasgaps probe RESULT.json --at R,Z [--field NAME]... [--json]`: the values of a result at a
/// point (plot/result/point_probe.hpp): the recovered stresses interpolated in the element holding
/// it (each material's side at an interface), the displacement and the temperature, as text lines
/// or as the JSON the service's GET /v1/jobs/{id}/probe returns.

#include <string>
#include <vector>

namespace saasgaps::cli {

struct ProbeOptions {
  std::string result_path;
  std::string at;                   ///< "r,z"
  std::vector<std::string> fields;  ///< names of plot fields (each may be a comma list); empty: the default set
  bool json = false;
};

/// Exit code 0. A malformed point, an unknown field or a point outside the mesh: std::invalid_argument
/// (main() maps it to exit 1 with the message).
int run_probe(const ProbeOptions& options);

}  // namespace saasgaps::cli
