#pragma once
/// `saasgaps export-vtu RESULT.json -o FILE.vtu|FILE.pvd [--format binary|ascii]`: the result as a
/// VTK unstructured grid for ParaView (see io/vtu_writer.hpp for what it holds); to a .pvd, the
/// iterations as a collection of .vtu files beside it (io::write_vtu_series).

#include <string>

namespace saasgaps::cli {

struct ExportVtuOptions {
  std::string result_path;
  std::string output_path;
  std::string format = "binary";  ///< binary | ascii
};

/// Exit code 0. Throws for unreadable or unsuitable results; main() maps that to exit 1.
int run_export_vtu(const ExportVtuOptions& options);

}  // namespace saasgaps::cli
