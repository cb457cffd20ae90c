#pragma once
/// Random mutations of JSON documents with a fixed seed, for the fuzz tests: the service's
/// (tests/service/fuzz_test.cpp) and the model reader's agreement with the tree reader
/// (tests/io/model/model_reader_test.cpp).

#include <random>
#include <vector>

#include <nlohmann/json.hpp>

namespace saasgaps::testing {

using nlohmann::json;

/// Every value's pointer in a document, for picking what to mutate.
inline void collect_pointers(const json& value, const json::json_pointer& here, std::vector<json::json_pointer>& out) {
  out.push_back(here);
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) collect_pointers(child, here / key, out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) collect_pointers(value[i], here / i, out);
  }
}

inline json random_value(std::mt19937& random) {
  switch (std::uniform_int_distribution<int>(0, 11)(random)) {
    case 0: return nullptr;
    case 1: return true;
    case 2: return -1;
    case 3: return 0;
    case 4: return 1e308;
    case 5: return -1e-320;
    case 6: return "\xF0\x9F\x92\xA5 text";
    case 7: return json::array();
    case 8: return json::object();
    case 9: return 123456789012345LL;
    case 10: return json::array({1, 2, 3, 4, 5});
    default: return std::uniform_real_distribution<double>(-10.0, 10.0)(random);
  }
}

/// 1-3 mutations: replace a value, delete a member or element, or duplicate an array element.
inline json mutate(json document, std::mt19937& random) {
  const int count = std::uniform_int_distribution<int>(1, 3)(random);
  for (int m = 0; m < count; ++m) {
    std::vector<json::json_pointer> pointers;
    collect_pointers(document, json::json_pointer(), pointers);
    const json::json_pointer target = pointers[std::uniform_int_distribution<std::size_t>(0, pointers.size() - 1)(random)];
    const int kind = std::uniform_int_distribution<int>(0, 3)(random);
    if (target.empty()) {
      document = kind == 0 ? random_value(random) : document;
      continue;
    }
    json& parent = document[target.parent_pointer()];
    if (kind == 0 || kind == 1) {
      document[target] = random_value(random);
    } else if (kind == 2) {
      if (parent.is_object()) parent.erase(target.back());
      if (parent.is_array()) parent.erase(static_cast<std::size_t>(std::stoul(target.back())));
    } else if (parent.is_array()) {
      parent.push_back(document[target]);
    }
  }
  return document;
}

}  // namespace saasgaps::testing
