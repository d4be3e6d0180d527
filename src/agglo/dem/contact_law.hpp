#pragma once
// The adhesive contact law of the DEM (docs/model.md §A.2): one normal, damping, tangential, rolling
// and twisting sub-model, chosen by name (src/agglo/dem/contact/; the names are listed by
// contact::names(category)). Selected once; evaluating all pairs costs one virtual call per step.
#include <memory>
#include <vector>

#include "agglo/dem/contact/contact_kernel.hpp"
#include "agglo/dem/contact/model_names.hpp"
#include "agglo/dem/contact_params.hpp"
#include "agglo/dem/material.hpp"

namespace agglo::dem {

class ContactLaw {
 public:
  // The models p.models names.
  explicit ContactLaw(const ContactParams& p);
  // Explicit names; throws ConfigError for unknown names or coefficients a model rejects.
  ContactLaw(const ContactParams& p, const contact::ModelNames& names);
  // One set of sub-models per material pair: pairs.table[k] for kind k (material.hpp).
  ContactLaw(const MaterialPairs& pairs, const contact::ModelNames& names);

  const contact::ModelNames& names() const { return names_; }

  void evaluate_pairs(std::vector<Pair>& pairs, const Particles& p, double dt, std::vector<PairForce>& out) const {
    kernel_->evaluate_pairs(pairs, p, dt, out);
  }
  // The same forces summed into p.f and p.t without a buffer (serial; contact_kernel.hpp).
  void accumulate_pairs(std::vector<Pair>& pairs, Particles& p, double dt) const {
    kernel_->accumulate_pairs(pairs, p, dt);
  }
  // The same sums on several threads (pair_blocks.hpp), bit for bit those of accumulate_pairs: phase 1 (part
  // `part` of `parts` of the crossing pairs) on every thread, a barrier, then phase 2 of each block
  // (contact_kernel.hpp; DemSystem::pair_phases).
  void crossing_forces(std::vector<Pair>& pairs, const Particles& p, double dt, const contact::PairBlocks& blocks,
                       std::size_t part, std::size_t parts, std::vector<PairForce>& crossing) const {
    kernel_->crossing_forces(pairs, p, dt, blocks, part, parts, crossing);
  }
  void block_forces(std::vector<Pair>& pairs, Particles& p, double dt, const contact::PairBlocks& blocks, std::size_t b,
                    const std::vector<PairForce>& crossing) const {
    kernel_->block_forces(pairs, p, dt, blocks, b, crossing);
  }
  // The fast path's law on one pair (ContactKernel::fast_pair; tests).
  PairForce fast_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt,
                      std::uint32_t kind = 0) const {
    return kernel_->fast_pair(jkr, k, s, dt, kind);
  }
  // One contact evaluation: updates `s` (formation, break, springs) and returns the forces.
  PairForce evaluate_pair(const JkrPair& jkr, const PairKinematics& k, ContactState& s, double dt,
                          std::uint32_t kind = 0) const {
    return kernel_->evaluate_pair(jkr, k, s, dt, kind);
  }
  // Every particle against wall `w` (wall.hpp): the same sub-models with an infinite partner.
  void evaluate_wall(const Wall& w, WallContacts& wc, const Particles& p, double dt, std::vector<PairForce>& out) const {
    kernel_->evaluate_wall(w, wc, p, dt, out);
  }
  // The same, added into p.f and p.t without the buffer (contact_kernel.hpp).
  void accumulate_wall(const Wall& w, WallContacts& wc, Particles& p, double dt) const {
    kernel_->accumulate_wall(w, wc, p, dt);
  }
  PairForce evaluate_wall_contact(const JkrPair& jkr, const WallKinematics& k, ContactState& s, double dt,
                                  std::uint32_t kind = 0) const {
    return kernel_->evaluate_wall_contact(jkr, k, s, dt, kind);
  }

 private:
  contact::ModelNames names_;
  std::shared_ptr<const contact::ContactKernel> kernel_;
};

}  // namespace agglo::dem
