#pragma once
// The pair loop compiled for one combination of sub-models (docs/model.md §A.2). Per pair:
//   1. overlap delta = r_i + r_j - |x_j - x_i|; hysteresis: a contact forms at delta >= 0 and breaks
//      below -Normal::break_separation (state reset on both events);
//   2. a = Normal::contact_radius, F_ne = Normal::force, eta_N = Damping::coefficient(m*, k_N);
//   3. relative velocity at the contact plane with levers l_i + l_j = |x_j - x_i| (l_i = r_i at
//      touching, conserving angular momentum exactly); F_n = F_ne + eta_N d(delta)/dt on i along -n;
//   4. F_t = Tangential::force, then Twisting::torque and Rolling::torque (moments on i, -moment on j;
//      models declaring `inactive` are skipped), finally the lever torques l_i n x F_t, l_j n x F_t.
// A sphere against a wall (wall.hpp) runs steps 2-4 unchanged with n = -wall normal, m* = m, l_i = h
// (the centre height), l_j = 0 and the wall at rest: the same sub-models, R* = r in its JkrPair.
// The kernel holds one set of sub-models per ordered pair of material ids (dem/material.hpp) and
// evaluates pair k with the set Pair::kind names (a wall contact: WallContacts::kind); with a single
// material there is one set. The interface each sub-model implements is the call made on it below.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "agglo/dem/contact/contact_kernel.hpp"
#include "agglo/dem/contact/contact_point.hpp"
#include "agglo/dem/contact/lane_staging.hpp"
#include "agglo/dem/contact/model_names.hpp"
#include "agglo/dem/contact_params.hpp"
#include "agglo/dem/parallel_for.hpp"

namespace agglo::dem::contact {

template <class M>
concept Inactive = requires { requires M::inactive; };
template <class M>
concept HasLanes = requires { requires M::has_lanes; };
template <class M>
concept KeepsSlidingSpring = requires { requires M::sliding_spring; };

template <class Normal, class Damping, class Tangential, class Rolling, class Twisting>
class PairKernel final : public ContactKernel {
  static_assert(Normal::category == Category::normal && Damping::category == Category::damping &&
                Tangential::category == Category::tangential && Rolling::category == Category::rolling &&
                Twisting::category == Category::twisting);

  // Pairs per chunk of accumulate_range's passes (their states stay in the L1 cache between the passes).
  static constexpr std::size_t kChunk = 64;

  template <int W>
  using Staged = LaneStaging<kChunk, W, KeepsSlidingSpring<Tangential>, !Inactive<Rolling>, !Inactive<Twisting>>;
  // Pairs per Lane: 4, or 8 in the wide form (lanes::wide_lanes()).
  static constexpr int kNarrow = 4, kWide = 8;

  // The inputs of one engaged pair for respond_lanes.
  [[gnu::always_inline]] static LaneIn<double> lane_in(const JkrPair& jkr, const PairKinematics& k,
                                                       const ContactState& s, double t) {
    LaneIn<double> in{to_lanes(k.xi), to_lanes(k.xj), to_lanes(k.vi), to_lanes(k.vj), to_lanes(k.wi),
                      to_lanes(k.wj), k.ri, k.rj, k.mi, k.mj, t, jkr.a0, jkr.Fc, jkr.Estar, {0.0, 0.0, 0.0}};
    if constexpr (KeepsSlidingSpring<Tangential>) in.xi_t = to_lanes(s.xi_t);
    if constexpr (!Inactive<Rolling>) in.R = jkr.R, in.xi_r = to_lanes(s.xi_r);
    if constexpr (!Inactive<Twisting>) in.xi_q = s.xi_q;
    return in;
  }

 public:
  // Whether the fast path runs several pairs at once (sub_model.hpp: every model has a lane form).
  static constexpr bool kLaned = HasLanes<Normal> && HasLanes<Damping> && HasLanes<Tangential> &&
                                 (Inactive<Rolling> || HasLanes<Rolling>) && (Inactive<Twisting> || HasLanes<Twisting>);

