#include "cli/common/result_file.hpp"

#include <filesystem>
#include <stdexcept>

#include "io/json/json_limits.hpp"
#include "io/model/document_kind.hpp"
#include "io/results/result_arrays.hpp"

namespace saasgaps::cli {

namespace {

/// Throws unless `document` (its root members; the nodes and elements need not be there) is a result.
void require_result(const nlohmann::json& document, const std::string& path) {
  switch (io::document_kind(document)) {
    case io::DocumentKind::result: return;
    case io::DocumentKind::model:
      throw std::runtime_error(path + " is a model, not a result; run solve first: saasgaps solve " + path +
                               " -o RESULT.json");
    case io::DocumentKind::restart_state:
      throw std::runtime_error(path + " is a restart state, not a result; the result is what saasgaps solve -o writes");
    case io::DocumentKind::unknown: break;
  }
  throw std::runtime_error(path + " is not a result document: it has no status and history (it is written by "
                                  "saasgaps solve -o)");
}

[[noreturn]] void nesting_too_deep(const std::string& path, const io::NestingTooDeep& e) {
  throw std::runtime_error(path + " is not a result document: " + e.issues().front().pointer + ": " +
                           e.issues().front().detail);
}

}  // namespace

io::ResultArrays read_result_arrays(const std::string& path, const io::ResultSelection& selection) {
  // fopen opens a directory, whose read then fails as an empty document: say what it is.
  if (std::filesystem::is_directory(path)) throw std::runtime_error("cannot read " + path + ": it is a directory, not a file");
  io::ResultArrays arrays;
  try {
    arrays = io::read_result_arrays_file(path, selection);
  } catch (const io::ResultTextError& e) {
    throw std::runtime_error(path + " is not a result document (JSON): " + e.what());
  } catch (const io::NestingTooDeep& e) {
    nesting_too_deep(path, e);
  }
  require_result(arrays.document, path);
  return arrays;
}

}  // namespace saasgaps::cli
