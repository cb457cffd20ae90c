#include "cli/commands/export_vtu_command.hpp"

#include "cli/common/file_io.hpp"
#include "cli/common/result_file.hpp"
#include "io/results/vtu_writer.hpp"

namespace saasgaps::cli {

int run_export_vtu(const ExportVtuOptions& options) {
  require_writable(options.output_path, "-o");
  const io::VtuFormat format = io::vtu_format(options.format);
  const std::string& out = options.output_path;
  if (out.size() > 4 && out.compare(out.size() - 4, 4, ".pvd") == 0) {
    io::write_vtu_series(read_result_arrays(options.result_path, io::vtu_result_selection()),
                         out.substr(0, out.size() - 4), format,
                         [](const std::string& file, const std::string& bytes) { write_file_atomically(file, bytes); });
    return 0;
  }
  write_file_atomically(out, io::result_to_vtu(read_result_arrays(options.result_path, io::vtu_result_selection()), format));
  return 0;
}

}  // namespace saasgaps::cli
