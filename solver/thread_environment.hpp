#pragma once
/// Thread limits for CHOLMOD and OpenBLAS that must be set before the process starts.
///
/// Debian's CHOLMOD (SuiteSparse 5.12) asks OpenMP for 4 threads whatever the machine has, and
/// libgomp reads OMP_THREAD_LIMIT only when it loads, before main(). OpenBLAS threads on top of
/// CHOLMOD's OpenMP threads contend for the same cores: on 2 cores one BLAS thread is fastest (a
/// gap iteration of a 51k-unknown model: 0.10 s with one, 0.26 s with two). So when
/// OMP_THREAD_LIMIT is unset, a program sets it to the available cores, sets OPENBLAS_NUM_THREADS=1
/// unless the user chose a value, and re-executes itself once.

namespace saasgaps {

/// Call first thing in main(); returns only in the re-executed (or already configured) process.
void ensure_thread_environment(char** argv);

}  // namespace saasgaps
