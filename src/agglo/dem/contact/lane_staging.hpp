#pragma once
// What the fast pair loop's lanes read and write (pair_kernel.hpp, respond_lanes; docs/benchmarks_dem.md §9):
// LaneIn / LaneOut of one pair (T = double) or of a Lane of pairs, and LaneStaging, the engaged pairs of one
// chunk between the loop's passes: per pair its particle indices, the argument t of its contact root, its JKR
// constants and springs (kSpring: the tangential model keeps a sliding spring; kRoll, kTwist: the rolling and
// twisting models are active, with their springs), and after pass 2 its forces, torques, contact radius and
// springs. The particles' positions, velocities, spins, radii and masses are gathered by
// index when a Lane is read. No physics.
#include <cstddef>
#include <cstdint>
#include <utility>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/contact/lanes.hpp"
#include "agglo/dem/contact/pair_state.hpp"
#include "agglo/dem/neighbor_list.hpp"
#include "agglo/dem/particles.hpp"

namespace agglo::dem::contact {

template <class T>
struct LaneIn {
  lanes::V3<T> xi, xj, vi, vj, wi, wj;
  T ri, rj, mi, mj, t, a0, fc, estar;  // t = delta t_per_delta, the argument of the contact root
  lanes::V3<T> xi_t;                   // the sliding spring (zero without one)
  T R{};                               // effective radius (kRoll only)
  lanes::V3<T> xi_r{};                 // the rolling spring (kRoll only)
  T xi_q{};                            // the twisting angle (kTwist only)
};

template <class T>
struct LaneOut {
  lanes::V3<T> f_on_i, t_on_i, t_on_j, xi_t;
  T a;  // the contact radius
  lanes::V3<T> xi_r{};
  T xi_q{};
};

[[gnu::always_inline]] inline lanes::V3<double> to_lanes(const Vec3& v) { return {v.x, v.y, v.z}; }
[[gnu::always_inline]] inline Vec3 to_vec(const lanes::V3<double>& v) { return {v.x, v.y, v.z}; }

// T of a[idx[0]] (a Lane: of a[idx[0 .. kWidth<T>)]).
template <class T>
[[gnu::always_inline]] inline T gather(const std::vector<double>& a, const std::uint32_t* idx) {
  if constexpr (sizeof(T) == sizeof(double)) {
    return a[idx[0]];
  } else {
    return [&]<std::size_t... L>(std::index_sequence<L...>) {
      return T{a[idx[L]]...};
    }(std::make_index_sequence<lanes::kWidth<T>>{});
  }
}
// Four Vec3s into x, y, z lanes of four: (x, y) of each element as one 16-byte load, interleaved into the x and
// y lanes; z one by one.
[[gnu::always_inline]] inline lanes::V3<lanes::Quad> gather3_four(const std::vector<Vec3>& a,
                                                                 const std::uint32_t* idx) {
  using Q = lanes::Quad;
  using Half = double __attribute__((vector_size(16)));
  const Vec3 &e0 = a[idx[0]], &e1 = a[idx[1]], &e2 = a[idx[2]], &e3 = a[idx[3]];
  Half h0, h1, h2, h3;
  __builtin_memcpy(&h0, &e0.x, sizeof h0), __builtin_memcpy(&h1, &e1.x, sizeof h1);
  __builtin_memcpy(&h2, &e2.x, sizeof h2), __builtin_memcpy(&h3, &e3.x, sizeof h3);
  const Q xy02 = __builtin_shufflevector(h0, h2, 0, 1, 2, 3), xy13 = __builtin_shufflevector(h1, h3, 0, 1, 2, 3);
  return {__builtin_shufflevector(xy02, xy13, 0, 4, 2, 6), __builtin_shufflevector(xy02, xy13, 1, 5, 3, 7),
          Q{e0.z, e1.z, e2.z, e3.z}};
}
template <class T>
[[gnu::always_inline]] inline lanes::V3<T> gather3(const std::vector<Vec3>& a, const std::uint32_t* idx) {
  if constexpr (sizeof(T) == sizeof(double)) {
    return to_lanes(a[idx[0]]);
  } else if constexpr (lanes::kWidth<T> == 4) {
    return gather3_four(a, idx);
  } else {
    static_assert(lanes::kWidth<T> == 8);
    const lanes::V3<lanes::Quad> lo = gather3_four(a, idx), hi = gather3_four(a, idx + 4);
    const auto join = [](lanes::Quad l, lanes::Quad h) { return __builtin_shufflevector(l, h, 0, 1, 2, 3, 4, 5, 6, 7); };
    return {join(lo.x, hi.x), join(lo.y, hi.y), join(lo.z, hi.z)};
  }
}

// W: the pairs of a Lane (pass 2 reads and writes W entries at a time).
template <std::size_t kChunk, int W, bool kSpring, bool kRoll, bool kTwist>
struct LaneStaging {
  static constexpr std::size_t kCap = kChunk + W;
  enum Field { t = 0, a0, fc, estar, xi_t, R = xi_t + 3, xi_r, xi_q = xi_r + 3, kInputs, f = kInputs, ti = f + 3,
               tj = ti + 3, a = tj + 3, kFields };
  alignas(64) double v[kFields][kCap];
  std::uint32_t i[kCap], j[kCap], kind[kCap];

