#include "cli/commands/validate_command.hpp"

#include <iostream>

#include "cli/common/file_io.hpp"
#include "cli/common/usage.hpp"
#include "io/model/model_reader.hpp"
#include "io/sections/restraint_issues.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps::cli {

int run_validate(const std::string& path) {
  const Model model = io::parse_model(read_file(path));
  io::require_restrained(model);
  const auto count = [](std::size_t n, const char* noun) { return plural(static_cast<long long>(n), noun); };
  std::cout << "valid: " << path << ": " << count(model.nodes.size(), "node") << ", " << count(model.elements.size(), "element")
            << ", " << count(model.gap_count(), "gap element") << ", " << count(model.materials.size(), "material") << '\n';
  return 0;
}

}  // namespace saasgaps::cli
