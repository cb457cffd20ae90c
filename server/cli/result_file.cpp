#include "cli/result_file.hpp"

#include <stdexcept>

#include "cli/file_io.hpp"

namespace saasgaps::cli {

nlohmann::json read_result_document(const std::string& path) {
  try {
    return nlohmann::json::parse(read_file(path));
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path + " is not a result document (JSON): " + e.what());
  }
}

}  // namespace saasgaps::cli
