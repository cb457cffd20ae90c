#pragma once
/// schemas/examples/quickstart-plane-strain-block.json (2 x 2 elements, uniform sigma_z = -1000 psi,
/// heated from 70 to 200 degF) with its right column (elements 2 and 4) in a second material of
/// twice the expansion: an interface at r = 1 across which the out-of-plane stress jumps, for the
/// tests of probes at material sides (CLI and service).

#include <nlohmann/json.hpp>

namespace saasgaps::testing {

nlohmann::json two_material_block();

}  // namespace saasgaps::testing
