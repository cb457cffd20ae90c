#pragma once
/// Thread counts of the libraries under CHOLMOD, set at run time: no environment variables, no
/// re-executed process.
///
/// Debian's CHOLMOD (SuiteSparse 5.12) runs a few OpenMP loops with 4 threads whatever the machine
/// has. Measured on 2 cores they do not speed its supernodal factorization up, while OpenMP and
/// OpenBLAS threads together thrash (10^6 unknowns: 7.3 s with 2 + 2 threads, 2.1 s with OpenMP 1
/// and OpenBLAS 2), and idle libgomp workers spin. libgomp reads OMP_THREAD_LIMIT only when it
/// loads, so instead OpenMP's max-active-levels is set to 0, which makes every parallel region run
/// on the thread that reaches it. libgomp 12 keeps that setting per thread (an ICV of the thread's
/// data environment), so it is set on every thread that calls CHOLMOD.
///
/// OpenBLAS's pthread workers spin (sched_yield) between calls and for about 2^28 cycles after the
/// last one; so the BLAS gets its threads only for the duration of a factorization (BlasThreads)
/// and runs on one thread otherwise: the solves, stress recovery and I/O never have spinning
/// workers beside them.

namespace saasgaps {

/// Makes CHOLMOD's OpenMP loops serial on the calling thread (once per thread), and puts the BLAS on
/// one thread (once per process); does nothing to a library that is not loaded. Call before any
/// CHOLMOD call on a thread.
void configure_solver_threads();

/// Sets OpenBLAS's thread count when OpenBLAS provides the BLAS (Debian's libblas.so.3
/// alternative, found with dlsym); does nothing with another BLAS.
void set_blas_threads(int threads);

/// The BLAS on `threads` threads while this object lives, on one thread before and after.
class BlasThreads {
 public:
  explicit BlasThreads(int threads);
  ~BlasThreads();
  BlasThreads(const BlasThreads&) = delete;
  BlasThreads& operator=(const BlasThreads&) = delete;

 private:
  bool changed_;
};

}  // namespace saasgaps
