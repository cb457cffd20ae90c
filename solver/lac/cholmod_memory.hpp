#pragma once
/// Process-wide settings for the memory CHOLMOD uses.

namespace saasgaps {

/// Routes CHOLMOD's allocations of 32 MiB and more (the factor: about 840 MB at 10^6 unknowns) to
/// anonymous mappings of their own: fresh zero pages, touched once by CHOLMOD and returned to the
/// system when freed. Installed once, before CHOLMOD allocates anything; later calls do nothing.
void use_mapped_memory_for_cholmod();

/// Faults in every page of a block CHOLMOD allocated from its own mapping (MADV_POPULATE_WRITE),
/// so that CHOLMOD's first writes do not trap page by page. Nothing for smaller blocks (malloc's)
/// or on kernels older than 5.14, whose first writes fault the pages in as before.
void prefault_cholmod_block(void* block);

/// Whether those mappings are advised to use transparent huge pages (default: no). With the kernel's
/// defrag setting "madvise" (Debian's default) the advice makes the first touch compact memory
/// synchronously: measured on the development VM, 6.7-11 s per GB against 1.5-1.8 s per GB without
/// it, for a second pass 0.1-0.3 s faster per GB. saasgaps_bench --huge-pages measures both.
void advise_huge_pages(bool on);

}  // namespace saasgaps
