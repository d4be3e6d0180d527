#pragma once
// The UDUNITS string of a config key's declared unit (core/settings_*.hpp), for results.nc variables
// that hold config values (sweep's swept keys, calibrate's parameters): "m/s" -> "m s-1",
// "kg/m^3" -> "kg m-3", "1/s" -> "s-1"; dimensionless or unit-less keys ("-", "r_p", "steps", ...) -> "1".
#include <string>
#include <string_view>

namespace agglo::io {

// `key` dotted, array elements by index or not ("population.1.diameter" = "population.diameter");
// "1" for a key that is not declared.
std::string udunits_of_config_key(std::string_view key);

// A declared unit as a UDUNITS string (see above).
std::string udunits(std::string_view unit);

}  // namespace agglo::io
