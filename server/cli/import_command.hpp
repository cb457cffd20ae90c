#pragma once
/// `saasgaps import ASSEMBLY.json -o MODEL.json`: a Gmsh mesh and an assembly document (named
/// physical groups for materials, constraints, loads, temperatures and gap pairs) become a model
/// document with generated gap elements (docs/import.md).

#include <string>

namespace saasgaps::cli {

struct ImportOptions {
  std::string assembly_path;
  std::string model_path;  ///< empty: stdout
};

/// Exit code 0 when the model was written; throws ModelError (exit 2) with every issue, each at the
/// JSON Pointer of the assembly value it concerns.
int run_import(const ImportOptions& options);

}  // namespace saasgaps::cli
