#pragma once
/// The solver's typed errors. Bad input and run-time failures are exceptions carrying the values a
/// user needs to act; internal invariants are asserts. The server maps these to HTTP responses and
/// the CLI to exit codes, each in one place.

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace saasgaps {

/// One problem with the input, located by a JSON Pointer into the model document.
struct InputIssue {
  std::string pointer;
  std::string detail;
};

/// An input document is invalid; carries every problem found, not just the first. document: what
/// the pointers point into, as messages name it: "model" (the default), "assembly", "resume
/// settings".
class ModelError : public std::runtime_error {
 public:
  explicit ModelError(std::vector<InputIssue> issues, std::string document = "model");
  [[nodiscard]] const std::vector<InputIssue>& issues() const { return issues_; }
  [[nodiscard]] const std::string& document() const { return document_; }

 private:
  std::vector<InputIssue> issues_;
  std::string document_;
};

/// One degree of freedom: a node (by user id) and a direction, 'r' or 'z'.
struct NodeDof {
  int node_id = 0;
  char direction = 'r';
};

/// The stiffness matrix is singular or not positive definite: a mechanism (an unrestrained body or
/// an unconnected node). Names the degrees of freedom where the factorization broke down.
class SingularModelError : public std::runtime_error {
 public:
  SingularModelError(std::string what, std::vector<NodeDof> dofs)
      : std::runtime_error(std::move(what)), dofs_(std::move(dofs)) {}
  [[nodiscard]] const std::vector<NodeDof>& dofs() const { return dofs_; }

 private:
  std::vector<NodeDof> dofs_;
};

/// A failure while solving a valid model (for example a resume state that does not fit the model).
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace saasgaps
