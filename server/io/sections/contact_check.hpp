#pragma once
/// The contact input rules the solver judges on a model otherwise valid: every gap element of the
/// exact mode must give node pairs (solver/contact_pairs), every contact surface must be a chain of
/// boundary edges (solver/contact_surface). Their failures become model errors at their JSON
/// Pointers, so `validate`, `solve` and the service report them like any other bad input.

#include <vector>

#include "solver/base/errors.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::io {

/// One issue per gap element that cannot be paired; none unless gaps.method is "exact".
std::vector<InputIssue> contact_pairing_input_issues(const Model& model);

/// The contact surfaces' chain rule (solver/contact_surface.hpp): one issue per refused edge, at
/// /contact/surfaces/<i>/edges/<k>, saying why (not a side of exactly one solid element, not a chain);
/// and one at /contact/pairs/<k>/friction per pair with friction > 0 when gaps.method is "exact".
std::vector<InputIssue> contact_surface_input_issues(const Model& model);

}  // namespace saasgaps::io
