// The ordering and symbolic-analysis caches: a run that computes its analysis (miss), one that loads
// the whole symbolic factor (hit), one that loads only the ordering, and runs that find damaged,
// foreign or wrongly structured files (fallback) all end with the same numbers to the last digit;
// a damaged file is replaced by a good one, and a cache that cannot be written is not an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>

#include "solver/analysis/analysis.hpp"
#include "solver/assembly/dof_map.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/lac/ordering_cache.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/lac/symbolic_cache.hpp"
#include "support/examples.hpp"
#include "support/identical_solutions.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;

constexpr const char* example = "ring-shrink-fit-plane-strain.json";

/// What a fresh analysis took from the cache.
enum class Loaded { nothing, ordering, analysis };

class OrderingCacheTest : public ::testing::Test {
 protected:
  void SetUp() override { fs::remove_all(directory_); }
  void TearDown() override { fs::remove_all(directory_); }

  Loaded analysis_loads(const OrderingCache& cache) const {
    const SparseCholesky cholesky(system_.pattern(), dofs_.node_of_equation(), &cache);
    if (cholesky.analysis_from_cache()) return Loaded::analysis;
    return cholesky.ordering_from_cache() ? Loaded::ordering : Loaded::nothing;
  }

  /// The one file of the cache with this extension.
  fs::path only_file(const std::string& extension) const {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(directory_)) {
      if (entry.path().extension() == extension) files.push_back(entry.path());
    }
    EXPECT_EQ(files.size(), 1U) << extension;
    return files.empty() ? fs::path() : files.front();
  }

  static void flip_byte(const fs::path& file, long position) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(position);
    const char c = static_cast<char>(f.get());
    f.seekp(position);
    f.put(static_cast<char>(c ^ 0x5a));
  }

  Solution solve_with(const OrderingCache& cache) const { return solve(model_, nullptr, nullptr, {}, &cache); }

  fs::path directory_ = fs::temp_directory_path() /
                        ("saasgaps-ordering-cache-" + std::to_string(::getpid()) + "-" +
                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Model model_ = testing::example_model(example);
  DofMap dofs_{model_};
  StiffnessSystem system_{model_, dofs_};
};

TEST_F(OrderingCacheTest, MissHitAndCorruptOrderingFilesGiveTheSameNumbers) {
  const Solution reference = solve(model_);
  const OrderingCache cache(directory_);

  ASSERT_FALSE(fs::exists(directory_));
  testing::expect_identical(solve_with(cache), reference);  // miss: computed, both files stored
  const fs::path file = only_file(".order");
  const fs::path symbolic = only_file(".symbolic");
  const auto size = fs::file_size(file);
  EXPECT_EQ(analysis_loads(cache), Loaded::analysis);
  testing::expect_identical(solve_with(cache), reference);  // hit: the whole analysis loaded
  fs::remove(symbolic);  // an ordering-only cache, as earlier versions wrote
  testing::expect_identical(solve_with(cache), reference);  // the ordering loaded, the analysis computed
  EXPECT_EQ(analysis_loads(cache), Loaded::analysis);       // ... and stored

  // Each damage is caught, the ordering computed again, and the file rewritten whole.
  const auto damaged_at = [&](long position) {
    fs::remove(symbolic);
    flip_byte(file, position);
    EXPECT_EQ(analysis_loads(cache), Loaded::nothing) << "damage at byte " << position;
    EXPECT_EQ(fs::file_size(file), size);
    EXPECT_EQ(analysis_loads(cache), Loaded::analysis);
  };
  damaged_at(0);                              // magic
  damaged_at(24);                             // key
  damaged_at(48 + 8 * 5);                     // an entry of the order: the checksum fails
  damaged_at(static_cast<long>(size) - 3);    // the checksum itself
  fs::remove(symbolic);
  fs::resize_file(file, size / 2);  // truncated
  testing::expect_identical(solve_with(cache), reference);
  EXPECT_EQ(fs::file_size(file), size);
  fs::remove(symbolic);
  std::ofstream(file, std::ios::app) << "trailing";  // longer than it should be
  testing::expect_identical(solve_with(cache), reference);
  EXPECT_EQ(fs::file_size(file), size);
}

