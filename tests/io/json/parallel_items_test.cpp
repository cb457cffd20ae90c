/// An array's items formatted on several threads (io/parallel_items.hpp) give the text of the same
/// items written one after the other: compact and pretty, at any depth, for any piece size, thread
/// count and look-ahead; the sink still gets pieces of at most the writer's buffer; a failure in an
/// item or in the sink comes back to the caller.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <ios>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json/json_writer.hpp"
#include "io/json/parallel_items.hpp"

namespace saasgaps::io {
namespace {

/// Item i: an object with doubles of every magnitude (from bit patterns), an integer, a string that
/// needs escaping and a nested array; every 97th item is long enough to fill the writer's buffer on
/// its own.
void write_item(JsonWriter& out, std::size_t i) {
  std::mt19937_64 rng(i);
  out.begin_object().field("id", static_cast<std::int64_t>(i));
  out.key("values").begin_array();
  const std::size_t values = i % 97 == 0 ? 5000 : i % 5;
  for (std::size_t k = 0; k < values; ++k) {
    const std::uint64_t bits = rng();
    double v = 0.0;
    std::memcpy(&v, &bits, sizeof v);
    out.value(v);  // nan and inf among them: null
  }
  out.end_array();
  out.field("name", "item \"" + std::to_string(i) + "\"\t\xc3\xa9").field("yes", i % 2 == 0).end_object();
}

/// The document {"a": 1, "list": [[ items ]], "z": "end"}: the items two levels down, so that pretty
/// indentation and commas depend on the levels a continuation carries.
std::string document(std::size_t count, bool pretty, const ItemPieces* pieces) {
  std::string text;
  JsonWriter out(string_sink(text), pretty);
  out.begin_object().field("a", 1).key("list").begin_array().begin_array();
  if (pieces == nullptr) {
    for (std::size_t i = 0; i < count; ++i) write_item(out, i);
  } else {
    write_items(out, count, write_item, *pieces);
  }
  out.end_array().end_array().field("z", "end").end_object();
  out.flush();
  return text;
}

TEST(ParallelItems, SameTextAsTheItemsWrittenInTurn) {
  for (const bool pretty : {false, true}) {
    for (const std::size_t count : {0UL, 1UL, 2UL, 7UL, 300UL}) {
      const std::string expected = document(count, pretty, nullptr);
      for (const std::size_t items : {1UL, 3UL, 7UL, 64UL, 1000UL}) {
        for (const unsigned threads : {2U, 3U, 5U}) {
          for (const std::size_t ahead : {1UL, 2UL, 16UL}) {
            const ItemPieces pieces{items, threads, ahead};
            ASSERT_EQ(document(count, pretty, &pieces), expected)
                << "pretty " << pretty << ", " << count << " items in pieces of " << items << ", " << threads
                << " threads, " << ahead << " ahead";
          }
        }
      }
    }
  }
  // The text is JSON, with the items where they were written.
  const ItemPieces defaults;
  const nlohmann::json parsed = nlohmann::json::parse(document(1000, true, &defaults));
  EXPECT_EQ(parsed["list"][0].size(), 1000U);
  EXPECT_EQ(parsed["list"][0][999]["id"], 999);
}

TEST(ParallelItems, TheSinkGetsPiecesOfAtMostTheBufferInOrder) {
  std::vector<std::size_t> sizes;
  std::string text;
  JsonWriter out([&](std::string_view piece) {
    sizes.push_back(piece.size());
    text.append(piece);
  });
  out.begin_array();
  write_items(out, 2000, write_item, {50, 2, 4});
  out.end_array();
  out.flush();
  EXPECT_GT(sizes.size(), 20U);
  for (const std::size_t size : sizes) EXPECT_LE(size, (1U << 16) + 64);
  EXPECT_EQ(out.bytes(), text.size());
  std::string serial;
  JsonWriter reference(string_sink(serial));
  reference.begin_array();
  for (std::size_t i = 0; i < 2000; ++i) write_item(reference, i);
  reference.end_array();
  reference.flush();
  EXPECT_EQ(text, serial);
}

TEST(ParallelItems, AFailureInAnItemOrTheSinkReachesTheCaller) {
  for (const std::size_t bad : {0UL, 5UL, 999UL}) {
    std::string text;
    JsonWriter out(string_sink(text));
    out.begin_array();
    const auto failing = [bad](JsonWriter& w, std::size_t i) {
      if (i == bad) throw std::runtime_error("item " + std::to_string(i));
      write_item(w, i);
    };
    EXPECT_THROW(write_items(out, 1000, failing, {10, 3, 4}), std::runtime_error) << "item " << bad;
  }
  // A full disk: the sink throws after some pieces; the writing stops there.
  std::size_t calls = 0;
  JsonWriter out([&](std::string_view) {
    if (++calls == 3) throw std::ios_base::failure("disk full");
  });
  out.begin_array();
  EXPECT_THROW(write_items(out, 5000, write_item, {20, 2, 8}), std::ios_base::failure);
  EXPECT_EQ(calls, 3U);
}

}  // namespace
}  // namespace saasgaps::io
