#pragma once
/// Where the generated model's values come from in the assembly, and the model reader's findings
/// on the generated model reported there: the importer judges the assembly's own shapes, the model
/// reader everything the model rules say of the values generated from it (docs/architecture.md,
/// "Model rules, once").

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/base/errors.hpp"

namespace saasgaps::io::assembly {

class GeneratedOrigins {
 public:
  /// A finding at `generated` or below it is reported at `written`, as "the generated <pointer>:
  /// ..." or, when `same_keys` (the generated object has the assembly object's keys), at `written`
  /// with the rest of the pointer, as the reader words it.
  void add(std::string generated, std::string written, bool same_keys = false);

  /// The model reader's findings on `model` (none when it reads), each at the assembly pointer it
  /// comes from: an origin's, the finding's own for a block that passed through (the same pointer in
  /// both documents), else "/mesh" with the generated pointer in its text.
  std::vector<InputIssue> findings(const nlohmann::json& model) const;

 private:
  struct Origin {
    std::string generated;
    std::string written;
    bool same_keys = false;
  };
  std::vector<Origin> origins_;
};

}  // namespace saasgaps::io::assembly
