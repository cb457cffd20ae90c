// The canonical form of a document (io/json/canonical_json.hpp): key order, number spelling and
// whitespace do not change it; any value does, down to the last bit of a double.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "io/json/canonical_json.hpp"
#include "io/model/model_reader.hpp"
#include "solver/base/result_version.hpp"

namespace saasgaps::io {
namespace {

std::string canonical(const std::string& text) { return canonical_json(parse_document(text)); }

TEST(CanonicalJson, KeyOrderNumberSpellingAndWhitespaceDoNotMatter) {
  const std::string a = R"({"b": [1, 2.5, true, null, "x"], "a": {"y": 1e3, "x": -0.25}})";
  const std::string b = "{\n  \"a\" : {\"x\":-25e-2,\"y\":1000.0},\n\t\"b\":[1.0,25E-1,true,null,\"x\"]}";
  EXPECT_EQ(canonical(a), canonical(b));
  EXPECT_EQ(canonical(a), R"({"a":{"x":-0.25,"y":1000},"b":[1,2.5,true,null,"x"]})");
  EXPECT_EQ(canonical("[1, 1.0, 1e0, 10e-1, 0.1e1]"), "[1,1,1,1,1]");
}

TEST(CanonicalJson, EveryValueMatters) {
  const std::string base = canonical(R"({"E": 30000000.0, "name": "steel", "list": [1, 2]})");
  EXPECT_NE(base, canonical(R"({"E": 30000000.1, "name": "steel", "list": [1, 2]})"));
  EXPECT_NE(base, canonical(R"({"E": 30000000.0, "name": "steel ", "list": [1, 2]})"));
  EXPECT_NE(base, canonical(R"({"E": 30000000.0, "name": "steel", "list": [2, 1]})"));
  EXPECT_NE(base, canonical(R"({"E": 30000000.0, "name": "steel", "list": [1, 2], "x": null})"));
  // The tenth significant digit of one value, and the last bit of a double.
  EXPECT_NE(canonical("[1.234567890]"), canonical("[1.234567891]"));
  EXPECT_NE(canonical("[0.1]"), canonical("[0.10000000000000002]"));
  EXPECT_EQ(canonical("[0.1]"), canonical("[0.10000000000000000001]"));  // the same double
  EXPECT_NE(canonical("[0]"), canonical("[-0.0]"));
}

TEST(CanonicalJson, NumbersPrintShortestRoundTrip) {
  const double values[] = {0.1, 1.0 / 3.0, 6.5e-6, 30.0e6, 1e300, 5e-324, 123456789012345680.0};
  for (const double v : values) {
    const std::string text = canonical_json(nlohmann::json::array({v}));
    EXPECT_EQ(std::strtod(text.substr(1, text.size() - 2).c_str(), nullptr), v) << text;
  }
  EXPECT_EQ(canonical_json(nlohmann::json::array({6.5e-6, 30.0e6})), "[6.5e-06,3e+07]");
}

TEST(CanonicalJson, CacheKeyCarriesTheResultVersionAndTheLength) {
  const std::string text = canonical(R"({"a": 1})");
  const std::string key = cache_key(text);
  EXPECT_EQ(key.rfind("r" + std::to_string(result_version) + "-" + std::to_string(text.size()) + "-", 0), 0u) << key;
  EXPECT_NE(key, cache_key(canonical(R"({"a": 2})")));
}

}  // namespace
}  // namespace saasgaps::io
