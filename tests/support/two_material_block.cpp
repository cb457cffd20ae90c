#include "support/two_material_block.hpp"

#include <fstream>
#include <string>

namespace saasgaps::testing {

nlohmann::json two_material_block() {
  std::ifstream in(std::string(SAASGAPS_EXAMPLES_DIR) + "/quickstart-plane-strain-block.json");
  nlohmann::json model = nlohmann::json::parse(in);
  nlohmann::json hot = model["materials"][0];
  hot["id"] = 2;
  hot["table"][0]["alpha"] = 13.0e-6;
  model["materials"].push_back(hot);
  model["elements"][1]["material"] = 2;
  model["elements"][3]["material"] = 2;
  return model;
}

}  // namespace saasgaps::testing
