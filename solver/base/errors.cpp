#include "solver/base/errors.hpp"

namespace saasgaps {

namespace {
std::string summarise(const std::vector<InputIssue>& issues) {
  std::string text = "invalid model";
  if (issues.empty()) return text;
  text += ": " + issues.front().pointer + ": " + issues.front().detail;
  if (issues.size() > 1) text += " (and " + std::to_string(issues.size() - 1) + " more)";
  return text;
}
}  // namespace

ModelError::ModelError(std::vector<InputIssue> issues, std::string document)
    : std::runtime_error(summarise(issues)), issues_(std::move(issues)), document_(std::move(document)) {}

}  // namespace saasgaps
