#include "solver/lac/cholmod_memory.hpp"

#include <SuiteSparse_config.h>
#include <malloc.h>
#include <sys/mman.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace saasgaps {

namespace {

constexpr std::size_t huge_threshold = std::size_t{32} << 20;
std::atomic<bool> huge_page_advice{false};

/// The big blocks we mapped, with their sizes; everything else came from malloc.
std::mutex mapped_mutex;
std::unordered_map<void*, std::size_t>& mapped() {
  static std::unordered_map<void*, std::size_t> blocks;
  return blocks;
}

std::size_t mapped_size(void* p) {
  std::lock_guard lock(mapped_mutex);
  const auto it = mapped().find(p);
  return it == mapped().end() ? 0 : it->second;
}

void* allocate(std::size_t size) {
  if (size < huge_threshold) return std::malloc(size);
  void* p = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return nullptr;
  // Advice only: without transparent huge pages the mapping works as usual.
  if (huge_page_advice) madvise(p, size, MADV_HUGEPAGE);
  std::lock_guard lock(mapped_mutex);
  mapped()[p] = size;
  return p;
}

void release(void* p) {
  if (p == nullptr) return;
  {
    std::lock_guard lock(mapped_mutex);
    const auto it = mapped().find(p);
    if (it != mapped().end()) {
      munmap(p, it->second);
      mapped().erase(it);
      return;
    }
  }
  std::free(p);
}

void* allocate_zeroed(std::size_t count, std::size_t size) {
  if (count != 0 && size > SIZE_MAX / count) return nullptr;
  const std::size_t bytes = count * size;
  if (bytes < huge_threshold) return std::calloc(count, size);
  return allocate(bytes);  // fresh anonymous mappings are zero
}

void* reallocate(void* p, std::size_t size) {
  const std::size_t old_size = mapped_size(p);
  if (old_size == 0 && size < huge_threshold) return std::realloc(p, size);
  void* q = allocate(size);
  if (q == nullptr) return nullptr;
  if (p != nullptr) {
    const std::size_t old_bytes = old_size != 0 ? old_size : malloc_usable_size(p);
    std::memcpy(q, p, std::min(old_bytes, size));
    release(p);
  }
  return q;
}

}  // namespace

void prefault_cholmod_block(void* block) {
  const std::size_t size = mapped_size(block);
#ifdef MADV_POPULATE_WRITE
  if (size != 0) madvise(block, size, MADV_POPULATE_WRITE);
#endif
}

void advise_huge_pages(bool on) { huge_page_advice = on; }

void use_mapped_memory_for_cholmod() {
  static std::once_flag once;
  std::call_once(once, [] {
    SuiteSparse_config.malloc_func = allocate;
    SuiteSparse_config.calloc_func = allocate_zeroed;
    SuiteSparse_config.realloc_func = reallocate;
    SuiteSparse_config.free_func = release;
  });
}

}  // namespace saasgaps
