#pragma once
/// The example models of schemas/examples, read through the io layer as a user's would be.

#include <string>

#include <nlohmann/json.hpp>

#include "model.hpp"

namespace saasgaps::testing {

/// The document of schemas/examples/<name>.
nlohmann::json example_document(const std::string& name);

/// The model of schemas/examples/<name>.
Model example_model(const std::string& name);

}  // namespace saasgaps::testing
