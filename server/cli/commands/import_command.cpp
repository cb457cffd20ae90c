#include "cli/commands/import_command.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>

#include "cli/common/file_io.hpp"
#include "cli/common/usage.hpp"
#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps::cli {

void add_mesh_limit_options(CLI::App& command, io::MeshLimits& limits) {
  command.add_option("--max-mesh-nodes", limits.max_nodes, "Most nodes a Gmsh mesh may have (413 / exit 2 beyond)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}))
      ->capture_default_str();
  command.add_option("--mesh-time-limit", limits.seconds, "Seconds Gmsh may take to read or mesh one file")
      ->check(CLI::Range(1, 86400))
      ->capture_default_str();
}

int run_import(const ImportOptions& options) {
  io::set_mesh_limits(options.mesh);
  require_writable(options.model_path, "-o");  // before Gmsh meshes anything
  const nlohmann::json assembly = io::parse_document(read_file(options.assembly_path));
  const std::filesystem::path base = std::filesystem::absolute(options.assembly_path).parent_path();
  const nlohmann::json model = io::import_assembly(assembly, base);
  const std::string text = model.dump(1) + "\n";
  if (options.model_path.empty()) {
    std::cout << text;
  } else {
    write_file_atomically(options.model_path, text);
  }
  const auto count = [&](const char* key, const char* noun) {
    return plural(model.contains(key) ? static_cast<long long>(model[key].size()) : 0, noun);
  };
  const long long gaps = model.contains("gaps") ? static_cast<long long>(model["gaps"]["elements"].size()) : 0;
  // Exact face pairs import as contact surfaces (docs/import.md): say so, not only "0 gap elements".
  const long long pairs = model.contains("contact") ? static_cast<long long>(model["contact"]["pairs"].size()) : 0;
  std::cerr << "imported " << options.assembly_path << ": " << count("nodes", "node") << ", " << count("elements", "element")
            << ", " << plural(gaps, "gap element") << (pairs > 0 ? ", " + plural(pairs, "contact pair") : "") << ", "
            << count("constraints", "constrained node") << '\n';
  return 0;
}

}  // namespace saasgaps::cli
