#include "solver/base/thread_environment.hpp"

#include <dlfcn.h>

#include <mutex>

namespace saasgaps {

namespace {

/// A C function of a library that may or may not be loaded (OpenBLAS, libgomp): looked up in the
/// process rather than linked, so a reference BLAS or a CHOLMOD built without OpenMP still works.
template <class Function>
Function* optional_function(const char* name) {
  return reinterpret_cast<Function*>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

void configure_solver_threads() {
  static std::once_flag process_once;
  std::call_once(process_once, [] { set_blas_threads(1); });
  thread_local bool thread_done = false;
  if (thread_done) return;
  thread_done = true;
  // With max-active-levels 0 no parallel region is active: each runs on the thread that reaches
  // it and no OpenMP worker is created for it.
  static auto* const set_levels = optional_function<void(int)>("omp_set_max_active_levels");
  if (set_levels != nullptr) set_levels(0);
}

void set_blas_threads(int threads) {
  static auto* const set = optional_function<void(int)>("openblas_set_num_threads");
  if (set != nullptr) set(threads);
}

BlasThreads::BlasThreads(int threads) : changed_(threads > 1) {
  if (changed_) set_blas_threads(threads);
}

BlasThreads::~BlasThreads() {
  if (changed_) set_blas_threads(1);
}

}  // namespace saasgaps
