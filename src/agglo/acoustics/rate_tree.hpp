#pragma once
// Non-negative rates r_0..r_{n-1} with their running sums kept as a Fenwick (binary indexed) tree:
// changing one rate and drawing an index with probability r_k / sum both cost O(log n) (binned
// selection: the candidate rates of one row of group pairs, updated after every collision).
#include <bit>
#include <cstddef>
#include <vector>

namespace agglo::acoustics {

class RateTree {
 public:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  // Takes the rates r[0, n) (O(n) construction).
  void assign(const double* r, std::size_t n) {
    v_.assign(r, r + n);
    t_.assign(n + 1, 0.0);
    total_ = 0.0;
    for (std::size_t i = 1; i <= n; ++i) {
      t_[i] += v_[i - 1];
      total_ += v_[i - 1];
      const std::size_t up = i + (i & (~i + 1));
      if (up <= n) t_[up] += t_[i];
    }
    top_ = n == 0 ? 0 : std::bit_floor(n);
  }

  void set(std::size_t k, double r) {
    const double delta = r - v_[k];
    if (delta == 0.0) return;
    v_[k] = r;
    total_ += delta;
    for (std::size_t i = k + 1; i < t_.size(); i += i & (~i + 1)) t_[i] += delta;
  }

  std::size_t size() const { return v_.size(); }
  double value(std::size_t k) const { return v_[k]; }
  double total() const { return total_; }

  // Index k with r_0 + ... + r_{k-1} <= x < r_0 + ... + r_k, x in [0, total) (rounding at the end of the
  // range falls back to the last positive rate); npos if every rate is 0.
  std::size_t find(double x) const {
    std::size_t pos = 0;
    for (std::size_t step = top_; step > 0; step >>= 1)
      if (pos + step < t_.size() && t_[pos + step] <= x) {
        pos += step;
        x -= t_[pos];
      }
    std::size_t k = pos < v_.size() ? pos : v_.size() - 1;
    while (k > 0 && !(v_[k] > 0.0)) --k;
    return v_.empty() || !(v_[k] > 0.0) ? npos : k;
  }

 private:
  std::vector<double> v_, t_;  // rates; tree (1-based: t_[i] sums v over (i - lowbit(i), i])
  double total_ = 0.0;
  std::size_t top_ = 0;
};

}  // namespace agglo::acoustics