  // One set of sub-models per pair of material ids (material.hpp): table[k] for Pair::kind == k.
  explicit PairKernel(const std::vector<ContactParams>& table) {
    models_.reserve(table.size());
    for (const auto& p : table) models_.emplace_back(p);
  }

  void evaluate_pairs(std::vector<Pair>& pairs, const Particles& p, double dt,
                      std::vector<PairForce>& out) const override {
    out.resize(pairs.size());
    parallel_for(static_cast<std::int64_t>(pairs.size()), [&](std::int64_t k) {
      Pair& pr = pairs[k];
      const PairKinematics kin{p.x[pr.i], p.x[pr.j], p.v[pr.i], p.v[pr.j], p.w[pr.i], p.w[pr.j],
                               p.r[pr.i], p.r[pr.j], p.m[pr.i], p.m[pr.j]};
      out[k] = models_[pr.kind].force(pr.jkr, kin, pr.state, dt);
    });
  }

  // Serially in pair order, with the fast arithmetic (Models::fast_force). flatten: the sub-model calls are
  // inlined into the loop (without it GCC keeps the tangential force out of line).
  void accumulate_pairs(std::vector<Pair>& pairs, Particles& p, double dt) const override {
    if (lanes::wide_lanes())
      accumulate_all_wide(pairs, p, dt);
    else
      accumulate_all(pairs, p, dt);
  }
  void crossing_forces(std::vector<Pair>& pairs, const Particles& p, double dt, const PairBlocks& b, std::size_t part,
                       std::size_t parts, std::vector<PairForce>& crossing) const override {
    if (lanes::wide_lanes())
      crossing_part_wide(pairs, p, dt, b, part, parts, crossing);
    else
      crossing_part(pairs, p, dt, b, part, parts, crossing);
  }
  void block_forces(std::vector<Pair>& pairs, Particles& p, double dt, const PairBlocks& b, std::size_t t,
                    const std::vector<PairForce>& crossing) const override {
    if (lanes::wide_lanes())
      block_part_wide(pairs, p, dt, b, t, crossing);
    else
      block_part(pairs, p, dt, b, t, crossing);
  }

  // (the bodies of the three above; GCC clones no virtual function)
  [[gnu::flatten]] AGGLO_LANE_CLONES void accumulate_all(std::vector<Pair>& pairs, Particles& p, double dt) const {
    accumulate_all_of<kNarrow>(pairs, p, dt);
  }
  [[gnu::flatten]] AGGLO_WIDE_TARGET void accumulate_all_wide(std::vector<Pair>& pairs, Particles& p, double dt) const {
    accumulate_all_of<kWide>(pairs, p, dt);
  }
  template <int W>
  [[gnu::always_inline]] void accumulate_all_of(std::vector<Pair>& pairs, Particles& p, double dt) const {
    std::fill(p.f.begin(), p.f.end(), Vec3{});
    std::fill(p.t.begin(), p.t.end(), Vec3{});
    accumulate_range<false, W>(pairs, p, dt, 0, pairs.size(), 0, nullptr);
  }

  // Pairs [k0, k1) added to their particles in pair order, in chunks of kChunk pairs: the three passes of
  // accumulate_range_lanes, or for models without lane forms the two of accumulate_range_scalar (first step 1 and
  // the contact root of every pair, Models::fast_engage: short independent chains of a square root and a
  // division, which the core overlaps across pairs; then the rest of the law, Models::fast_respond, and the
  // sums). The same operations as fast_force pair by pair, so the same bits as fast_pair, and as the parallel
  // path's phase 1 (crossing_part_of, the same passes): a pair whose j is >= j_end (a crossing pair of a block,
  // pair_blocks.hpp; only with Crossing) was evaluated there, and its force crossing[k] goes to i. So the sums
  // are the same bits on any number of threads.
  template <bool Crossing, int W>
  [[gnu::always_inline]] void accumulate_range(std::vector<Pair>& pairs, Particles& p, double dt, std::size_t k0,
                                               std::size_t k1, std::uint32_t j_end, const PairForce* crossing) const {
    if constexpr (kLaned)
      accumulate_range_lanes<Crossing, W>(pairs, p, dt, k0, k1, j_end, crossing);
    else
      accumulate_range_scalar<Crossing>(pairs, p, dt, k0, k1, j_end, crossing);
  }

