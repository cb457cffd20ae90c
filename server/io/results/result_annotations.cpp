#include "io/results/result_annotations.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace saasgaps::io {

void write_units(JsonWriter& out, const Units& units) {
  const std::array<std::pair<const char*, const std::string*>, 4> names{
      {{"force", &units.force}, {"length", &units.length}, {"stress", &units.stress}, {"temperature", &units.temperature}}};
  if (std::none_of(names.begin(), names.end(), [](const auto& n) { return !n.second->empty(); })) return;
  out.key("units").begin_object();
  for (const auto& [key, name] : names) {
    if (!name->empty()) out.field(key, *name);
  }
  out.end_object();
}

double contact_pressure(double sigma_m) { return std::max(0.0, -sigma_m); }

}  // namespace saasgaps::io
