// The nesting limit of io/json_limits.hpp in every reader of io/: models (streamed and as a tree),
// result subsets, JSON text checks and CBOR. Issue 17: 10^5 nested arrays or objects overflowed the
// stack. Each refusal is one issue at the place of the limit, naming the limit; 64 levels pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

#include "io/json/json_limits.hpp"
#include "io/json/json_subset.hpp"
#include "io/model/model_reader.hpp"
#include "io/restart/stored_state.hpp"

#include <zlib.h>

#include "solver/base/errors.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

constexpr int deep = 100000;

std::string example(const std::string& name) {
  std::ifstream in(std::string(SAASGAPS_EXAMPLES_DIR) + "/" + name);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// `text` with `inner` put in place of the first occurrence of `marker`.
std::string replaced(std::string text, const std::string& marker, const std::string& inner) {
  const auto at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return text.replace(at, marker.size(), inner);
}

std::string nested_arrays(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }

std::string nested_objects(int levels) {
  std::string text;
  for (int k = 0; k < levels; ++k) text += "{\"a\":";
  return text + "1" + std::string(levels, '}');
}

/// The one issue of a NestingTooDeep thrown by `read`.
template <class Read>
InputIssue too_deep(Read read) {
  try {
    read();
  } catch (const NestingTooDeep& e) {
    EXPECT_EQ(e.issues().size(), 1u);
    return e.issues().front();
  }
  ADD_FAILURE() << "no NestingTooDeep";
  return {};
}

std::string repeated(const std::string& token, int count) {
  std::string text;
  for (int k = 0; k < count; ++k) text += token;
  return text;
}

TEST(JsonLimits, DeepArraysInNodesAreRefusedAtTheirPointer) {
  const std::string model = replaced(example("report-problem1.json"), "\"nodes\": [", "\"nodes\": [" + nested_arrays(deep) + ",");
  const InputIssue issue = too_deep([&] { (void)parse_model(model); });
  // Root object (1), nodes (2), then 62 more arrays: the 65th container opens at /nodes/0 + 62 x /0.
  EXPECT_EQ(issue.pointer, shown_pointer("/nodes" + repeated("/0", 63)));
  EXPECT_EQ(issue.pointer, "/nodes" + repeated("/0", 63));  // 132 bytes: shown whole
  EXPECT_NE(issue.detail.find("deeper than 64 levels"), std::string::npos) << issue.detail;
  // The tree reader (imports, request bodies) says the same.
  EXPECT_EQ(too_deep([&] { (void)parse_document(model); }).pointer, issue.pointer);
}

TEST(JsonLimits, DeepObjectsInDescriptionAreRefused) {
  const std::string model = replaced(example("report-problem1.json"), "{", "{\"description\": " + nested_objects(deep) + ",");
  const InputIssue issue = too_deep([&] { (void)parse_model(model); });
  EXPECT_EQ(issue.pointer, "/description" + repeated("/a", 63));
  EXPECT_NE(issue.detail.find("deeper than 64 levels"), std::string::npos) << issue.detail;
}

TEST(JsonLimits, AKeptSectionIsCheckedToo) {
  // elements before nodes: the elements' span is kept and parsed again later; the first pass
  // already stops at the limit.
  const std::string model = replaced(example("report-problem1.json"), "{", "{\"elements\": " + nested_arrays(deep) + ",");
  EXPECT_EQ(too_deep([&] { (void)parse_model(model); }).pointer, shown_pointer("/elements" + repeated("/0", 63)));
}

TEST(JsonLimits, SixtyFourLevelsPassAndSixtyFiveDoNot) {
  EXPECT_NO_THROW((void)parse_document(nested_arrays(64)));
  EXPECT_EQ(parse_document(nested_arrays(64)).dump(), nested_arrays(64));
  EXPECT_EQ(too_deep([] { (void)parse_document(nested_arrays(65)); }).pointer, repeated("/0", 64));
  EXPECT_TRUE(accept_json(nested_objects(64)));
  EXPECT_EQ(too_deep([] { (void)accept_json(nested_objects(65)); }).pointer, shown_pointer(repeated("/a", 64)));
  EXPECT_NO_THROW((void)parse_json_subset(nested_arrays(64), nullptr));
  EXPECT_THROW((void)parse_json_subset(nested_arrays(65), nullptr), NestingTooDeep);
}

TEST(JsonLimits, UnclosedNestingIsRefusedBeforeTheSyntaxError) {
  // `[` x 10^5 (the assembly part of issue 17): no tree is built, the limit answers first.
  EXPECT_EQ(too_deep([] { (void)parse_document(std::string(deep, '[')); }).pointer, repeated("/0", 64));
  EXPECT_THROW((void)parse_model(std::string(deep, '[')), NestingTooDeep);
}

TEST(JsonLimits, ResultSubsetsCountSkippedMembersToo) {
  // A plot keeps only some members; the limit is the document's, kept or not.
  const std::string result = "{\"status\": \"converged\", \"junk\": " + nested_arrays(deep) + "}";
  const auto keep = [](int, std::string_view, std::string_view key) { return key == "status"; };
  EXPECT_EQ(too_deep([&] { (void)parse_json_subset(result, keep); }).pointer, shown_pointer("/junk" + repeated("/0", 63)));
}

TEST(JsonLimits, AcceptJsonStillTellsSyntax) {
  EXPECT_TRUE(accept_json("{\"a\": [1, 2, {\"b\": null}]}"));
  EXPECT_FALSE(accept_json("{\"a\": [1, 2"));
  EXPECT_FALSE(accept_json(""));
}

TEST(JsonLimits, DeepCborIsRefusedBeforeTheDecoderRecurses) {
  // 0x81: an array of one item; 10^5 of them then 0x01. nlohmann's decoder recurses per level.
  std::string cbor(deep, '\x81');
  cbor += '\x01';
  EXPECT_EQ(too_deep([&] { (void)parse_cbor(std::string_view(cbor)); }).pointer, repeated("/0", 64));
  // Maps: 0xA1 (one pair), key "k" (0x61 'k').
  std::string maps = repeated("\xA1\x61k", deep) + '\x01';
  EXPECT_EQ(too_deep([&] { (void)parse_cbor(std::string_view(maps)); }).pointer, shown_pointer(repeated("/k", 64)));
  // Indefinite-length arrays (0x9F ... 0xFF) too.
  std::string open(deep, '\x9F');
  EXPECT_THROW((void)parse_cbor(std::string_view(open)), NestingTooDeep);
  // 10^5 tags: refused as CBOR (tags are not accepted), without recursion.
  std::string tags(deep, '\xC6');
  tags += '\x01';
  EXPECT_THROW((void)parse_cbor(std::string_view(tags)), json::parse_error);
}

TEST(JsonLimits, CborWithinTheLimitDecodesAsFromCbor) {
  const json document = {{"job", 3}, {"state", json::binary({1, 2, 3})}, {"deep", json::parse(nested_arrays(60))},
                         {"text", "x"}, {"number", 1.5}, {"null", nullptr}};
  const std::vector<std::uint8_t> bytes = json::to_cbor(document);
  EXPECT_EQ(parse_cbor(bytes), json::from_cbor(bytes));
  EXPECT_THROW((void)parse_cbor(std::string_view("\xA1\x61", 2)), json::parse_error);
}

/// Levels of arrays and objects in `value` (a scalar: 0).
std::size_t levels(const json& value) {
  std::size_t inner = 0;
  if (value.is_structured()) {
    for (const json& child : value) inner = std::max(inner, levels(child));
    return inner + 1;
  }
  return 0;
}

TEST(JsonLimits, TheExamplesNestFiveLevels) {
  // What the limit's message says of legitimate documents.
  for (const char* name : {"report-problem1.json", "report-problem3-case1.json", "report-beam-model-a.json",
                           "ring-shrink-fit-plane-strain.json", "assemblies/ring-fit.assembly.json",
                           "assemblies/mhw-heat-shield.assembly.json"}) {
    EXPECT_EQ(levels(parse_document(example(name))), 5u) << name;
  }
}

TEST(JsonLimits, LongPointersAreAbbreviatedReadably) {
  EXPECT_EQ(shown_pointer("/nodes/3/0"), "/nodes/3/0");
  const std::string deep_pointer = "/nodes" + repeated("/12345", 63);
  const std::string shown = shown_pointer(deep_pointer);
  EXPECT_LE(shown.size(), 160u) << shown;
  EXPECT_TRUE(shown.starts_with("/nodes/12345/")) << shown;
  EXPECT_TRUE(shown.ends_with("/12345")) << shown;
  EXPECT_NE(shown.find("/..."), std::string::npos) << shown;
  // A key of a megabyte is cut, not copied into the message.
  const std::string key(1 << 20, 'k');
  const std::string cut = shown_pointer("/" + key + "/0");
  EXPECT_LE(cut.size(), 160u);
  EXPECT_TRUE(cut.starts_with("/kkkk")) << cut;
}

TEST(JsonLimits, ACompressedStateThatInflatesBeyondItsLimitIsRefused) {
  // A zlib bomb in the stored-state encoding: "SGZ1" + zlib of 16 MiB of zeros (about 16 KiB).
  const std::vector<std::uint8_t> zeros(std::size_t{16} << 20, 0);
  uLongf size = compressBound(static_cast<uLong>(zeros.size()));
  std::vector<std::uint8_t> bomb(4 + size);
  std::memcpy(bomb.data(), "SGZ1", 4);
  ASSERT_EQ(compress2(bomb.data() + 4, &size, zeros.data(), static_cast<uLong>(zeros.size()), 9), Z_OK);
  bomb.resize(4 + size);
  ASSERT_LT(bomb.size(), std::size_t{64} << 10);
  try {
    (void)decode_stored_state(bomb, "digest", std::size_t{1} << 20);
    FAIL() << "a state inflating beyond 1 MiB was decoded";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("inflates beyond 1048576 bytes"), std::string::npos) << e.what();
  }
  // Under the limit it is judged as a state (these zeros are not one), not refused for its size.
  try {
    (void)decode_stored_state(bomb, "digest", std::size_t{32} << 20);
    FAIL() << "zeros were decoded as a restart state";
  } catch (const SolverError& e) {
    EXPECT_EQ(std::string(e.what()).find("inflates beyond"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace saasgaps::io