  // accumulate_range with the lanes (kLaned): pass 1 as in accumulate_range_scalar, the engaged pairs' inputs
  // copied into the chunk's Staged arrays; pass 2 the rest of the law W pairs at a time (respond_lanes; a
  // group of different material pairs one pair at a time), outputs back into Staged; pass 3 the sums in pair
  // order. respond_lanes is the same code on one double and on a Lane, so the bits are those of one pair at a
  // time (fast_force on the parallel path's crossing pairs).
  template <bool Crossing, int W>
  [[gnu::always_inline]] void accumulate_range_lanes(std::vector<Pair>& pairs, Particles& p, double dt,
                                                     std::size_t k0, std::size_t k1, std::uint32_t j_end,
                                                     const PairForce* crossing) const {
    Staged<W> st;
    for (std::size_t c0 = k0; c0 < k1; c0 += kChunk) {
      const std::size_t c1 = std::min(k1, c0 + kChunk);
      respond_engaged(
          st, p, dt, c0, c1, [&](std::size_t k) -> Pair& { return pairs[k]; },
          [&](const Pair& pr) { return Crossing && pr.j >= j_end; });
      std::size_t q = 0;
      add_chunk<Crossing>(pairs, p, c0, c1, j_end, crossing, [&](Pair& pr) { return st.take(q++, pr.state); });
    }
  }

  // Passes 1 and 2 of a chunk: step 1 of pairs pair_at(c0) .. pair_at(c1 - 1) but those skip(pair) names, the
  // engaged ones staged into st in that order, then the rest of their law (respond_staged).
  template <int W, class PairAt, class Skip>
  [[gnu::always_inline]] void respond_engaged(Staged<W>& st, const Particles& p, double dt, std::size_t c0,
                                              std::size_t c1, PairAt&& pair_at, Skip&& skip) const {
    std::size_t n = 0;
    for (std::size_t c = c0; c < c1; ++c) {
      Pair& pr = pair_at(c);
      if (skip(pr)) continue;
      double t = 0.0;
      if (models_[pr.kind].engage_root_arg(pr.jkr, kinematics(pr, p), pr.state, t)) st.put(n++, pr, t);
    }
    respond_staged(st, n, p, dt);
  }

  // The sums of pairs [c0, c1) in pair order: force_of(pair) of each active pair (an engaged contact is active
  // after step 1; an inactive pair's zero force is not added, which changes no bit, as in
  // ContactKernel::accumulate_wall: the sums start at +0 and only add, so they are never -0), a crossing pair's
  // buffered force to its i only. The sums into i run in registers while consecutive pairs share it (RunningSum).
  template <bool Crossing, class ForceOf>
  [[gnu::always_inline]] static void add_chunk(std::vector<Pair>& pairs, Particles& p, std::size_t c0, std::size_t c1,
                                               std::uint32_t j_end, const PairForce* crossing, ForceOf&& force_of) {
    RunningSum sum;
    for (std::size_t k = c0; k < c1; ++k) {
      Pair& pr = pairs[k];
      if (Crossing && pr.j >= j_end) {
        sum.to(pr.i, p);
        sum.f += crossing[k].f_on_i;
        sum.t += crossing[k].t_on_i;
        continue;
      }
      if (!pr.state.active) continue;
      const PairForce out = force_of(pr);
      sum.to(pr.i, p);
      sum.f += out.f_on_i;
      sum.t += out.t_on_i;
      p.f[pr.j] -= out.f_on_i;
      p.t[pr.j] += out.t_on_j;
    }
    sum.store(p);
  }

