// The stored-result reader (io/result_arrays): its arrays hold the tree's numbers bit for bit, its
// tree part is the tree without the nodes and elements, bad meshes are named by pointer, and the
// nesting limit holds wherever the text nests (skipped members included). A fuzz test with a fixed
// seed: mutated result text never crashes it, and it refuses exactly what nlohmann's parser refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include <nlohmann/json.hpp>

#include "io/json/json_limits.hpp"
#include "io/json/json_subset.hpp"
#include "io/results/result_arrays.hpp"
#include "support/json_mutation.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

/// Doubles of every magnitude: random bit patterns (finite), round numbers, -0.0, subnormals.
double random_value(std::mt19937_64& rng) {
  switch (rng() % 5) {
    case 0: return static_cast<double>(static_cast<int>(rng() % 2001) - 1000);
    case 1: return std::uniform_real_distribution<double>(-1e4, 1e4)(rng);
    case 2:
      for (;;) {
        const std::uint64_t b = rng();
        double v = 0.0;
        std::memcpy(&v, &b, sizeof v);
        if (std::isfinite(v)) return v;
      }
    case 3: return -0.0;
    default: return std::numeric_limits<double>::denorm_min() * static_cast<double>(rng() % 1000);
  }
}

/// A result document of the writer's shape: a grid of quads, a few gaps, a history.
json random_result(std::mt19937_64& rng, int side) {
  json nodes = json::array(), elements = json::array(), gaps = json::array(), history = json::array();
  const auto node_id = [side](int i, int j) { return 1 + i + j * (side + 1); };
  for (int j = 0; j <= side; ++j) {
    for (int i = 0; i <= side; ++i) {
      json n = {{"id", node_id(i, j)}, {"r", random_value(rng)}, {"z", random_value(rng)},
                {"u_r", random_value(rng)}, {"u_z", random_value(rng)}};
      if (rng() % 2) n["T"] = random_value(rng);
      nodes.push_back(n);
    }
  }
  int id = 1;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      json e = {{"id", id++}, {"material", 1 + static_cast<int>(rng() % 3)},
                {"nodes", {node_id(i, j), node_id(i + 1, j), node_id(i + 1, j + 1), node_id(i, j + 1)}}};
      for (const char* key : {"sigma_r", "sigma_z", "tau_rz", "sigma_theta", "effective", "eps_r"}) e[key] = random_value(rng);
      e["yield"] = false;
      e["principal"] = {{"angle", random_value(rng)}};  // nested members are skipped
      elements.push_back(e);
    }
  }
  for (int g = 0; g < 3; ++g) {
    gaps.push_back({{"id", 100 + g}, {"nodes", {1, 2, 3, 4}}, {"closure", random_value(rng)}, {"state", "closed"}});
  }
  for (int k = 1; k <= 3; ++k) {
    history.push_back({{"iteration", k}, {"max_closure", random_value(rng)}, {"gap_closures", {1.5, -2, 3e300}}});
  }
  return {{"analysis", "plane_strain"}, {"elements", elements}, {"gaps", gaps}, {"history", history},
          {"iterations", 3}, {"nodes", nodes}, {"status", "converged"}, {"title", "t\u00e9st \"q\""},
          {"units", {{"stress", "psi"}}}, {"big", 18446744073709551615ULL}, {"negative", -9223372036854775807LL - 1}};
}

json without_mesh(json document) {
  document.erase("nodes");
  document.erase("elements");
  return document;
}

const ResultSelection contour{.mesh = true, .element_keys = {"effective", "sigma_r"}};

