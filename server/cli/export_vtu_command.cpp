#include "cli/export_vtu_command.hpp"

#include "cli/file_io.hpp"
#include "cli/result_file.hpp"
#include "io/vtu_writer.hpp"

namespace saasgaps::cli {

int run_export_vtu(const ExportVtuOptions& options) {
  write_file_atomically(options.output_path, io::result_to_vtu(read_result_document(options.result_path)));
  return 0;
}

}  // namespace saasgaps::cli
