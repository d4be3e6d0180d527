#pragma once
// The selected contact law as the DEM engine calls it: one virtual call per step evaluates every
// listed pair (the loop itself is compiled for the chosen sub-models, see pair_kernel.hpp).
#include <cstdint>
#include <vector>

#include "agglo/dem/contact/pair_blocks.hpp"
#include "agglo/dem/contact/pair_state.hpp"
#include "agglo/dem/jkr.hpp"
#include "agglo/dem/neighbor_list.hpp"
#include "agglo/dem/particles.hpp"
#include "agglo/dem/wall.hpp"

namespace agglo::dem::contact {

class ContactKernel {
 public:
  virtual ~ContactKernel() = default;
  // Forces of every pair into out[k] (resized to pairs.size()); updates the pair states.
  virtual void evaluate_pairs(std::vector<Pair>& pairs, const Particles& p, double dt,
                              std::vector<PairForce>& out) const = 0;
  // The same forces added straight into p.f and p.t (zeroed first), serially in pair order: pair k's
  // force goes to i (+) and j (-) as k grows, the order in which the per-pair buffer is gathered, so
  // the sums are bit for bit those of evaluate_pairs + gather (DemSystem), without the buffer.
  virtual void accumulate_pairs(std::vector<Pair>& pairs, Particles& p, double dt) const = 0;
  // The same sums on blocks (pair_blocks.hpp), in two phases with a barrier between them, bit for bit those
  // of accumulate_pairs (ContactLaw::accumulate_pairs_in_blocks, DemSystem::step). Phase 1: the forces of part
  // `part` of `parts` equal parts of blocks.crossing into crossing[k] (sized pairs.size(); updates those pairs'
  // states; reads no force or torque).
  virtual void crossing_forces(std::vector<Pair>& pairs, const Particles& p, double dt, const PairBlocks& blocks,
                               std::size_t part, std::size_t parts, std::vector<PairForce>& crossing) const = 0;
  // Phase 2, block b: its particles' forces and torques zeroed, the incoming crossing forces added, then its own
  // pairs in order (a crossing pair's buffered force to its i only); touches only block b's particles and pairs.
  virtual void block_forces(std::vector<Pair>& pairs, Particles& p, double dt, const PairBlocks& blocks, std::size_t b,
                            const std::vector<PairForce>& crossing) const = 0;
  // One pair of material pair `kind` by the fast path's law, one pair at a time (tests: the lanes of
  // accumulate_pairs, block_forces and crossing_forces give its bits).
  virtual PairForce fast_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt,
                              std::uint32_t kind) const = 0;
  // One pair of material pair `kind` (tests and diagnostics; a virtual call per pair).
  virtual PairForce evaluate_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt,
                                  std::uint32_t kind) const = 0;
  // Forces of every particle against wall `w` into out[k] (resized to p.size()); updates wc.state.
  virtual void evaluate_wall(const Wall& w, WallContacts& wc, const Particles& p, double dt,
                             std::vector<PairForce>& out) const = 0;
  // The same forces and torques added straight into p.f and p.t, for the spheres in contact only (adding the
  // others' zero forces changes no bit: a sum that starts at +0 and only adds is never -0): no buffer and no
  // pass over it (the fast path; the reference twin keeps evaluate_wall and its buffer).
  virtual void accumulate_wall(const Wall& w, WallContacts& wc, Particles& p, double dt) const = 0;
  // One sphere against a wall, material pair `kind` (tests).
  virtual PairForce evaluate_wall_contact(const JkrPair& jkr, const WallKinematics& k, ContactState& s, double dt,
                                          std::uint32_t kind) const = 0;
};

}  // namespace agglo::dem::contact
