#pragma once
/// Reading a result document (written by `saasgaps solve -o`) for the commands that work on one.

#include <string>

#include <nlohmann/json.hpp>

#include "io/json_subset.hpp"

namespace saasgaps::cli {

/// The parsed result document; a file that cannot be read or is not JSON is a std::runtime_error
/// naming the file. `members` (optional) keeps only what a reader needs (io/json_subset.hpp).
nlohmann::json read_result_document(const std::string& path, const io::MemberFilter& members = nullptr);

}  // namespace saasgaps::cli
