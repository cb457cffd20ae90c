#include "cli/result_file.hpp"

#include <stdexcept>

#include "cli/file_io.hpp"
#include "io/document_kind.hpp"
#include "io/json_limits.hpp"

namespace saasgaps::cli {

nlohmann::json read_result_document(const std::string& path, const io::MemberFilter& members) {
  nlohmann::json document;
  try {
    document = io::parse_json_subset(read_file(path), members);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path + " is not a result document (JSON): " + e.what());
  } catch (const io::NestingTooDeep& e) {
    throw std::runtime_error(path + " is not a result document: " + e.issues().front().pointer + ": " +
                             e.issues().front().detail);
  }
  switch (io::document_kind(document)) {
    case io::DocumentKind::result: return document;
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

}  // namespace saasgaps::cli