TEST(ResultArrays, ColumnsHoldTheTreesNumbersBitForBit) {
  std::mt19937_64 rng(23);
  const json tree = random_result(rng, 12);
  for (const std::string& text : {tree.dump(), tree.dump(2)}) {
    const ResultArrays arrays = read_result_arrays(text, contour);
    ASSERT_FALSE(arrays.mesh_error) << *arrays.mesh_error;
    EXPECT_EQ(arrays.document, without_mesh(tree));
    ASSERT_TRUE(arrays.nodes && arrays.elements);
    const ResultNodes& nodes = *arrays.nodes;
    ASSERT_EQ(nodes.id.size(), tree["nodes"].size());
    for (std::size_t n = 0; n < nodes.id.size(); ++n) {
      const json& node = tree["nodes"][n];
      EXPECT_EQ(nodes.id[n], node["id"].get<int>());
      EXPECT_EQ(bits(nodes.r[n]), bits(node["r"].get<double>()));
      EXPECT_EQ(bits(nodes.z[n]), bits(node["z"].get<double>()));
      EXPECT_EQ(bits(nodes.u_r[n]), bits(node["u_r"].get<double>()));
      EXPECT_EQ(bits(nodes.u_z[n]), bits(node["u_z"].get<double>()));
      EXPECT_EQ(bits(nodes.T[n]), bits(node.value("T", 0.0)));
    }
    const ResultElements& elements = *arrays.elements;
    ASSERT_EQ(elements.size(), tree["elements"].size());
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const json& element = tree["elements"][e];
      EXPECT_EQ(elements.id[e], element["id"].get<int>());
      EXPECT_EQ(elements.material[e], element["material"].get<int>());
      const std::vector<int> ids(elements.node_ids.begin() + static_cast<std::ptrdiff_t>(elements.first_node[e]),
                                 elements.node_ids.begin() + static_cast<std::ptrdiff_t>(elements.first_node[e + 1]));
      EXPECT_EQ(ids, element["nodes"].get<std::vector<int>>());
      EXPECT_EQ(bits(elements.values[0][e]), bits(element["effective"].get<double>()));
      EXPECT_EQ(bits(elements.values[1][e]), bits(element["sigma_r"].get<double>()));
    }
    EXPECT_FALSE(elements.first_missing[0] || elements.first_missing[1]);
  }
}

TEST(ResultArrays, PiecesReadAsTheWholeTextAndNoPieceIsAskedBeyond64KiB) {
  // What the service does with a stored result: the text comes from a blob handle in pieces and is
  // never held whole. The source here counts what it is asked for: the reader asks for at most
  // 64 KiB at a time, and every byte exactly once, in order; the pieces it gets may be of any size.
  std::mt19937_64 rng(7);
  const std::string text = random_result(rng, 60).dump();  // 1.1 MB: many pieces
  ASSERT_GT(text.size(), 16U * 64 * 1024);
  for (const std::size_t most : {std::size_t{1}, std::size_t{7}, std::size_t{4096}, std::size_t{1} << 20}) {
    std::size_t offset = 0, largest_request = 0, requests = 0;
    const TextPieces pieces = [&](char* out, std::size_t capacity) {
      largest_request = std::max(largest_request, capacity);
      ++requests;
      const std::size_t count = std::min({capacity, most, text.size() - offset});
      text.copy(out, count, offset);
      offset += count;
      return count;
    };
    const ResultArrays streamed = read_result_arrays_pieces(pieces, contour);
    const ResultArrays whole = read_result_arrays(text, contour);
    EXPECT_EQ(offset, text.size());
    EXPECT_LE(largest_request, 64U * 1024);
    EXPECT_GE(requests, text.size() / (64 * 1024));
    EXPECT_EQ(streamed.document, whole.document);
    ASSERT_TRUE(streamed.nodes && streamed.elements);
    EXPECT_EQ(streamed.nodes->id, whole.nodes->id);
    EXPECT_EQ(streamed.nodes->r, whole.nodes->r);
    EXPECT_EQ(streamed.nodes->u_z, whole.nodes->u_z);
    EXPECT_EQ(streamed.elements->node_ids, whole.elements->node_ids);
    EXPECT_EQ(streamed.elements->values, whole.elements->values);
  }
  // Text that is not JSON is refused at the same byte either way, across a piece boundary.
  const std::string broken = text.substr(0, 100000) + "}" + text.substr(100000);
  std::size_t offset = 0;
  const TextPieces pieces = [&](char* out, std::size_t capacity) {
    const std::size_t count = std::min(capacity, broken.size() - offset);
    broken.copy(out, count, offset);
    offset += count;
    return count;
  };
  std::string streamed_error, whole_error;
  try {
    (void)read_result_arrays_pieces(pieces, contour);
  } catch (const ResultTextError& e) {
    streamed_error = e.what();
  }
  try {
    (void)read_result_arrays(broken, contour);
  } catch (const ResultTextError& e) {
    whole_error = e.what();
  }
  EXPECT_FALSE(whole_error.empty());
  EXPECT_EQ(streamed_error, whole_error);
}

TEST(ResultArrays, WithoutTheMeshNodesAndElementsAreSkipped) {
  std::mt19937_64 rng(7);
  const json tree = random_result(rng, 4);
  const ResultArrays arrays = read_result_arrays(tree.dump(), {.mesh = false, .element_keys = {}});
  EXPECT_FALSE(arrays.nodes || arrays.elements || arrays.mesh_error);
  EXPECT_EQ(arrays.document, without_mesh(tree));
}

