#pragma once
/// Wall-clock timing shared by the benchmark programs (steady clock, seconds).

#include <chrono>
#include <utility>

namespace saasgaps::bench {

/// Seconds from `start` to now.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Wall seconds of one call of `f`.
template <class F>
double timed(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  std::forward<F>(f)();
  return seconds_since(start);
}

}  // namespace saasgaps::bench
