#pragma once
/// Peak resident memory of the benchmark process, shared by the benchmark programs.

#include <sys/resource.h>

namespace saasgaps::bench {

/// Peak resident memory of the process so far (MiB; getrusage's ru_maxrss, which Linux gives in kB).
inline double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace saasgaps::bench
