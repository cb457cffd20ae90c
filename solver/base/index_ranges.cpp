#include "solver/base/index_ranges.hpp"

#include <algorithm>
#include <atomic>
#include <future>
#include <thread>
#include <vector>

namespace saasgaps {

namespace {
std::atomic<unsigned> thread_budget{std::clamp(std::thread::hardware_concurrency(), 1U, 4U)};
}  // namespace

unsigned parallel_threads() { return thread_budget.load(); }

void set_parallel_threads(unsigned threads) { thread_budget = std::max(threads, 1U); }

unsigned range_count(std::size_t n, std::size_t smallest) {
  return static_cast<unsigned>(
      std::clamp<std::size_t>(n / std::max<std::size_t>(smallest, 1), 1, parallel_threads()));
}

void for_each_range(std::size_t n, const std::function<void(std::size_t, std::size_t, unsigned)>& work, std::size_t smallest) {
  const unsigned count = range_count(n, smallest);
  const auto bound = [&](unsigned r) { return n * r / count; };
  std::vector<std::future<void>> others;
  for (unsigned r = 1; r < count; ++r) others.push_back(std::async(std::launch::async, work, bound(r), bound(r + 1), r));
  std::exception_ptr failure;
  try {
    work(0, bound(1), 0);
  } catch (...) {
    failure = std::current_exception();
  }
  // Every range finishes before anything it writes goes out of scope.
  for (std::future<void>& f : others) {
    try {
      f.get();
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace saasgaps
