#pragma once
/// Reading a result document (written by `saasgaps solve -o`) for the commands that work on one.

#include <string>

#include <nlohmann/json.hpp>

namespace saasgaps::cli {

/// The parsed result document; a file that cannot be read or is not JSON is a std::runtime_error
/// naming the file. `members` (optional) drops what a reader does not need while parsing.
nlohmann::json read_result_document(const std::string& path, const nlohmann::json::parser_callback_t& members = nullptr);

}  // namespace saasgaps::cli
