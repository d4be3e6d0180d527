// The solvers' large work vectors (electrostatics/large_buffer.hpp).
#include <gtest/gtest.h>

#include <cstdint>

#include "agglo/electrostatics/large_buffer.hpp"

using namespace agglo::es;

namespace {

std::uintptr_t large_buffer_address(const LargeVector& v) { return reinterpret_cast<std::uintptr_t>(v.data()); }

}  // namespace

// A block of kLargeBufferBytes or more starts on a 2 MiB boundary (a huge page); released, it is handed to
// the next request of the same rounded size instead of a new mapping; the values there are the caller's.
TEST(LargeBuffer, LargeBlocksAreHugePageAlignedAndReused) {
  release_cached_large_buffers();
  const std::size_t n = kLargeBufferBytes / sizeof(double) + 1000;
  std::uintptr_t first = 0;
  {
    LargeVector v(n, 1.5);
    first = large_buffer_address(v);
    EXPECT_EQ(first % (std::size_t(2) << 20), 0u);
    EXPECT_EQ(v[n - 1], 1.5);
  }
  {
    LargeVector w;
    w.assign(n - 10, 2.5);  // rounds to the same number of huge pages
    EXPECT_EQ(large_buffer_address(w), first);
    EXPECT_EQ(w[0], 2.5);
    EXPECT_EQ(w[n - 11], 2.5);
  }
  release_cached_large_buffers();
  LargeVector small(16, 3.0);  // below kLargeBufferBytes: ordinary operator new
  EXPECT_EQ(small[15], 3.0);
}
