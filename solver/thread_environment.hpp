#pragma once
/// Thread limits for CHOLMOD and OpenBLAS that must be set before the process starts.
///
/// Debian's CHOLMOD (SuiteSparse 5.12) asks OpenMP for 4 threads whatever the machine has, and
/// libgomp reads OMP_THREAD_LIMIT only when it loads, before main(). Measured on 2 cores, CHOLMOD's
/// OpenMP loops do not speed its supernodal factorization up, while OpenMP and OpenBLAS threads
/// together thrash (10^6 unknowns: 7.3 s with 2 + 2 threads, 2.5 s with 1 + 1, 2.1 s with OpenMP 1
/// and OpenBLAS 2). So when OMP_THREAD_LIMIT is unset, a program sets it to 1 and re-executes itself
/// once; SparseCholesky then chooses OpenBLAS's threads for each factorization.

namespace saasgaps {

/// Call first thing in main(); returns only in the re-executed (or already configured) process.
void ensure_thread_environment(char** argv);

}  // namespace saasgaps
