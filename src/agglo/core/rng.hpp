#pragma once
// Counter-based random numbers (Random123 Philox4x64-10). A draw is a pure function of
// (seed, stream, counter), so results do not depend on thread count or scheduling order:
// e.g. stream = particle or cell id, counter = step number and draw index.
#include <cstdint>

#include <Random123/philox.h>

#if defined(__GNUC__)
#define AGGLO_RNG_NOINLINE __attribute__((noinline))
#else
#define AGGLO_RNG_NOINLINE
#endif

namespace agglo {

class CounterRng {
 public:
  CounterRng(std::uint64_t seed, std::uint64_t stream, std::uint64_t counter)
      : key_{{seed, stream}}, ctr_{{counter, 0, 0, 0}} {}

  // Uniform in [0, 1) with 53 random bits.
  double uniform() {
    if (idx_ == 4) [[unlikely]]
      refill();
    return static_cast<double>(buf_.v[idx_++] >> 11) * 0x1.0p-53;
  }
  std::uint64_t bits() {
    if (idx_ == 4) [[unlikely]]
      refill();
    return buf_.v[idx_++];
  }

 private:
  // Out of line (one call per four draws): the ten Philox rounds need many registers, and inlined into
  // uniform() they made every draw save and restore six of them (12 instructions on a 10-instruction path).
  AGGLO_RNG_NOINLINE void refill() {
    r123::Philox4x64 gen;
    buf_ = gen(ctr_, key_);
    ++ctr_.v[1];
    idx_ = 0;
  }
  r123::Philox4x64::key_type key_;
  r123::Philox4x64::ctr_type ctr_;
  r123::Philox4x64::ctr_type buf_{};
  int idx_ = 4;
};

}  // namespace agglo

#undef AGGLO_RNG_NOINLINE
