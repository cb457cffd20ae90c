#include "cli/validate_command.hpp"

#include <iostream>

#include "cli/file_io.hpp"
#include "io/model_reader.hpp"
#include "io/restraint_issues.hpp"

namespace saasgaps::cli {

int run_validate(const std::string& path) {
  const Model model = io::parse_model(read_file(path));
  io::require_restrained(model);
  std::cout << "valid: " << path << ": " << model.nodes.size() << " nodes, " << model.elements.size()
            << " elements, " << model.gap_count() << " gap elements, " << model.materials.size() << " materials\n";
  return 0;
}

}  // namespace saasgaps::cli
