#pragma once
/// The tree VTU writer (before issue 23), the reference of io/vtu_writer's typed one: the same
/// functions over a tree of the whole result.

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/results/vtu_encoding.hpp"

namespace saasgaps::io::reference {

std::string result_to_vtu(const nlohmann::json& result, VtuFormat format = VtuFormat::binary);

void write_vtu_series(const nlohmann::json& result, const std::string& stem, VtuFormat format,
                      const std::function<void(const std::string& file, const std::string& bytes)>& write);

}  // namespace saasgaps::io::reference
