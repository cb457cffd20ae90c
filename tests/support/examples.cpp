#include "support/examples.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/model/model_reader.hpp"

namespace saasgaps::testing {

nlohmann::json example_document(const std::string& name) {
  const std::string path = std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read example " + path);
  return nlohmann::json::parse(in);
}

Model example_model(const std::string& name) { return io::read_model(example_document(name)); }

std::vector<std::pair<std::string, bool>> example_runs() {
  std::vector<std::string> files;
  for (const std::filesystem::directory_entry& entry : std::filesystem::directory_iterator(SAASGAPS_EXAMPLES_DIR)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::pair<std::string, bool>> out;
  for (const std::string& file : files) {
    out.emplace_back(file, false);
    const nlohmann::json doc = example_document(file);
    if (doc.contains("gaps") && doc["gaps"].value("method", "classic") == "classic") out.emplace_back(file, true);
  }
  return out;
}

}  // namespace saasgaps::testing
