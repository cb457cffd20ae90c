#pragma once
/// The exact contact mode's input rule: every gap element must give node pairs (solver/contact_pairs).
/// Its failures become model errors at /gaps/elements/<i>, so `validate`, `solve` and the service
/// report them like any other bad input.

#include <vector>

#include "errors.hpp"
#include "model.hpp"

namespace saasgaps::io {

/// One issue per gap element that cannot be paired; none unless gaps.method is "exact".
std::vector<InputIssue> contact_pairing_input_issues(const Model& model);

}  // namespace saasgaps::io
