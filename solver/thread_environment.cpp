#include "thread_environment.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <thread>

namespace saasgaps {

void ensure_thread_environment(char** argv) {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr) return;
  const unsigned cores = std::max(1U, std::thread::hardware_concurrency());
  setenv("OMP_THREAD_LIMIT", std::to_string(cores).c_str(), 1);
  setenv("OPENBLAS_NUM_THREADS", "1", 0);  // 0: keep the user's choice
  // If the re-exec fails we simply carry on with the library defaults: slower, still correct.
  execv("/proc/self/exe", argv);
}

}  // namespace saasgaps
