#pragma once
// Error types. ConfigError -> exit code 2 (bad input); NumericalError -> exit code 3
// (blow-up detected during a run: NaN, energy explosion, violated probability bound);
// InterruptedError -> exit code 130 (the run was cancelled, e.g. by Ctrl-C; finished jobs of an
// ensemble are kept in its journal and `--resume` continues).
#include <stdexcept>
#include <string>

namespace agglo {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct InterruptedError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace agglo
