// UDUNITS strings of declared config units (src/agglo/io/config_units.hpp), used for the config values
// stored in results.nc (sweep, calibrate).
#include <gtest/gtest.h>

#include "agglo/io/config_units.hpp"

using namespace agglo::io;

TEST(ConfigUnits, Conversion) {
  EXPECT_EQ(udunits("m/s"), "m s-1");
  EXPECT_EQ(udunits("kg/m^3"), "kg m-3");
  EXPECT_EQ(udunits("m^3/s"), "m3 s-1");
  EXPECT_EQ(udunits("1/m^3"), "m-3");
  EXPECT_EQ(udunits("Pa s"), "Pa s");
  EXPECT_EQ(udunits("-"), "1");
  EXPECT_EQ(udunits("r_p"), "1");
  EXPECT_EQ(udunits_of_config_key("projectile.speed"), "m s-1");
  EXPECT_EQ(udunits_of_config_key("population.1.diameter"), "m");
  EXPECT_EQ(udunits_of_config_key("no.such.key"), "1");
}
