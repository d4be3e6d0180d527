#include "agglo/run/ranks.hpp"

namespace agglo::run {

bool is_output_rank() { return true; }

int rank_count() { return 1; }

}  // namespace agglo::run
