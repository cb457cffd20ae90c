#include "io/contact_check.hpp"

#include "contact_pairs.hpp"
#include "io/json_pointer.hpp"

namespace saasgaps::io {

std::vector<InputIssue> contact_pairing_input_issues(const Model& model) {
  std::vector<InputIssue> issues;
  if (!model.gaps || model.gaps->method != GapMethod::exact) return issues;
  // The reader keeps gap elements in document order, so index i is /gaps/elements/i.
  for (const PairingIssue& issue : contact_pairing_issues(model)) {
    issues.push_back({pointer_append("/gaps/elements", issue.gap), issue.detail});
  }
  return issues;
}

}  // namespace saasgaps::io
