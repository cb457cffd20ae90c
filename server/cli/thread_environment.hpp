#pragma once
/// Thread limits that must be set before the process starts.
///
/// Debian's CHOLMOD (SuiteSparse 5.12) asks OpenMP for 4 threads whatever the machine has; libgomp
/// reads OMP_THREAD_LIMIT only when it loads, before main(). So when the variable is unset the
/// binary sets it to the number of available cores and re-executes itself, once.

namespace saasgaps::cli {

void ensure_thread_environment(int argc, char** argv);

}  // namespace saasgaps::cli
