#pragma once
/// `saasgaps validate MODEL.json`: checks a model and prints every error with its JSON Pointer.

#include <string>

namespace saasgaps::cli {

/// Exit code 0 when valid; throws ModelError (exit 2) with every issue when not.
int run_validate(const std::string& path);

}  // namespace saasgaps::cli