  // The force and torque of particle q, read once and written back once while the pairs of q as their i follow
  // each other (the neighbour list is sorted by i): the same additions in the same order as adding into p.f[q]
  // and p.t[q] pair by pair, since a pair's other particle j is never q.
  struct RunningSum {
    static constexpr std::uint32_t kNone = UINT32_MAX;
    std::uint32_t q = kNone;
    Vec3 f, t;
    [[gnu::always_inline]] void to(std::uint32_t i, Particles& p) {
      if (i == q) return;
      store(p);
      q = i, f = p.f[i], t = p.t[i];
    }
    [[gnu::always_inline]] void store(Particles& p) const {
      if (q != kNone) p.f[q] = f, p.t[q] = t;
    }
  };

  // Pass 2 of accumulate_range_lanes on the n staged pairs.
  template <int W>
  [[gnu::always_inline]] void respond_staged(Staged<W>& st, std::size_t n, const Particles& p, double dt) const {
    using L = lanes::Lane<W>;
    if (n == 0) return;
    st.pad(n);
    for (std::size_t g = 0; g < n; g += W) {
      const std::uint32_t kind = st.kind[g];
      bool same = true;
      for (std::size_t l = 1; l < W; ++l) same = same && st.kind[g + l] == kind;
      if (same) {
        st.template write<L>(g, models_[kind].respond_lanes(st.template read<L>(g, p), dt));
      } else {
        for (std::size_t l = g; l < std::min(n, g + W); ++l)
          st.template write<double>(l, models_[st.kind[l]].respond_lanes(st.template read<double>(l, p), dt));
      }
    }
  }

  // The one-thread loop of the sub-models without lane forms: two passes per chunk.
  template <bool Crossing>
  [[gnu::always_inline]] void accumulate_range_scalar(std::vector<Pair>& pairs, Particles& p, double dt,
                                                      std::size_t k0, std::size_t k1, std::uint32_t j_end,
                                                      const PairForce* crossing) const {
    std::array<double, kChunk> root;
    for (std::size_t c0 = k0; c0 < k1; c0 += kChunk) {
      const std::size_t c1 = std::min(k1, c0 + kChunk);
      for (std::size_t k = c0; k < c1; ++k) {
        Pair& pr = pairs[k];
        if (Crossing && pr.j >= j_end) continue;
        models_[pr.kind].fast_engage(pr.jkr, kinematics(pr, p), pr.state, root[k - c0]);
      }
      add_chunk<Crossing>(pairs, p, c0, c1, j_end, crossing, [&](Pair& pr) {
        return models_[pr.kind].fast_respond(pr.jkr, kinematics(pr, p), pr.state, dt, root[&pr - &pairs[c0]]);
      });
    }
  }

  // Phase 1 of the blocks (contact_kernel.hpp): the crossing pairs of part `part`, in chunks as accumulate_range
  // (lanes where the sub-models have them, one pair at a time otherwise), each pair's force into crossing[k].
  [[gnu::flatten]] AGGLO_LANE_CLONES void crossing_part(std::vector<Pair>& pairs, const Particles& p, double dt,
                                                        const PairBlocks& b, std::size_t part, std::size_t parts,
                                                        std::vector<PairForce>& crossing) const {
    crossing_part_of<kNarrow>(pairs, p, dt, b, part, parts, crossing);
  }
  [[gnu::flatten]] AGGLO_WIDE_TARGET void crossing_part_wide(std::vector<Pair>& pairs, const Particles& p, double dt,
                                                             const PairBlocks& b, std::size_t part, std::size_t parts,
                                                             std::vector<PairForce>& crossing) const {
    crossing_part_of<kWide>(pairs, p, dt, b, part, parts, crossing);
  }
  template <int W>
  [[gnu::always_inline]] void crossing_part_of(std::vector<Pair>& pairs, const Particles& p, double dt,
                                               const PairBlocks& b, std::size_t part, std::size_t parts,
                                               std::vector<PairForce>& crossing) const {
    const std::size_t n = b.crossing.size(), end = (part + 1) * n / parts;
    if constexpr (!kLaned) {
      for (std::size_t c = part * n / parts; c < end; ++c)
        crossing[b.crossing[c]] = fast_pair_force(pairs[b.crossing[c]], p, dt);
    } else {
      Staged<W> st;
      for (std::size_t c0 = part * n / parts; c0 < end; c0 += kChunk) {
        const std::size_t c1 = std::min(end, c0 + kChunk);
        respond_engaged(
            st, p, dt, c0, c1, [&](std::size_t c) -> Pair& { return pairs[b.crossing[c]]; },
            [](const Pair&) { return false; });
        std::size_t q = 0;
        for (std::size_t c = c0; c < c1; ++c) {
          Pair& pr = pairs[b.crossing[c]];
          crossing[b.crossing[c]] = pr.state.active ? st.take(q++, pr.state) : PairForce{};
        }
      }
    }
  }

