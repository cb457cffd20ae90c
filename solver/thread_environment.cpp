#include "thread_environment.hpp"

#include <unistd.h>

#include <cstdlib>

namespace saasgaps {

void ensure_thread_environment(char** argv) {
  if (std::getenv("OMP_THREAD_LIMIT") != nullptr) return;
  // CHOLMOD's OpenMP loops gain nothing here and fight OpenBLAS's threads for the cores; the
  // parallelism goes to the BLAS instead (SparseCholesky sets its thread count per factorization).
  setenv("OMP_THREAD_LIMIT", "1", 1);
  // If the re-exec fails we simply carry on with the library defaults: slower, still correct.
  execv("/proc/self/exe", argv);
}

}  // namespace saasgaps
