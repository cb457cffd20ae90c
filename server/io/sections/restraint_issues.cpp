#include "io/sections/restraint_issues.hpp"

#include <string>

#include "io/json/json_pointer.hpp"
#include "solver/base/errors.hpp"
#include "solver/model/restraint_check.hpp"

namespace saasgaps::io {

namespace {

/// "node 3 (/nodes/2), node 4 (/nodes/3), ... and 120 more"
std::string node_list(const Model& model, const std::vector<int>& nodes) {
  constexpr std::size_t shown = 8;
  std::string text;
  for (std::size_t k = 0; k < nodes.size() && k < shown; ++k) {
    if (k > 0) text += ", ";
    text += "node " + std::to_string(model.nodes[nodes[k]].id) + " (" + pointer_append("/nodes", static_cast<std::size_t>(nodes[k])) + ")";
  }
  if (nodes.size() > shown) text += " and " + std::to_string(nodes.size() - shown) + " more";
  return text;
}

std::string joined(const std::vector<const char*>& words) {
  std::string text;
  for (const char* w : words) text += (text.empty() ? "" : ", ") + std::string(w);
  return text;
}

}  // namespace

void require_restrained(const Model& model) {
  std::vector<InputIssue> issues;
  const bool axisymmetric = model.analysis == AnalysisType::axisymmetric;
  for (const RestraintIssue& issue : check_restraint(model)) {
    const std::string pointer = pointer_append("/nodes", static_cast<std::size_t>(issue.nodes.front()));
    const std::string id = std::to_string(model.nodes[issue.nodes.front()].id);
    if (issue.kind == RestraintIssue::Kind::orphan_node) {
      issues.push_back({pointer, "node " + id + " belongs to no element or gap element, so nothing holds it; "
                                 "use it in an element, prescribe both r and z, or remove it"});
      continue;
    }
    issues.push_back(
        {pointer, "the body of " + std::to_string(issue.nodes.size()) + " nodes joined through elements and gaps (" +
                      node_list(model, issue.nodes) + ") is not restrained: it is free to move (" +
                      joined(issue.motions) + ")" +
                      (axisymmetric ? "; an axisymmetric body needs at least one prescribed z"
                                    : "; a plane body needs prescribed components that stop both translations "
                                      "and the rotation (e.g. r and z at one node and r or z at another)")});
  }
  if (!issues.empty()) throw ModelError(std::move(issues));
}

}  // namespace saasgaps::io
