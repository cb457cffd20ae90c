#pragma once
/// What the quadratic element families (tri6, quad8, quad9) do not carry yet, judged on a model
/// otherwise valid, as model errors at their JSON Pointers:
/// - a gap element along an edge of a quadratic element (gap elements stay 4-node elements between
///   straight edges; the mid-side node would be left out of the contact), at /gaps/elements/<g>/nodes;
/// - heat conduction (a `thermal` section) with quadratic elements, at the first such element's
///   /elements/<e>/nodes.
/// The report's quadrilateral, the CST and quad4i (4 nodes, conducting as the report's quadrilateral)
/// have no limit here.

#include <vector>

#include "solver/base/errors.hpp"
#include "solver/model/model.hpp"

namespace saasgaps::io {

std::vector<InputIssue> element_family_input_issues(const Model& model);

}  // namespace saasgaps::io
