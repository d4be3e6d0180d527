#pragma once
// Allocator for the solvers' large work vectors (the GMRES Krylov basis, 9 vectors of 18 MB each for a
// spectral solve of 1000 spheres at L = 47, and the solver's own vectors of that size; issue 25):
// * value-initialisation (vector::resize) leaves the numbers unset: such vectors are written before they
//   are read, and zeroing them first cost 13 % of that solve (perf, the memset of the basis);
// * blocks of at least kLargeBufferBytes are aligned to 2 MiB and marked for transparent huge pages
//   (Linux madvise(MADV_HUGEPAGE); a hint, without effect where the kernel has them disabled): their
//   first touch faults once per 2 MiB instead of once per 4 KiB page;
// * released blocks of that size are kept (at most kLargeBufferCacheBlocks) and handed to the next
//   request of the same rounded size: a new solver of the same problem size (agglo.electrostatic_forces
//   makes one per call) reuses pages the process already has instead of faulting in pages the kernel
//   must zero first. The price: up to that many blocks stay with the process after their solver is gone
//   (their touched pages only: the Krylov basis is reserved for restart + 1 vectors and touched as the
//   iteration reaches them); release_cached_large_buffers() returns them.
// Measured (perf stat / perf record of bench_spectral_far_field solve/fmm_k2.5/N:1000/, one thread): the
// page faults of that process and the kernel's share of the samples, docs/electrostatics.md
// "Fast far field". None of this changes a number that is computed: only where the memory comes from.
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace agglo::es {

// Smallest block (bytes) that is backed by huge pages (a few huge pages; smaller blocks stay with malloc).
inline constexpr std::size_t kLargeBufferBytes = std::size_t(4) << 20;
// Released large blocks kept for reuse.
inline constexpr std::size_t kLargeBufferCacheBlocks = 8;

// Memory for `bytes` bytes (>= kLargeBufferBytes: 2 MiB aligned and marked for huge pages); release with
// release_large_buffer(p, bytes) and the same `bytes`. Throws std::bad_alloc.
void* acquire_large_buffer(std::size_t bytes);
void release_large_buffer(void* p, std::size_t bytes) noexcept;
// Frees the kept blocks.
void release_cached_large_buffers() noexcept;

template <class T>
struct LargeBufferAllocator {
  using value_type = T;
  LargeBufferAllocator() = default;
  template <class U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(acquire_large_buffer(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { release_large_buffer(p, n * sizeof(T)); }
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const LargeBufferAllocator<U>&) const noexcept {
    return true;
  }
};

// A vector of doubles on LargeBufferAllocator (resize() leaves new numbers unset: use assign to zero).
using LargeVector = std::vector<double, LargeBufferAllocator<double>>;

}  // namespace agglo::es
