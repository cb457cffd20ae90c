#include "support/examples.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/model_reader.hpp"

namespace saasgaps::testing {

nlohmann::json example_document(const std::string& name) {
  const std::string path = std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read example " + path);
  return nlohmann::json::parse(in);
}

Model example_model(const std::string& name) { return io::read_model(example_document(name)); }

}  // namespace saasgaps::testing
