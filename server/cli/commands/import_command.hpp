#pragma once
/// `saasgaps import ASSEMBLY.json -o MODEL.json`: a Gmsh mesh and an assembly document (named
/// physical groups for materials, constraints, loads, temperatures and gap pairs) become a model
/// document with generated gap elements (docs/import.md).

#include <string>

#include "io/mesher/gmsh_mesh.hpp"

namespace CLI {
class App;
}

namespace saasgaps::cli {

struct ImportOptions {
  std::string assembly_path;
  std::string model_path;  ///< empty: stdout
  io::MeshLimits mesh;
};

/// --max-mesh-nodes and --mesh-time-limit, for `import` and `serve` (docs/import.md).
void add_mesh_limit_options(CLI::App& command, io::MeshLimits& limits);

/// Exit code 0 when the model was written; throws ModelError (exit 2) with every issue, each at the
/// JSON Pointer of the assembly value it concerns.
int run_import(const ImportOptions& options);

}  // namespace saasgaps::cli
