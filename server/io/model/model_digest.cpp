#include "io/model/model_digest.hpp"

namespace saasgaps::io {

using nlohmann::json;

std::string model_digest(const json& model_document) {
  json significant = model_document;
  if (significant.is_object()) {
    significant.erase("title");
    significant.erase("description");
    significant.erase("output");
  }
  Fingerprint f;
  f.add(significant.dump());
  return f.hex();
}

}  // namespace saasgaps::io
