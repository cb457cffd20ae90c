#pragma once
/// What the quadratic element families (tri6, quad8, quad9) do not carry yet, judged on a model
/// otherwise valid, as model errors at their JSON Pointers: a gap element along an edge of a
/// quadratic element (gap elements stay 4-node elements between straight edges; the mid-side node
/// would be left out of the contact), at /gaps/elements/<g>/nodes. Contact surfaces, with friction
/// and contact conductance, run on their edges (solver/mortar, docs/contact-surfaces.md section 7);
/// heat conduction on every family (solver/thermal/isoparametric_conduction.hpp). The report's
/// quadrilateral, the CST and quad4i have no limit here.

#include <vector>

#include "solver/base/errors.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::io {

std::vector<InputIssue> element_family_input_issues(const Model& model);

}  // namespace saasgaps::io