TEST_F(OrderingCacheTest, DamagedSymbolicFilesAreMissesWithTheSameNumbers) {
  const Solution reference = solve(model_);
  const OrderingCache cache(directory_);
  testing::expect_identical(solve_with(cache), reference);
  const fs::path file = only_file(".symbolic");
  const auto size = static_cast<long>(fs::file_size(file));

  // Layout: magic 16 | 12 header words | Perm, ColCount, super, pi, px, s | checksum.
  for (long position : {0L, 16 + 8L, 16 + 8 * 4L, 16 + 8 * 12 + 8 * 3L, size - 8 - 8 * 2, size - 3}) {
    flip_byte(file, position);
    EXPECT_EQ(analysis_loads(cache), Loaded::ordering) << "damage at byte " << position;
    EXPECT_EQ(static_cast<long>(fs::file_size(file)), size);
    EXPECT_EQ(analysis_loads(cache), Loaded::analysis);
  }
  flip_byte(file, size / 2);
  testing::expect_identical(solve_with(cache), reference);
  fs::resize_file(file, size / 2);  // truncated
  testing::expect_identical(solve_with(cache), reference);
  EXPECT_EQ(static_cast<long>(fs::file_size(file)), size);
  std::ofstream(file, std::ios::app) << "trailing";  // longer than it should be
  testing::expect_identical(solve_with(cache), reference);
  EXPECT_EQ(static_cast<long>(fs::file_size(file)), size);
  EXPECT_EQ(analysis_loads(cache), Loaded::analysis);
}

/// The 128-bit key a cache file is named by.
PatternKey key_of(const fs::path& file) {
  const std::string hex = file.stem().string();
  return {std::stoull(hex.substr(0, 16), nullptr, 16), std::stoull(hex.substr(16), nullptr, 16)};
}

constexpr int given_ordering = 1;  // CHOLMOD_GIVEN, what the group ordering records

/// A copy of a real symbolic factor's arrays, to change and store under the real key.
struct StructureCopy {
  std::vector<Index> perm, colcount, super, pi, px, s;
  SupernodalStructure base;
  int ordering = given_ordering;

  static StructureCopy of(const SupernodalStructure& f) {
    return {{f.perm.begin(), f.perm.end()}, {f.colcount.begin(), f.colcount.end()}, {f.super.begin(), f.super.end()},
            {f.pi.begin(), f.pi.end()},     {f.px.begin(), f.px.end()},             {f.s.begin(), f.s.end()},
            f};
  }
  SupernodalStructure view() const {
    SupernodalStructure v = base;
    v.perm = perm, v.colcount = colcount, v.super = super, v.pi = pi, v.px = px, v.s = s;
    return v;
  }
};

/// A cache holding the example's analysis, and that analysis as loaded from it.
class SymbolicFileTest : public OrderingCacheTest {
 protected:
  void SetUp() override {
    OrderingCacheTest::SetUp();
    testing::expect_identical(solve_with(cache_), reference_);
    key_ = key_of(only_file(".symbolic"));
    loaded_ = std::make_unique<SparseCholesky>(system_.pattern(), dofs_.node_of_equation(), &cache_);
    ASSERT_TRUE(loaded_->analysis_from_cache());
  }

  StructureCopy real() const { return StructureCopy::of(supernodal_structure(*loaded_->factor())); }

  /// What a fresh analysis loads after `copy` is stored, checksummed, under the real key.
  Loaded stored(const StructureCopy& copy) const {
    const SymbolicStatistics statistics{loaded_->factor_flops(), loaded_->factor_nonzeros()};
    SymbolicCache(directory_).store(key_, copy.view(), copy.ordering, statistics);
    return analysis_loads(cache_);
  }

  const Solution reference_ = solve(model_);
  const OrderingCache cache_{directory_};
  PatternKey key_;
  std::unique_ptr<SparseCholesky> loaded_;
};

