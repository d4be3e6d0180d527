#pragma once
// The work of a step's blocks shared out between its threads (engine.cpp): the items [0, m) of a block are
// claimed one at a time from the front by the thread that owns the block and from the back by a thread
// that has finished its own blocks, so a thread that the OS holds back on a shared machine does not hold up
// the step for its whole block, while on free cores each thread keeps to its own block (and cache). No
// physics: every item is claimed exactly once, so what is computed does not depend on who claims it.
#include <atomic>
#include <cstdint>
#include <vector>

namespace agglo::acoustics {

class alignas(64) BlockClaims {  // a cache line each: the owners' claims share no line
 public:
  void reset(std::uint32_t items) { ends_.store(std::uint64_t{items} << 32, std::memory_order_relaxed); }
  // The next item from the front (the owner) or from the back (a helper); -1 when none is left.
  std::int64_t front() { return claim(true); }
  std::int64_t back() { return claim(false); }

 private:
  std::int64_t claim(bool from_front) {
    std::uint64_t e = ends_.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t first = e & 0xffffffffu, end = e >> 32;  // items [first, end) are left
      if (first >= end) return -1;
      const std::uint64_t next = from_front ? e + 1 : e - (std::uint64_t{1} << 32);
      if (ends_.compare_exchange_weak(e, next, std::memory_order_relaxed))
        return static_cast<std::int64_t>(from_front ? first : end - 1);
    }
  }
  std::atomic<std::uint64_t> ends_{0};
};

// work(b, k) for every item k of every block b, on thread `thread` of a team of `team`: first the items of
// the thread's own blocks (b in [thread B / team, (thread + 1) B / team)) from the front, then what is left
// of the others from the back. (The team's barriers order these claims with the resets.)
template <class F>
void share_blocks(std::vector<BlockClaims>& claims, int thread, int team, F&& work) {
  const std::size_t nb = claims.size(), t = static_cast<std::size_t>(thread), tm = static_cast<std::size_t>(team);
  const std::size_t own0 = t * nb / tm, own1 = (t + 1) * nb / tm;
  for (std::size_t b = own0; b < own1; ++b)
    for (std::int64_t k = claims[b].front(); k >= 0; k = claims[b].front()) work(b, static_cast<std::size_t>(k));
  for (std::size_t s = 0; s < nb; ++s) {
    const std::size_t b = (own1 + s) % nb;
    if (b >= own0 && b < own1) continue;
    for (std::int64_t k = claims[b].back(); k >= 0; k = claims[b].back()) work(b, static_cast<std::size_t>(k));
  }
}

}  // namespace agglo::acoustics