TEST(ResultArrays, ABadMeshIsNamedByPointerAndTheRestStillRead) {
  std::mt19937_64 rng(5);
  const json tree = random_result(rng, 3);
  const auto error_of = [](const json& document) {
    const ResultArrays arrays = read_result_arrays(document.dump(), contour);
    EXPECT_EQ(arrays.document.value("status", ""), "converged");
    return arrays.mesh_error.value_or("(none)");
  };
  json bad = tree;
  bad["nodes"][2].erase("u_r");
  EXPECT_EQ(error_of(bad), "malformed result document: /nodes/2 has no 'u_r'");
  bad = tree;
  bad["nodes"][0].erase("r");
  EXPECT_NE(error_of(bad).find("has no node coordinates"), std::string::npos);
  bad = tree;
  bad["nodes"][1]["z"] = "1.5";
  EXPECT_EQ(error_of(bad), "malformed result document: /nodes/1/z is a string, not a number");
  bad = tree;
  bad["nodes"][1]["id"] = 2.5;
  EXPECT_EQ(error_of(bad), "malformed result document: /nodes/1/id is not an integer within the range of an int: 2.5");
  bad = tree;
  bad["elements"][4]["nodes"] = {1, {2}};
  EXPECT_EQ(error_of(bad), "malformed result document: /elements/4/nodes/1 is not a node id");
  bad = tree;
  bad["elements"][3].erase("nodes");
  EXPECT_EQ(error_of(bad), "malformed result document: /elements/3 has no 'nodes'");
  bad = tree;
  bad["elements"][1]["effective"] = nullptr;  // nan is written as null: not a value to draw
  EXPECT_EQ(error_of(bad), "malformed result document: /elements/1/effective is null, not a number");
  bad = tree;
  bad["nodes"][0] = 7;
  EXPECT_EQ(error_of(bad), "malformed result document: /nodes/0 is a number, not an object");
  EXPECT_EQ(read_result_arrays("[1, 2]", contour).mesh_error.value_or(""), "the result document is not a JSON object");

  // A selected element member some element lacks: its column says where.
  bad = tree;
  bad["elements"][5].erase("sigma_r");
  const ResultArrays arrays = read_result_arrays(bad.dump(), contour);
  EXPECT_FALSE(arrays.mesh_error);
  EXPECT_FALSE(arrays.elements->first_missing[0]);
  EXPECT_EQ(arrays.elements->first_missing[1], std::optional<std::size_t>(5));
}

TEST(ResultArrays, TextThatIsNotJsonIsRefused) {
  std::mt19937_64 rng(3);
  const std::string text = random_result(rng, 2).dump();
  for (const std::string& bad : {text.substr(0, text.size() / 2), text + "x", std::string(), std::string("{\"a\": 1e400}"),
                                 std::string("{\"nodes\": [{\"r\": 1e400}]}"), std::string("{\"title\": \"\xC3\x28\"}"),
                                 // Beyond a double by its digits, not its exponent: in kept and in skipped members.
                                 std::string("{\"nodes\": [{\"r\": 1.8e308}]}"),
                                 std::string("{\"elements\": [{\"id\": 1, \"sigma_1\": -1.8e308}]}"),
                                 "{\"elements\": [{\"id\": 1, \"nodes\": [1], \"x\": 1" + std::string(400, '0') + "}]}",
                                 std::string("{\"a\": NaN}"), std::string("{\"a\": 01}")}) {
    EXPECT_THROW((void)read_result_arrays(bad, contour), ResultTextError) << bad.substr(0, 60);
  }
  // What nlohmann reads as a double, so does this reader: an integer beyond 64 bits.
  EXPECT_EQ(read_result_arrays("{\"a\": 123456789012345678901234567890}", contour).document["a"],
            json::parse("123456789012345678901234567890"));
}

std::string nested_arrays(int depth) { return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']'); }

std::string too_deep_pointer(const std::string& text, const ResultSelection& selection) {
  try {
    (void)read_result_arrays(text, selection);
  } catch (const NestingTooDeep& e) {
    return e.issues().front().pointer;
  }
  return "(no NestingTooDeep)";
}

