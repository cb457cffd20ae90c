// The ordering cache: a run that computes its ordering (miss), one that loads it (hit), and runs
// that find a damaged or foreign file (fallback) all end with the same numbers to the last digit;
// a damaged file is replaced by a good one, and a cache that cannot be written is not an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "analysis.hpp"
#include "dof_map.hpp"
#include "ordering_cache.hpp"
#include "sparse_cholesky.hpp"
#include "stiffness_system.hpp"
#include "support/examples.hpp"
#include "support/identical_solutions.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;

constexpr const char* example = "ring-shrink-fit-plane-strain.json";

class OrderingCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() /
                 ("saasgaps-ordering-cache-" + std::to_string(::getpid()) + "-" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  /// Whether a fresh analysis of the example's matrix loads its ordering from the cache.
  bool analysis_hits(const OrderingCache& cache) const {
    const DofMap dofs(model_);
    const StiffnessSystem system(model_, dofs);
    return SparseCholesky(system.pattern(), dofs.node_of_equation(), &cache).ordering_from_cache();
  }

  /// The one file the cache holds.
  fs::path only_file() const {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(directory_)) files.push_back(entry.path());
    EXPECT_EQ(files.size(), 1U);
    return files.empty() ? fs::path() : files.front();
  }

  fs::path directory_;
  Model model_ = testing::example_model(example);
};

TEST_F(OrderingCacheTest, MissHitAndCorruptFilesGiveTheSameNumbers) {
  const Solution reference = solve(model_);
  const OrderingCache cache(directory_);

  ASSERT_FALSE(fs::exists(directory_));
  testing::expect_identical(solve(model_, nullptr, nullptr, {}, &cache), reference);  // miss: computed, stored
  const fs::path file = only_file();
  const auto size = fs::file_size(file);
  EXPECT_TRUE(analysis_hits(cache));
  testing::expect_identical(solve(model_, nullptr, nullptr, {}, &cache), reference);  // hit

  // Each damage is caught, the ordering computed again, and the file rewritten whole.
  const auto flip_byte_at = [&](long position) {
    {
      std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
      f.seekg(position);
      const char c = static_cast<char>(f.get());
      f.seekp(position);
      f.put(static_cast<char>(c ^ 0x5a));
    }
    EXPECT_FALSE(analysis_hits(cache)) << "damage at byte " << position;
    EXPECT_EQ(fs::file_size(file), size);
    EXPECT_TRUE(analysis_hits(cache));
  };
  flip_byte_at(0);                              // magic
  flip_byte_at(24);                             // key
  flip_byte_at(48 + 8 * 5);                     // an entry of the order: the checksum fails
  flip_byte_at(static_cast<long>(size) - 3);    // the checksum itself
  fs::resize_file(file, size / 2);  // truncated
  testing::expect_identical(solve(model_, nullptr, nullptr, {}, &cache), reference);
  EXPECT_EQ(fs::file_size(file), size);
  std::ofstream(file, std::ios::app) << "trailing";  // longer than it should be
  testing::expect_identical(solve(model_, nullptr, nullptr, {}, &cache), reference);
  EXPECT_TRUE(analysis_hits(cache));
}

TEST_F(OrderingCacheTest, ACacheThatCannotBeWrittenIsNotAnError) {
  fs::create_directories(directory_);
  std::ofstream(directory_ / "a-file") << "not a directory";
  const OrderingCache cache(directory_ / "a-file" / "cache");
  testing::expect_identical(solve(model_, nullptr, nullptr, {}, &cache), solve(model_));
  EXPECT_FALSE(analysis_hits(cache));
}

TEST(OrderingCacheKey, DependsOnThePatternTheGroupsAndTheMethod) {
  CscPattern p;
  p.n = 3;
  p.colptr = {0, 1, 3, 5};
  p.rowind = {0, 0, 1, 1, 2};
  const std::vector<Index> groups = {0, 0, 1};
  const PatternKey key = pattern_key(p, groups, "m");
  EXPECT_EQ(pattern_key(p, groups, "m"), key);
  EXPECT_NE(pattern_key(p, groups, "m2"), key);
  EXPECT_NE(pattern_key(p, std::vector<Index>{0, 1, 1}, "m"), key);
  CscPattern q = p;
  q.rowind = {0, 0, 1, 0, 2};
  EXPECT_NE(pattern_key(q, groups, "m"), key);
  EXPECT_TRUE(is_permutation_of(std::vector<Index>{2, 0, 1}, 3));
  EXPECT_FALSE(is_permutation_of(std::vector<Index>{2, 0, 0}, 3));
  EXPECT_FALSE(is_permutation_of(std::vector<Index>{2, 0, 3}, 3));
  EXPECT_FALSE(is_permutation_of(std::vector<Index>{1, 0}, 3));
}

}  // namespace
}  // namespace saasgaps