TEST_F(SymbolicFileTest, AWronglyStructuredFileWithAValidChecksumIsAMiss) {
  const auto changed = [&](const std::function<void(StructureCopy&)>& change) {
    StructureCopy c = real();
    change(c);
    return stored(c);
  };
  EXPECT_EQ(changed([](StructureCopy&) {}), Loaded::analysis);  // the copy itself is a valid file
  const Index n = system_.pattern().n;
  EXPECT_EQ(changed([](StructureCopy& c) { std::iota(c.perm.begin(), c.perm.end(), 0); }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.perm[1] = c.perm[0]; }), Loaded::ordering);
  EXPECT_EQ(changed([&](StructureCopy& c) { c.s.back() = n; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.super[1] += 1; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.pi[1] -= 1; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.px[1] += 1; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.colcount[0] = 0; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.base.maxcsize += 1; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.base.xsize += 1; }), Loaded::ordering);
  EXPECT_EQ(changed([](StructureCopy& c) { c.ordering = 0; }), Loaded::ordering);  // NATURAL: not permuted
  changed([](StructureCopy& c) { std::iota(c.perm.begin(), c.perm.end(), 0); });
  testing::expect_identical(solve_with(cache_), reference_);
  EXPECT_EQ(analysis_loads(cache_), Loaded::analysis);
}

TEST_F(SymbolicFileTest, RandomlyChangedStructuresAreMissesOrStillSolveTheModel) {
  // One entry of one array changed per round (fixed seed), the file checksummed again: the
  // structure check alone stands between it and CHOLMOD. A change it accepts (a column count
  // still within its supernode, say) must still give the model's answer.
  const Index n = system_.pattern().n;
  double largest = 0.0;
  for (const NodeResult& node : reference_.nodes) largest = std::max({largest, std::abs(node.u_r), std::abs(node.u_z)});
  std::mt19937_64 random(20261123);
  int accepted = 0;
  for (int round = 0; round < 120; ++round) {
    StructureCopy c = real();
    std::vector<Index>* arrays[] = {&c.perm, &c.colcount, &c.super, &c.pi, &c.px, &c.s};
    std::vector<Index>& a = *arrays[random() % 6];
    Index& entry = a[random() % a.size()];
    entry = random() % 2 != 0 ? entry + (random() % 2 != 0 ? 1 : -1) : static_cast<Index>(random() % (n + 2)) - 1;
    if (stored(c) != Loaded::analysis) continue;
    ++accepted;
    const Solution s = solve_with(cache_);
    ASSERT_EQ(s.status, reference_.status) << "round " << round;
    ASSERT_EQ(s.nodes.size(), reference_.nodes.size());
    for (std::size_t k = 0; k < s.nodes.size(); ++k) {
      EXPECT_NEAR(s.nodes[k].u_r, reference_.nodes[k].u_r, 1e-9 * largest) << "round " << round;
      EXPECT_NEAR(s.nodes[k].u_z, reference_.nodes[k].u_z, 1e-9 * largest) << "round " << round;
    }
  }
  std::printf("%d of 120 changed structures accepted\n", accepted);
}

/// A 3 x 3 upper-triangular pattern with one entry in column 0 and two in columns 1 and 2.
CscPattern pattern_3x3(std::vector<Index> rowind) {
  CscPattern p;
  p.n = 3;
  p.colptr = {0, 1, 3, 5};
  p.rowind = std::move(rowind);
  return p;
}