  // Phase 2, block t: the own pairs in the chunks of the one-thread loop (accumulate_range).
  [[gnu::flatten]] AGGLO_LANE_CLONES void block_part(std::vector<Pair>& pairs, Particles& p, double dt,
                                                     const PairBlocks& b, std::size_t t,
                                                     const std::vector<PairForce>& crossing) const {
    block_part_of<kNarrow>(pairs, p, dt, b, t, crossing);
  }
  [[gnu::flatten]] AGGLO_WIDE_TARGET void block_part_wide(std::vector<Pair>& pairs, Particles& p, double dt,
                                                          const PairBlocks& b, std::size_t t,
                                                          const std::vector<PairForce>& crossing) const {
    block_part_of<kWide>(pairs, p, dt, b, t, crossing);
  }
  template <int W>
  [[gnu::always_inline]] void block_part_of(std::vector<Pair>& pairs, Particles& p, double dt, const PairBlocks& b,
                                            std::size_t t, const std::vector<PairForce>& crossing) const {
    const std::uint32_t end = b.first_particle[t + 1];
    for (std::uint32_t q = b.first_particle[t]; q < end; ++q) p.f[q] = p.t[q] = Vec3{};
    for (std::size_t k : b.crossing_in[t]) {
      p.f[pairs[k].j] -= crossing[k].f_on_i;
      p.t[pairs[k].j] += crossing[k].t_on_j;
    }
    accumulate_range<true, W>(pairs, p, dt, b.first_pair[t], b.first_pair[t + 1], end, crossing.data());
  }

