// The model reader's fast path (io/scan_model_reader.hpp, io/json_scan.hpp): it reads every
// example in every layout to the Model of the tree reader, converts numbers as nlohmann's parser
// does to the last bit, gives up on what it does not read itself, and never accepts text that is
// not JSON (byte mutations of an example, against nlohmann's own verdict).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/model/json_scan.hpp"
#include "io/model/model_reader.hpp"
#include "io/model/scan_model_reader.hpp"
#include "io/restart/state_codec.hpp"
#include "solver/base/errors.hpp"
#include "support/text_models.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;
using testing::example_models;
using testing::expect_same_model;
using testing::text_of;

/// The Model of the fast path; fails the test when it gives up or finds an issue.
Model scanned(const std::string& text) {
  SectionReader reader;
  EXPECT_TRUE(scan_model_text(text, reader)) << text.substr(0, 300);
  return reader.finish();
}

bool scan_gives_up(const std::string& text) {
  SectionReader reader;
  return !scan_model_text(text, reader);
}

/// The text with the root's members in reverse order of the contract: every big array comes
/// before what it depends on, so each is skipped and read at the end.
std::string reversed_members(const json& document) {
  std::vector<std::string> members;
  for (auto it = document.begin(); it != document.end(); ++it) members.push_back(json(it.key()).dump() + ":" + it->dump());
  std::string text = "{";
  for (auto it = members.rbegin(); it != members.rend(); ++it) text += (text.size() > 1 ? "," : "") + *it;
  return text + "}";
}

TEST(ScanModelReader, EveryExampleInEveryLayoutIsReadAsTheTreeReaderReadsIt) {
  const auto paths = example_models();
  ASSERT_GE(paths.size(), 10U);
  for (const auto& path : paths) {
    SCOPED_TRACE(path.filename().string());
    const std::string text = text_of(path);
    const json document = json::parse(text);
    const Model tree = read_model(document);
    for (const std::string& layout : {text, document.dump(), document.dump(2), reversed_members(document)}) {
      expect_same_model(scanned(layout), tree);
      std::string digest;
      expect_same_model(parse_model(layout, &digest), tree);
      EXPECT_EQ(digest, model_digest(document));  // computed apart from the read, the same bits
      EXPECT_EQ(model_text_digest(layout), model_digest(document));
    }
  }
}

TEST(ScanModelReader, NumbersAreNlohmannsToTheLastBit) {
  std::mt19937_64 random(23);
  std::vector<std::string> texts{"0",     "1",     "-1",   "18446744073709551615", "-9223372036854775807",
                                 "1.0",   "0.5e1", "1E-5", "-2.5E+300",            "4.9406564584124654e-324",
                                 "1e308", "123456789.123456789e-3"};
  for (int k = 0; k < 20000; ++k) {
    double x = 0.0;
    const std::uint64_t bits = random();
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) texts.push_back(json(x).dump());
    texts.push_back(std::to_string(static_cast<std::int64_t>(random()) >> (k % 60)));
    // Short decimals, the fast path's (Clinger's) and just beyond it: up to 20 digits, a point
    // anywhere, exponents around +-22.
    std::string digits = std::to_string(random() >> (random() % 64));
    const std::size_t point = random() % (digits.size() + 1);
    std::string decimal = (random() % 2 == 0 ? "-" : "") + (point == 0 ? "0" : digits.substr(0, point));
    if (point < digits.size()) decimal += "." + digits.substr(point);
    if (decimal.find('.') == std::string::npos || random() % 2 == 0) {
      decimal += "e" + std::to_string(static_cast<int>(random() % 61) - 30);
    }
    texts.push_back(decimal);
  }
  for (const std::string& text : texts) {
    Number n;
    JsonScan scan(text);
    ASSERT_TRUE(scan.number(n)) << text;
    EXPECT_TRUE(scan.at_end()) << text;
    const json tree = json::parse(text);
    if (tree.is_number_unsigned()) {
      EXPECT_EQ(n.kind, Number::Kind::unsigned_integer) << text;
      EXPECT_EQ(n.unsigned_, tree.get<std::uint64_t>()) << text;
    } else if (tree.is_number_integer()) {
      EXPECT_EQ(n.kind, Number::Kind::signed_integer) << text;
      EXPECT_EQ(n.integer, tree.get<std::int64_t>()) << text;
    } else {
      EXPECT_EQ(n.kind, Number::Kind::floating) << text;
      const double expected = tree.get<double>();
      EXPECT_EQ(std::memcmp(&n.floating, &expected, sizeof expected), 0) << text;
    }
  }
}

TEST(ScanModelReader, RefusesWhatIsNotItsSubsetOfJson) {
  // Not JSON numbers, or numbers left to the reporting path (beyond 64 bits or a double, "-0").
  for (const std::string text : {"01", "1.", ".5", "1e", "1e+", "+1", "-", "- 1", "0x10", "1e400", "-0",
                                 "18446744073709551616", "-9223372036854775809", "NaN", "Infinity", "true", "\"1\""}) {
    Number n;
    JsonScan scan(text);
    EXPECT_FALSE(scan.number(n) && scan.at_end()) << text;
  }
  // Keys: printable ASCII without escapes, followed by a colon.
  for (const std::string text : {R"("\u0069d":)", "\"i\\\"d\":", "\"\xC3\xA9\":", "\"a\tb\":", R"("id" 1)", R"("id)"}) {
    std::string_view key;
    JsonScan scan(text);
    EXPECT_FALSE(scan.key(key)) << text;
  }
  std::string_view key;
  JsonScan scan(R"( "id" : )");
  ASSERT_TRUE(scan.key(key));
  EXPECT_EQ(key, "id");
}