  // Entry n: engaged pair pr with contact-root argument t_root.
  [[gnu::always_inline]] void put(std::size_t n, const Pair& pr, double t_root) {
    i[n] = pr.i;
    j[n] = pr.j;
    kind[n] = pr.kind;
    v[t][n] = t_root;
    v[a0][n] = pr.jkr.a0;
    v[fc][n] = pr.jkr.Fc;
    v[estar][n] = pr.jkr.Estar;
    if constexpr (kSpring) {
      v[xi_t][n] = pr.state.xi_t.x;
      v[xi_t + 1][n] = pr.state.xi_t.y;
      v[xi_t + 2][n] = pr.state.xi_t.z;
    }
    if constexpr (kRoll) {
      v[R][n] = pr.jkr.R;
      v[xi_r][n] = pr.state.xi_r.x;
      v[xi_r + 1][n] = pr.state.xi_r.y;
      v[xi_r + 2][n] = pr.state.xi_r.z;
    }
    if constexpr (kTwist) v[xi_q][n] = pr.state.xi_q;
  }
  // Entries n .. the next multiple of W copied from entry n - 1 (n > 0).
  [[gnu::always_inline]] void pad(std::size_t n) {
    for (std::size_t e = n; e % W != 0; ++e) {
      for (int fld = 0; fld < kInputs; ++fld) v[fld][e] = v[fld][n - 1];
      i[e] = i[n - 1], j[e] = j[n - 1], kind[e] = kind[n - 1];
    }
  }
  template <class T>
  [[gnu::always_inline]] lanes::V3<T> get3(int field, std::size_t g) const {
    return {lanes::load<T>(&v[field][g]), lanes::load<T>(&v[field + 1][g]), lanes::load<T>(&v[field + 2][g])};
  }
  // The inputs of entries g .. g + W (T = Lane) or of entry g (T = double).
  template <class T>
  [[gnu::always_inline]] LaneIn<T> read(std::size_t g, const Particles& p) const {
    using lanes::load;
    const std::uint32_t *ii = &i[g], *jj = &j[g];
    LaneIn<T> in{gather3<T>(p.x, ii), gather3<T>(p.x, jj), gather3<T>(p.v, ii), gather3<T>(p.v, jj),
                 gather3<T>(p.w, ii), gather3<T>(p.w, jj), gather<T>(p.r, ii), gather<T>(p.r, jj),
                 gather<T>(p.m, ii),  gather<T>(p.m, jj),  load<T>(&v[t][g]),  load<T>(&v[a0][g]),
                 load<T>(&v[fc][g]),  load<T>(&v[estar][g]), {T{}, T{}, T{}}};
    if constexpr (kSpring) in.xi_t = get3<T>(xi_t, g);
    if constexpr (kRoll) in.R = load<T>(&v[R][g]), in.xi_r = get3<T>(xi_r, g);
    if constexpr (kTwist) in.xi_q = load<T>(&v[xi_q][g]);
    return in;
  }
  template <class T>
  [[gnu::always_inline]] void set3(int field, std::size_t g, const lanes::V3<T>& x) {
    lanes::store(&v[field][g], x.x);
    lanes::store(&v[field + 1][g], x.y);
    lanes::store(&v[field + 2][g], x.z);
  }
  template <class T>
  [[gnu::always_inline]] void write(std::size_t g, const LaneOut<T>& o) {
    set3(f, g, o.f_on_i);
    set3(ti, g, o.t_on_i);
    set3(tj, g, o.t_on_j);
    if constexpr (kSpring) set3(xi_t, g, o.xi_t);
    if constexpr (kRoll) set3(xi_r, g, o.xi_r);
    if constexpr (kTwist) lanes::store(&v[xi_q][g], o.xi_q);
    lanes::store(&v[a][g], o.a);
  }
  // The outputs of entry q.
  [[gnu::always_inline]] LaneOut<double> out(std::size_t q) const {
    LaneOut<double> o{get3<double>(f, q), get3<double>(ti, q), get3<double>(tj, q), {}, v[a][q]};
    if constexpr (kSpring) o.xi_t = get3<double>(xi_t, q);
    if constexpr (kRoll) o.xi_r = get3<double>(xi_r, q);
    if constexpr (kTwist) o.xi_q = v[xi_q][q];
    return o;
  }
  // One pair's outputs: its contact radius and springs into its state, its force and torques returned.
  [[gnu::always_inline]] static PairForce settle(const LaneOut<double>& o, ContactState& s) {
    s.a = o.a;
    if constexpr (kSpring) s.xi_t = to_vec(o.xi_t);
    if constexpr (kRoll) s.xi_r = to_vec(o.xi_r);
    if constexpr (kTwist) s.xi_q = o.xi_q;
    return PairForce{to_vec(o.f_on_i), to_vec(o.t_on_i), to_vec(o.t_on_j)};
  }
  [[gnu::always_inline]] PairForce take(std::size_t q, ContactState& s) const { return settle(out(q), s); }
};

}  // namespace agglo::dem::contact
