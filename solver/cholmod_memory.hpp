#pragma once
/// Process-wide settings for the memory CHOLMOD uses.

namespace saasgaps {

/// Routes CHOLMOD's allocations of 32 MiB and more to anonymous mappings advised to use transparent
/// huge pages. The factor of a 10^6-unknown model is about 800 MB; touching it in 4 KiB pages made
/// the first numeric factorization 2 s slower than the next ones on a virtual machine. Installed
/// once, before CHOLMOD allocates anything; later calls do nothing.
void use_huge_pages_for_cholmod();

}  // namespace saasgaps
