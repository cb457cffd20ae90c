// A plain block model for the browser tests: big results that solve quickly.
#pragma once

#include <nlohmann/json.hpp>

namespace saasgaps::testing {

/// A plain n x m plane-strain block of quads (no gaps: one iteration), fixed at the bottom and
/// pressed on the top, with units: a big result that solves in about a second.
nlohmann::json plain_block_document(int n, int m);

}  // namespace saasgaps::testing