  PairForce fast_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt,
                      std::uint32_t kind) const override {
    return models_[kind].fast_force(jkr, k, s, dt);
  }
  PairForce evaluate_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt,
                          std::uint32_t kind) const override {
    return models_[kind].force(jkr, k, s, dt);
  }

  void evaluate_wall(const Wall& w, WallContacts& wc, const Particles& p, double dt,
                     std::vector<PairForce>& out) const override {
    out.resize(p.size());
    parallel_for(static_cast<std::int64_t>(p.size()), [&](std::int64_t k) {
      const WallKinematics kin{w.height(p.x[k]), -w.normal, p.v[k], p.w[k], p.r[k], p.m[k]};
      out[k] = models_[wc.kind[k]].wall_force(wc.jkr[k], kin, wc.state[k], dt);
    });
  }

  void accumulate_wall(const Wall& w, WallContacts& wc, Particles& p, double dt) const override {
    parallel_for(static_cast<std::int64_t>(p.size()), [&](std::int64_t k) {
      const double h = w.height(p.x[k]);
      ContactState& s = wc.state[k];
      if (!s.active && p.r[k] - h < 0.0) {  // apart and not touching: Models::engaged's first exit, as wall_force
        s.delta = p.r[k] - h;
        return;
      }
      const WallKinematics kin{h, -w.normal, p.v[k], p.w[k], p.r[k], p.m[k]};
      const PairForce f = models_[wc.kind[k]].wall_force(wc.jkr[k], kin, s, dt);
      if (s.active) {
        p.f[k] += f.f_on_i;
        p.t[k] += f.t_on_i;
      }
    });
  }

  PairForce evaluate_wall_contact(const JkrPair& jkr, const WallKinematics& k, ContactState& s, double dt,
                                  std::uint32_t kind) const override {
    return models_[kind].wall_force(jkr, k, s, dt);
  }

 private:
  [[gnu::always_inline]] static PairKinematics kinematics(const Pair& pr, const Particles& p) {
    return PairKinematics{p.x[pr.i], p.x[pr.j], p.v[pr.i], p.v[pr.j], p.w[pr.i], p.w[pr.j],
                          p.r[pr.i], p.r[pr.j], p.m[pr.i], p.m[pr.j]};
  }

  // The fast path's force of one pair (Models::fast_force).
  [[gnu::always_inline]] PairForce fast_pair_force(Pair& pr, const Particles& p, double dt) const {
    return models_[pr.kind].fast_force(pr.jkr, kinematics(pr, p), pr.state, dt);
  }

  // The sub-models of one pair of materials and the contact they compute.
  struct Models {
    explicit Models(const ContactParams& p) : normal_(p), damping_(p), tangential_(p), rolling_(p), twisting_(p) {}

    // Step 1: true while the contact is (or becomes) active.
    bool engaged(const JkrPair& jkr, double delta, ContactState& s) const {
      s.delta = delta;
      if (!s.active) {
        if (delta < 0.0) return false;
        s = ContactState{};
        s.active = true;
        s.delta = delta;
      } else if (delta < -normal_.break_separation(jkr)) {
        s = ContactState{};
        s.delta = delta;
        return false;
      }
      return true;
    }

    // flatten: the sub-model calls are inlined into one body (as fast as a hand-written law; without it
    // GCC keeps them out of line and a step costs ~25 % more).
    [[gnu::flatten, gnu::always_inline]] PairForce force(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt) const {
      const Vec3 d = k.xj - k.xi;
      const double dist = norm(d);
      const double delta = k.ri + k.rj - dist;
      if (!engaged(jkr, delta, s)) return PairForce{};
      return respond(jkr, delta, geometry(k, d, dist), s, dt);
    }

    // The fast path (docs/benchmarks_dem.md §8; the reference twin is force): the same law with the contact
    // radius from Normal::contact_root where the model has one (no warm start, no convergence test; a = s^2 a0,
    // F_ne from s), one division 1/|d| for n and the levers. Within the documented tolerance of force, not its
    // bits. In two parts (PairKernel::accumulate_range runs them in two passes).
    [[gnu::always_inline]] PairForce fast_force(const JkrPair& jkr, const PairKinematics& k, ContactState& s,
                                                double dt) const {
      if constexpr (kLaned) {
        double t = 0.0;
        if (!engage_root_arg(jkr, k, s, t)) return PairForce{};
        return Staged<kNarrow>::settle(respond_lanes(lane_in(jkr, k, s, t), dt), s);
      } else {
        double root = 0.0;
        if (!fast_engage(jkr, k, s, root)) return PairForce{};
        return fast_respond(jkr, k, s, dt, root);
      }
    }

    // Step 1 of the lane path: true while engaged, with t = delta t_per_delta, the argument of the contact root.
    [[gnu::always_inline]] bool engage_root_arg(const JkrPair& jkr, const PairKinematics& k, ContactState& s,
                                                double& t) const {
      double delta = 0.0;
      if (!fast_overlap_engaged(jkr, k, s, delta)) return false;
      t = delta * jkr.t_per_delta;
      return true;
    }

    // Step 1 of the fast path: the overlap (one square root) and the hysteresis; true while engaged.
    [[gnu::always_inline]] bool fast_overlap_engaged(const JkrPair& jkr, const PairKinematics& k, ContactState& s,
                                                     double& delta) const {
      const Vec3 d = k.xj - k.xi;
      delta = k.ri + k.rj - std::sqrt(norm2(d));
      return engaged(jkr, delta, s);
    }

    // Steps 2-4 of engaged contacts after fast_engage, on one pair (T = double) or a Lane of pairs: the
    // arithmetic of fast_respond and respond_with with the lane forms of the sub-models (kLaned only).
    template <class T>
    [[gnu::always_inline]] LaneOut<T> respond_lanes(const LaneIn<T>& in, double dt) const {
      using namespace lanes;
      const V3<T> d = in.xj - in.xi;
      const T dist2 = norm2(d);
      const T dist = sqrt(dist2);
      const T inv = 1.0 / dist;
      LanePoint<T> c;
      c.n = d * inv;
      const T mstar = in.mi * in.mj / (in.mi + in.mj);
      const T li = (dist2 + in.ri * in.ri - in.rj * in.rj) * (0.5 * inv);
      const T lj = dist - li;
      const V3<T> vrel = in.vi - in.vj + cross(li * in.wi + lj * in.wj, c.n);
      const T root = Normal::contact_root_lanes(in.t);
      c.a = root * root * in.a0;
      c.f_ne = Normal::force_of_root_lanes(in.fc, root);
      c.eta_n = damping_.coefficient_lanes(mstar, Normal::stiffness_lanes(in.estar, c.a));
      const T ddelta_dt = dot(vrel, c.n);
      c.vs = vrel - ddelta_dt * c.n;
      c.f_n = c.f_ne + c.eta_n * ddelta_dt;
      c.dt = T{} + dt;
      c.w_rel = in.wi - in.wj;
      LaneOut<T> out;
      out.a = c.a;
      out.xi_t = in.xi_t;
      const V3<T> ft = tangential_.force_lanes(c, in.fc, out.xi_t);
      V3<T> ti{T{}, T{}, T{}}, tj = ti;  // the moments in respond_with's order: twisting, rolling, levers
      if constexpr (!Inactive<Twisting>) {
        out.xi_q = in.xi_q;
        const V3<T> m = twisting_.torque_lanes(c, in.fc, out.xi_q);
        ti = ti + m, tj = tj - m;
      }
      if constexpr (!Inactive<Rolling>) {
        out.xi_r = in.xi_r;
        const V3<T> m = rolling_.torque_lanes(c, in.fc, in.a0, in.R, out.xi_r);
        ti = ti + m, tj = tj - m;
      }
      out.f_on_i = -c.f_n * c.n + ft;
      out.t_on_i = ti + li * cross(c.n, ft);
      out.t_on_j = tj + lj * cross(c.n, ft);
      return out;
    }

    // Step 1 and the contact radius s.a (root: s = (a/a0)^(1/2) of Normal::contact_root); true while engaged.
    [[gnu::always_inline]] bool fast_engage(const JkrPair& jkr, const PairKinematics& k, ContactState& s,
                                            double& root) const {
      double delta = 0.0;
      if (!fast_overlap_engaged(jkr, k, s, delta)) return false;
      if constexpr (requires { normal_.contact_root(jkr, delta); }) {
        root = normal_.contact_root(jkr, delta);
        s.a = root * root * jkr.a0;
      } else {  // a normal model without a fast root: its contact_radius, as in force
        s.a = normal_.contact_radius(jkr, delta, s.a);
      }
      return true;
    }

    // Steps 2-4 of an engaged contact after fast_engage.
    [[gnu::always_inline]] PairForce fast_respond(const JkrPair& jkr, const PairKinematics& k, ContactState& s,
                                                  double dt, double root) const {
      const Vec3 d = k.xj - k.xi;
      const double dist2 = norm2(d);
      const double dist = std::sqrt(dist2);
      const double inv = 1.0 / dist;
      Geometry g;
      g.n = d * inv;
      g.mstar = k.mi * k.mj / (k.mi + k.mj);
      g.li = (dist2 + k.ri * k.ri - k.rj * k.rj) * (0.5 * inv);
      g.lj = dist - g.li;
      g.vrel = k.vi - k.vj + cross(g.li * k.wi + g.lj * k.wj, g.n);
      g.w_rel = k.wi - k.wj;
      double f_ne;
      if constexpr (requires { normal_.force_of_root(jkr, root); })
        f_ne = normal_.force_of_root(jkr, root);
      else
        f_ne = normal_.force(jkr, s.a);
      return respond_with(jkr, g, s, dt, f_ne);
    }

    // A sphere against a wall (wall.hpp): the partner of infinite radius and mass, at rest.
    [[gnu::flatten]] PairForce wall_force(const JkrPair& jkr, const WallKinematics& k, ContactState& s,
                                          double dt) const {
      const double delta = k.r - k.h;
      if (!engaged(jkr, delta, s)) return PairForce{};
      Geometry g;
      g.n = k.n;
      g.mstar = k.m;
      g.li = k.h;
      g.lj = 0.0;
      g.vrel = k.v + cross(g.li * k.w, g.n);
      g.w_rel = k.w;
      return respond(jkr, delta, g, s, dt);
    }

    // Steps 2-4 of an engaged contact: normal n (from i to its partner), reduced mass, levers to the
    // contact plane, relative velocity of i at the contact and relative angular velocity.
    struct Geometry {
      Vec3 n;
      double mstar = 0.0, li = 0.0, lj = 0.0;
      Vec3 vrel, w_rel;
    };

    // The geometry of a pair of spheres at centre distance dist = |d|, d = x_j - x_i.
    [[gnu::always_inline]] static Geometry geometry(const PairKinematics& k, const Vec3& d, double dist) {
      Geometry g;
      g.n = d / dist;  // from i to j
      g.mstar = k.mi * k.mj / (k.mi + k.mj);
      g.li = (dist * dist + k.ri * k.ri - k.rj * k.rj) / (2.0 * dist);
      g.lj = dist - g.li;
      g.vrel = k.vi - k.vj + cross(g.li * k.wi + g.lj * k.wj, g.n);
      g.w_rel = k.wi - k.wj;
      return g;
    }

    PairForce respond(const JkrPair& jkr, double delta, const Geometry& g, ContactState& s, double dt) const {
      s.a = normal_.contact_radius(jkr, delta, s.a);
      return respond_at_radius(jkr, g, s, dt);
    }

    // Steps 2-4 with the contact radius s.a already updated.
    PairForce respond_at_radius(const JkrPair& jkr, const Geometry& g, ContactState& s, double dt) const {
      return respond_with(jkr, g, s, dt, normal_.force(jkr, s.a));
    }

    // Steps 2-4 with the contact radius s.a and the elastic normal force f_ne [N] already computed.
    [[gnu::always_inline]] PairForce respond_with(const JkrPair& jkr, const Geometry& g, ContactState& s, double dt,
                                                  double f_ne) const {
      PairForce out;
      ContactPoint c;
      c.n = g.n;
      c.a = s.a;
      c.f_ne = f_ne;
      c.eta_n = damping_.coefficient(g.mstar, normal_.stiffness(jkr, c.a));
      const double ddelta_dt = dot(g.vrel, c.n);
      c.vs = g.vrel - ddelta_dt * c.n;
      c.f_n = c.f_ne + c.eta_n * ddelta_dt;  // > 0 repulsive
      c.w_rel = g.w_rel;
      c.dt = dt;
      out.f_on_i = -c.f_n * c.n;
      const Vec3 ft = tangential_.force(c, jkr, s);
      add_moment(twisting_, c, jkr, s, out);
      add_moment(rolling_, c, jkr, s, out);
      out.f_on_i += ft;
      out.t_on_i += g.li * cross(c.n, ft);
      out.t_on_j += g.lj * cross(c.n, ft);
      return out;
    }

    template <class Resistance>
    static void add_moment(const Resistance& model, const ContactPoint& c, const JkrPair& jkr, ContactState& s,
                           PairForce& out) {
      if constexpr (!Inactive<Resistance>) {
        const Vec3 m = model.torque(c, jkr, s);
        out.t_on_i += m;
        out.t_on_j -= m;
      }
    }

    Normal normal_;
    Damping damping_;
    Tangential tangential_;
    Rolling rolling_;
    Twisting twisting_;
  };


  std::vector<Models> models_;
};

}  // namespace agglo::dem::contact
