#pragma once
/// The example models of schemas/examples, read through the io layer as a user's would be.

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/model/model.hpp"

namespace saasgaps::testing {

/// The document of schemas/examples/<name>.
nlohmann::json example_document(const std::string& name);

/// The model of schemas/examples/<name>.
Model example_model(const std::string& name);

/// Every JSON model of schemas/examples (not the assemblies), sorted, as (file, false), followed for
/// those with classic gaps by (file, true): the run switched to "gaps.method": "exact".
std::vector<std::pair<std::string, bool>> example_runs();

}  // namespace saasgaps::testing
