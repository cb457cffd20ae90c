/// The shape checks every section of the assembly makes through the shared rules of
/// io/json/value_rules.hpp (worded as the model reader words them), and the files a value names,
/// each reported at the value's pointer.
#include "io/import/assembly_importer.hpp"

#include <optional>
#include <string>
#include <utility>

#include "io/json/json_pointer.hpp"
#include "io/json/value_rules.hpp"

namespace saasgaps::io::assembly {

bool Importer::object(const json& v, const std::string& p, std::initializer_list<std::string_view> required,
                      std::initializer_list<std::string_view> optional) {
  return check_object(v, p, {required.begin(), required.size()}, {optional.begin(), optional.size()}, reporter());
}

const json* Importer::array(const json& parent, const std::string& p, std::string_view key, bool non_empty) {
  const auto it = parent.find(key);
  if (it == parent.end()) return nullptr;
  return check_array(*it, pointer_append(p, key), key, non_empty ? 1 : 0, reporter());
}

std::optional<double> Importer::number(const json& o, const std::string& p, std::string_view key, const Range& range) {
  const auto it = o.find(key);
  if (it == o.end()) return std::nullopt;
  return check_number(*it, pointer_append(p, key), key, range, reporter());
}

std::optional<std::string> Importer::string(const json& o, const std::string& p, std::string_view key) {
  const auto it = o.find(key);
  if (it == o.end()) return std::nullopt;
  return check_string(*it, pointer_append(p, key), key, reporter());
}

std::optional<fs::path> Importer::resolve_file(const std::string& name, const std::string& pointer) {
  std::string problem;
  auto path = files_.resolve(name, problem);
  if (!path) report(pointer, std::move(problem));
  return path;
}

}  // namespace saasgaps::io::assembly