TEST(SupernodalStructure, EveryEntryAndAllFillMustBeInside) {
  // A = [x x x; x x .; x . x] (upper triangle stored): eliminating 0 fills (2,1).
  const CscPattern a = pattern_3x3({0, 0, 1, 0, 2});
  const std::vector<Index> identity = {0, 1, 2}, super = {0, 1, 2, 3};
  // One supernode per column: rows {0,1,2}, {1,2}, {2}.
  const std::vector<Index> colcount = {3, 2, 1}, pi = {0, 3, 5, 6}, s = {0, 1, 2, 1, 2, 2};
  EXPECT_TRUE(is_supernodal_structure_of({identity, colcount, super, pi, pi, s, 6, 2, 2}, a));
  EXPECT_FALSE(is_supernodal_structure_of({identity, colcount, super, pi, pi, s, 6, 1, 2}, a));  // maxcsize
  EXPECT_FALSE(is_supernodal_structure_of({identity, colcount, super, pi, pi, s, 6, 2, 1}, a));  // maxesize
  // Without the fill: column 1 holds row 1 only, not a superset of column 0's rows below it.
  const std::vector<Index> colcount1 = {3, 1, 1}, pi1 = {0, 3, 4, 5}, s1 = {0, 1, 2, 1, 2};
  EXPECT_FALSE(is_supernodal_structure_of({identity, colcount1, super, pi1, pi1, s1, 5, 2, 2}, a));
  // Closed under elimination but without A's entry (2,0).
  const std::vector<Index> colcount2 = {2, 2, 1}, pi2 = {0, 2, 4, 5}, s2 = {0, 1, 1, 2, 2};
  EXPECT_FALSE(is_supernodal_structure_of({identity, colcount2, super, pi2, pi2, s2, 5, 1, 1}, a));
  // Ordered 2, 1, 0 the matrix is an arrow pointing the other way: no fill, A's entries inside.
  const std::vector<Index> reversed = {2, 1, 0}, colcount3 = {2, 2, 1}, pi3 = {0, 2, 4, 5}, s3 = {0, 2, 1, 2, 2};
  EXPECT_TRUE(is_supernodal_structure_of({reversed, colcount3, super, pi3, pi3, s3, 5, 1, 1}, a));
  EXPECT_FALSE(is_supernodal_structure_of({identity, colcount3, super, pi3, pi3, s3, 5, 1, 1}, a));
  // Ordered so, A's entry (0,2) lands in column 0 at row 2: a structure with row 1 there misses it.
  EXPECT_FALSE(is_supernodal_structure_of({reversed, colcount2, super, pi2, pi2, s2, 5, 1, 1}, a));
}

TEST_F(OrderingCacheTest, ACacheThatCannotBeWrittenIsNotAnError) {
  fs::create_directories(directory_);
  std::ofstream(directory_ / "a-file") << "not a directory";
  const OrderingCache cache(directory_ / "a-file" / "cache");
  testing::expect_identical(solve_with(cache), solve(model_));
  EXPECT_EQ(analysis_loads(cache), Loaded::nothing);
}

TEST(OrderingCacheKey, DependsOnThePatternTheGroupsAndTheMethod) {
  const CscPattern p = pattern_3x3({0, 0, 1, 1, 2});
  const std::vector<Index> groups = {0, 0, 1};
  const PatternKey key = pattern_key(p, groups, "m");
  EXPECT_EQ(pattern_key(p, groups, "m"), key);
  EXPECT_NE(pattern_key(p, groups, "m2"), key);
  EXPECT_NE(pattern_key(p, std::vector<Index>{0, 1, 1}, "m"), key);
  CscPattern q = p;
  q.rowind = {0, 0, 1, 0, 2};
  EXPECT_NE(pattern_key(q, groups, "m"), key);
  EXPECT_EQ(derived_key(key, "settings"), derived_key(key, "settings"));
  EXPECT_NE(derived_key(key, "settings"), derived_key(key, "settings 2"));
  EXPECT_NE(derived_key(key, "settings"), key);
  EXPECT_TRUE(is_permutation_of(std::vector<Index>{2, 0, 1}, 3));
  EXPECT_FALSE(is_permutation_of(std::vector<Index>{2, 0, 0}, 3));
  EXPECT_FALSE(is_permutation_of(std::vector<Index>{2, 0, 3}, 3));
  EXPECT_FALSE(is_permutation_of(std::vector<Index>{1, 0}, 3));
}

}  // namespace
}  // namespace saasgaps
