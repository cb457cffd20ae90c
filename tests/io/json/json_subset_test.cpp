// io::parse_json_subset: the tree of only the members a filter keeps, checked against nlohmann's
// own parser on the same text.

#include "io/json/json_subset.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace saasgaps::io {
namespace {

using nlohmann::json;

const char* const document = R"({
  "title": "t", "status": "converged",
  "nodes": [{"id": 1, "r": 0.5, "z": 1e-3}, {"id": 2, "r": 1, "z": -2}],
  "elements": [{"id": 7, "nodes": [1, 2], "sigma_r": -1.5, "extra": {"deep": [1, [2, {"x": null}]]}},
               {"id": 8, "nodes": [2, 1], "sigma_r": 2.25, "extra": "s"}],
  "history": [{"iteration": 1, "gap_closures": [100, 99.5]}],
  "flags": [true, false, null], "empty": {}, "none": []
})";

TEST(JsonSubset, WithoutAFilterItIsTheWholeDocument) {
  EXPECT_EQ(parse_json_subset(document, nullptr), json::parse(document));
  EXPECT_EQ(parse_json_subset("[1, 2.5, \"x\"]", nullptr), json::parse("[1, 2.5, \"x\"]"));
  EXPECT_EQ(parse_json_subset("42", nullptr), json(42));
}

TEST(JsonSubset, DropsRootMembersAndMembersUnderASection) {
  const MemberFilter keep = [](int depth, std::string_view section, std::string_view key) {
    if (depth == 1) return key != "nodes";
    if (depth == 3 && section == "elements") return key == "id" || key == "sigma_r";
    return true;
  };
  json expected = json::parse(document);
  expected.erase("nodes");
  for (json& e : expected["elements"]) {
    e.erase("nodes");
    e.erase("extra");
  }
  EXPECT_EQ(parse_json_subset(document, keep), expected);
}

TEST(JsonSubset, TellsTheFilterTheDepthAndSectionOfEveryKey) {
  std::string seen;
  const MemberFilter record = [&seen](int depth, std::string_view section, std::string_view key) {
    seen += std::to_string(depth) + ":" + std::string(section) + ":" + std::string(key) + " ";
    return true;
  };
  (void)parse_json_subset(R"({"a": {"b": [{"c": 1}]}, "d": 2})", record);
  EXPECT_EQ(seen, "1::a 2:a:b 4:a:c 1::d ");
}

TEST(JsonSubset, RepeatedKeysKeepTheLastValueAsNlohmannDoes) {
  const char* text = R"({"a": 1, "b": {"c": 2}, "a": [3]})";
  EXPECT_EQ(parse_json_subset(text, nullptr), json::parse(text));
}

TEST(JsonSubset, TextThatIsNotJsonThrowsNlohmannsParseError) {
  EXPECT_THROW((void)parse_json_subset("{\"a\": [1, 2", nullptr), json::parse_error);
  EXPECT_THROW((void)parse_json_subset("{\"a\" 1}", [](int, std::string_view, std::string_view) { return false; }),
               json::parse_error);
  EXPECT_THROW((void)parse_json_subset("", nullptr), json::parse_error);
}

}  // namespace
}  // namespace saasgaps::io