TEST(ResultArrays, TheNestingLimitHoldsInEveryPartKeptOrSkipped) {
  const std::string deep = nested_arrays(100000);  // 200 KB: a stack overflow for a recursive reader
  for (const std::string& where :
       {std::string("{\"history\": X}"), std::string("{\"nodes\": [{\"id\": 1, \"extra\": X}]}"),
        std::string("{\"elements\": [{\"id\": 1, \"nodes\": [1], \"sigma_theta\": X}]}"),
        std::string("{\"elements\": [{\"id\": 1, \"nodes\": X}]}"), std::string("{\"nodes\": X}")}) {
    const std::string text = where.substr(0, where.find('X')) + deep + where.substr(where.find('X') + 1);
    for (const ResultSelection& selection : {contour, ResultSelection{.mesh = false, .element_keys = {}}}) {
      const std::string pointer = too_deep_pointer(text, selection);
      // The same place as the tree parser's limit.
      std::string expected;
      try {
        (void)parse_json_subset(text, nullptr);
      } catch (const NestingTooDeep& e) {
        expected = e.issues().front().pointer;
      }
      EXPECT_EQ(pointer, expected) << where;
    }
  }
  // Unclosed: the limit answers before the syntax error, at the tree parser's place.
  std::string sixty_four;
  for (int k = 0; k < 64; ++k) sixty_four += "/0";
  EXPECT_EQ(too_deep_pointer(std::string(100000, '['), contour), shown_pointer(sixty_four));
  EXPECT_FALSE(read_result_arrays("{\"history\": " + nested_arrays(63) + "}", contour).mesh_error);
}

/// How a parse ended: read, not JSON (or a number beyond a double), nesting too deep.
enum class Outcome { read, refused, too_deep };

Outcome tree_outcome(const std::string& text) {
  try {
    (void)parse_json_subset(text, nullptr);
    return Outcome::read;
  } catch (const NestingTooDeep&) {
    return Outcome::too_deep;
  } catch (const json::exception&) {
    return Outcome::refused;
  }
}

/// One byte-level mutation of result text: a byte changed, a span cut or doubled, brackets inserted,
/// the text cut short.
std::string mutate_text(std::string text, std::mt19937& random) {
  const auto at = [&](std::size_t size) { return std::uniform_int_distribution<std::size_t>(0, size)(random); };
  switch (std::uniform_int_distribution<int>(0, 5)(random)) {
    case 0: {
      static constexpr char bytes[] = "{}[],:\"0-.eE\\ \x80\xff";
      text[at(text.size() - 1)] = bytes[at(sizeof bytes - 2)];
      break;
    }
    case 1: {
      const std::size_t from = at(text.size() - 1);
      text.erase(from, at(40));
      break;
    }
    case 2: {
      const std::size_t from = at(text.size() - 1);
      text.insert(from, text.substr(from, at(60)));
      break;
    }
    case 3: text.insert(at(text.size()), std::string(at(120), at(1) ? '[' : '{')); break;
    case 4: text.resize(at(text.size())); break;
    default: text.insert(at(text.size()), "1e999"); break;
  }
  return text;
}

TEST(ResultArrays, FuzzedTextNeverCrashesAndIsRefusedExactlyWhenTheTreeParserRefusesIt) {
  std::mt19937_64 rng(1976);
  const json seed = random_result(rng, 3);
  std::mt19937 random(2323);
  int read = 0, refused = 0;
  for (int k = 0; k < 1500; ++k) {
    // Half the cases mutate the tree (wrong types at any place), half the text (syntax).
    const std::string text = k % 2 ? testing::mutate(seed, random).dump() : mutate_text(seed.dump(), random);
    for (const ResultSelection& selection : {contour, ResultSelection{.mesh = false, .element_keys = {}}}) {
      Outcome outcome = Outcome::read;
      ResultArrays arrays;
      try {
        arrays = read_result_arrays(text, selection);
      } catch (const ResultTextError&) {
        outcome = Outcome::refused;
      } catch (const NestingTooDeep&) {
        outcome = Outcome::too_deep;
      }
      ASSERT_EQ(outcome, tree_outcome(text)) << "case " << k << ": " << text.substr(0, 300);
      if (outcome != Outcome::read) {
        ++refused;
        continue;
      }
      ++read;
      const json tree = parse_json_subset(text, nullptr);
      if (tree.is_object()) {
        json expected = tree;
        if (expected.contains("nodes") && (expected["nodes"].is_array() || !selection.mesh)) expected.erase("nodes");
        if (expected.contains("elements") && (expected["elements"].is_array() || !selection.mesh)) expected.erase("elements");
        EXPECT_EQ(arrays.document, expected) << "case " << k;
      }
      if (!arrays.mesh_error && arrays.nodes) {
        EXPECT_EQ(arrays.nodes->id.size(), tree["nodes"].size()) << "case " << k;
      }
    }
  }
  EXPECT_GT(read, 500) << "the mutations should leave many documents readable";
  EXPECT_GT(refused, 300) << "and make many unreadable";
}

}  // namespace
}  // namespace saasgaps::io
