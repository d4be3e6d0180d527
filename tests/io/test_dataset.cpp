// io::Dataset (src/agglo/io/dataset.hpp): dimensions defined once, variables whose number of values is
// the product of their dimension lengths, no variable twice.
#include <gtest/gtest.h>

#include <stdexcept>

#include "agglo/io/dataset.hpp"

using namespace agglo::io;

TEST(Dataset, ShapesAreChecked) {
  Dataset d;
  d.add_dim("time", 3);
  d.add_dim("xyz", 3);
  d.add_dim("time", 3);  // the same again is a no-op
  EXPECT_EQ(d.dims.size(), 2u);
  EXPECT_THROW(d.add_dim("time", 4), std::logic_error);
  EXPECT_NO_THROW(d.add("a", {"time"}, "J", "a", {1, 2, 3}));
  EXPECT_THROW(d.add("b", {"time"}, "J", "b", {1, 2}), std::logic_error);
  EXPECT_THROW(d.add("c", {"time", "xyz"}, "m", "c", {1, 2, 3}), std::logic_error);
  EXPECT_THROW(d.add("e", {"frame"}, "m", "e", {}), std::logic_error);
  EXPECT_THROW(d.add("a", {"time"}, "J", "a again", {1, 2, 3}), std::logic_error);
  EXPECT_THROW(d.add_ints("n", {"time"}, "1", "n", {1}), std::logic_error);
  EXPECT_NO_THROW(d.add("s", {}, "s", "scalar", {4.0}));
  EXPECT_THROW(d.add("s2", {}, "s", "scalar", {}), std::logic_error);
  EXPECT_EQ(d.dim_length("xyz"), 3u);
  EXPECT_THROW(d.dim_length("frame"), std::logic_error);
  ASSERT_NE(d.find("a"), nullptr);
  EXPECT_EQ(d.find("b"), nullptr);
}
