// Large work vectors on transparent huge pages, kept for reuse. See large_buffer.hpp.
#include "agglo/electrostatics/large_buffer.hpp"

#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace agglo::es {

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;

std::size_t round_to_huge_page(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

struct CachedBlock {
  void* p = nullptr;
  std::size_t size = 0;  // rounded to huge pages
};

// Released blocks kept for the next solver (at most kLargeBufferCacheBlocks, the oldest freed first).
struct LargeBufferCache {
  std::mutex mutex;
  std::vector<CachedBlock> blocks;
  ~LargeBufferCache() {
    for (const CachedBlock& b : blocks) std::free(b.p);
  }
};

LargeBufferCache& large_buffer_cache() {
  static LargeBufferCache cache;
  return cache;
}

}  // namespace

void* acquire_large_buffer(std::size_t bytes) {
  if (bytes < kLargeBufferBytes) return ::operator new(bytes);
  const std::size_t size = round_to_huge_page(bytes);
  {
    LargeBufferCache& c = large_buffer_cache();
    const std::lock_guard<std::mutex> lock(c.mutex);
    for (std::size_t i = c.blocks.size(); i-- > 0;)
      if (c.blocks[i].size == size) {
        void* p = c.blocks[i].p;
        c.blocks.erase(c.blocks.begin() + static_cast<std::ptrdiff_t>(i));
        return p;
      }
  }
  void* p = std::aligned_alloc(kHugePage, size);
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(p, size, MADV_HUGEPAGE);  // a hint: its failure leaves ordinary pages
#endif
  return p;
}

void release_large_buffer(void* p, std::size_t bytes) noexcept {
  if (bytes < kLargeBufferBytes) {
    ::operator delete(p);
    return;
  }
  void* evicted = p;
  {
    LargeBufferCache& c = large_buffer_cache();
    const std::lock_guard<std::mutex> lock(c.mutex);
    try {
      c.blocks.push_back({p, round_to_huge_page(bytes)});
      evicted = nullptr;
      if (c.blocks.size() > kLargeBufferCacheBlocks) {
        evicted = c.blocks.front().p;
        c.blocks.erase(c.blocks.begin());
      }
    } catch (...) {  // no memory for the list: free the block instead of keeping it
    }
  }
  std::free(evicted);
}

void release_cached_large_buffers() noexcept {
  LargeBufferCache& c = large_buffer_cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  for (const CachedBlock& b : c.blocks) std::free(b.p);
  c.blocks.clear();
}

}  // namespace agglo::es