TEST(ScanModelReader, SkipsAValueWithoutJudgingIt) {
  const std::string text = R"( {"a":["]\"}",{"b":[1,2]}],"c":"\\"} ,7)";
  JsonScan scan(text);
  std::string_view span;
  ASSERT_TRUE(scan.skip_value(span, 4));
  EXPECT_EQ(span, R"({"a":["]\"}",{"b":[1,2]}],"c":"\\"})");
  EXPECT_TRUE(scan.consume(','));
  ASSERT_TRUE(scan.skip_value(span, 4));
  EXPECT_EQ(span, "7");
  JsonScan deep(text);
  EXPECT_FALSE(deep.skip_value(span, 3));  // opens a fourth level
  JsonScan open(R"({"a":[1,2})");
  EXPECT_FALSE(open.skip_value(span, 10));
}

TEST(ScanModelReader, GivesUpOnAnythingItDoesNotReadItselfAndParseModelStillJudgesIt) {
  const json document = json::parse(text_of(example_models().front()));
  const std::string text = document.dump();
  ASSERT_FALSE(scan_gives_up(text));
  const auto node = document["nodes"][0].dump();
  const auto at = text.find(node);
  ASSERT_NE(at, std::string::npos);
  const auto with_node = [&](const std::string& replacement) {
    std::string t = text;
    t.replace(at, node.size(), replacement);
    return t;
  };
  const std::string id = std::to_string(document["nodes"][0]["id"].get<int>());
  // Valid models it leaves to the reporting path: read all the same.
  const std::vector<std::string> valid{
      "\xEF\xBB\xBF" + text,                                  // a byte order mark (nlohmann skips it)
      with_node(R"({"\u0069d":)" + id + R"(,"r":0,"z":0})"),   // a key spelled with an escape
      with_node(R"({"id":)" + id + R"(,"r":-0,"z":0})"),       // "-0", an integer to nlohmann only
  };
  for (const std::string& t : valid) {
    EXPECT_TRUE(scan_gives_up(t)) << t.substr(0, 200);
    expect_same_model(parse_model(t), read_model(json::parse(t)));
  }
  const std::vector<std::string> invalid{
      text + " x",                                                // something after the document
      text.substr(0, text.size() - 1),                            // truncated
      "{\"extra\":1," + text.substr(1),                          // an unknown root key
      "{\"title\":\"a\"," + text.substr(1),                      // a repeated root key
      with_node(R"({"id":)" + id + R"(,"r":0,"z":0,"r":1})"),     // a repeated key in an item
      with_node(R"({"id":)" + id + R"(.0,"r":0,"z":0})"),         // an id that is no integer
      with_node(R"({"id":)" + id + R"(,"r":"0","z":0})"),         // a string for a number
      with_node(R"({"id":)" + id + R"(,"r":1e999,"z":0})"),       // beyond a double
      with_node(R"({"id":)" + id + R"(,"r":0,"z":0,"w":0})"),     // an unknown key
      with_node(R"({"id":)" + id + R"(,"r":0,"z":0})" + "," + node),  // a repeated id
  };
  for (const std::string& t : invalid) {
    EXPECT_TRUE(scan_gives_up(t)) << t.substr(0, 200);
    EXPECT_THROW((void)parse_model(t), ModelError) << t.substr(0, 200);
  }
  // A repeated key in a small member: the tree parser refuses it, and so the scan gives up.
  std::string repeated = text;
  const auto analysis = repeated.find("\"analysis\":{");
  repeated.insert(analysis + 12, "\"type\":\"plane_strain\",");
  EXPECT_TRUE(scan_gives_up(repeated));
}

TEST(ScanModelReader, NeverAcceptsTextThatIsNotJson) {
  // Byte mutations of a small example: whatever the scan accepts, nlohmann's parser accepts, and
  // both give the same Model.
  std::string seed;
  for (const auto& path : example_models()) {
    const std::string text = text_of(path);
    if (seed.empty() || text.size() < seed.size()) seed = text;
  }
  std::mt19937 random(2023);
  const std::string bytes = "{}[]\",:\\ 0123456789.eE+-tfnul\x01\xC3\xFF";
  int accepted = 0;
  int refused = 0;
  for (int k = 0; k < 3000; ++k) {
    std::string text = seed;
    for (int m = 1 + static_cast<int>(random() % 3); m > 0; --m) {
      const std::size_t at = random() % text.size();
      const char byte = bytes[random() % bytes.size()];
      switch (random() % 3) {
        case 0: text[at] = byte; break;
        case 1: text.insert(at, 1, byte); break;
        default: text.erase(at, 1); break;
      }
    }
    SectionReader reader;
    if (!scan_model_text(text, reader)) {
      ++refused;
      continue;
    }
    ++accepted;
    ASSERT_TRUE(json::accept(text)) << text;
    std::optional<Model> from_scan;
    try {
      from_scan = reader.finish();
    } catch (const ModelError&) {
      continue;  // an issue: parse_model reads it again with the reporting path
    }
    expect_same_model(*from_scan, read_model(json::parse(text)));
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace saasgaps::io
