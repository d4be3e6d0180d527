#pragma once
// Error types. ConfigError -> exit code 2 (bad input); NumericalError -> exit code 3
// (blow-up detected during a run: NaN, energy explosion, violated probability bound); InvalidRunError
// (a NumericalError) -> exit code 3 (a run whose result would not observe the experiment of the case);
// LimitError (a ConfigError) -> exit code 2 (a valid case beyond a run budget, run/budget.hpp);
// InterruptedError -> exit code 130 (the run was cancelled, e.g. by Ctrl-C; finished jobs of an
// ensemble are kept in its journal and `--resume` continues).
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

namespace agglo {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A case that follows the rules but exceeds a budget of steps, memory or output (run/budget.hpp): bad
// input like any ConfigError, told apart by front ends that report limits separately (Python).
struct LimitError : ConfigError {
  using ConfigError::ConfigError;
};

// An output file that cannot be written (a full or read-only disk, a quota): an unusable output folder,
// bad input like any ConfigError (exit 2), one line naming the file and the system's reason
// (io/output_dir.hpp, output_error). The run's folder is marked failed and keeps no temporary file.
struct OutputError : ConfigError {
  using ConfigError::ConfigError;
};

struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A run that cannot give a valid observation of its experiment, found while it runs: the target is not
// one agglomerate at launch, its contacts changed during the relaxation (e.g. torn apart by a field), or
// the projectile never touched it. Reported as an error (exit 3, naming the cause), never as an outcome.
struct InvalidRunError : NumericalError {
  using NumericalError::NumericalError;
};

struct InterruptedError : std::runtime_error {
  using std::runtime_error::runtime_error;
  // True when the run stopped before it wrote anything (while its case was read, run::plan).
  bool before_output = false;
};

// `text` cut for an error line: its first `max` characters (UTF-8 sequences kept whole) and "…" when it
// is longer, so that a huge key or value (a 1 MB --set) is not echoed whole.
inline std::string cut_for_message(std::string_view text, std::size_t max = 80) {
  if (text.size() <= max) return std::string(text);
  std::size_t n = max;
  while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xc0) == 0x80) --n;  // not inside a UTF-8 sequence
  return std::string(text.substr(0, n)) + "\u2026";
}

// `text` on one line: control characters (a raw newline, tab, ESC, U+0085...) and the Unicode
// line and paragraph separators U+2028/U+2029 copied from the input are shown escaped (\n, \t, \x1b, \u2028).
inline std::string one_line(std::string_view text) {
  std::string s;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') s += "\\n";
    else if (c == '\r') s += "\\r";
    else if (c == '\t') s += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      s += buf;
    } else if (c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) < 0xa0 &&
               static_cast<unsigned char>(text[i + 1]) >= 0x80) {  // C1 controls, e.g. U+0085 NEL
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(text[++i]));
      s += buf;
    } else if (c == 0xe2 && i + 2 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x80 &&
               (static_cast<unsigned char>(text[i + 2]) == 0xa8 || static_cast<unsigned char>(text[i + 2]) == 0xa9)) {
      s += static_cast<unsigned char>(text[i + 2]) == 0xa8 ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      s += text[i];
    }
  }
  return s;
}

}  // namespace agglo
