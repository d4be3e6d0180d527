#pragma once
// DEM engine: particles + adhesive contacts + optional non-contact forces, advanced by the
// velocity-Verlet scheme (kick-drift-kick, symplectic for conservative forces; velocity-dependent
// contact forces use the half-step velocity). Pair forces are summed per particle in the order of the
// pair list on any number of threads (blocks of pairs, contact/pair_blocks.hpp): results do not depend
// on the thread count. On several threads a step is one parallel region (parallel_step).
#include <memory>
#include <vector>

#include "agglo/dem/contact_law.hpp"
#include "agglo/dem/contact_params.hpp"
#include "agglo/dem/dem_state.hpp"
#include "agglo/dem/external_force.hpp"
#include "agglo/dem/gas_drag.hpp"
#include "agglo/dem/kick_drift.hpp"
#include "agglo/dem/material.hpp"
#include "agglo/dem/neighbor_list.hpp"
#include "agglo/dem/particles.hpp"
#include "agglo/dem/wall.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/thread_choice.hpp"

namespace agglo::dem {

// A blown-up DEM state (non-finite values, a particle crossing its radius in one step, an energy
// rise): a NumericalError (exit code 3) that callers may extend with the likely input cause.
struct DemInstability : NumericalError {
  using NumericalError::NumericalError;
};

// Largest time step accepted, as a fraction of the reference contact period T0: dt <= T0 / 10, the
// coarsest step allowed by time.steps_per_period. Above it a contact is resolved by too few steps
// and velocity Verlet pumps energy into it.
inline constexpr double kMaxDtOverPeriod = 0.1;

struct DemParams {
  ContactParams contact;    // [contact] options and the default material (id 0)
  std::vector<Material> materials;  // named materials, ids 1, 2, ... (material.hpp)
  double dt = 0.0;          // time step [s]; <= 0: T0 / steps_per_period (see reference_period)
  double steps_per_period = 50.0;
  double skin = 0.0;        // neighbour skin [m]; <= 0: 0.1 * smallest radius
  std::vector<Wall> walls;  // flat walls (wall.hpp)
  GasDrag gas;              // drag of the surrounding gas (gas_drag.hpp)
  Vec3 gravity;             // uniform acceleration g [m/s^2]
};

class DemSystem {
 public:
  // Contact sub-models as named by params.contact.models, or explicitly by `models`.
  DemSystem(Particles particles, DemParams params);
  DemSystem(Particles particles, DemParams params, const contact::ModelNames& models);

  void set_external_force(ExternalForce* ext) {
    ext_ = ext;
    forces_ready_ = false;
  }
  // Adds a particle (largest index); existing contacts keep their state.
  void add_particle(const Vec3& x, double radius, double density, const Vec3& v, double charge, double kappa,
                    std::uint32_t material = 0) {
    p_.add(x, radius, density, v, charge, kappa, material);
    attach();
    forces_ready_ = false;
  }
  // The reference twin of the pair step (tests, bench/bench_dem_scaling.cpp): every pair force into a
  // per-pair buffer, then gathered per particle (today's kernel, also the parallel path). Off (the
  // default): on one thread the forces go straight to the particles; the results are the same.
  void set_reference_kernel(bool on) { reference_ = on; }
  bool reference_kernel() const { return reference_; }

  // One step. With more than kParallelThreshold pairs and several OpenMP threads, the step's thread count (all
  // or one) is chosen by timed probes (core/thread_choice.hpp): the bits are those of any count, the wall time
  // that of the faster one on this machine at this time.
  void step();
  void run(long nsteps) {
    for (long s = 0; s < nsteps; ++s) step();
  }

  double dt() const { return dt_; }
  double time() const { return time_; }
  long steps() const { return step_; }
  const DemParams& params() const { return params_; }
  const ContactLaw& contact_law() const { return law_; }
  const MaterialPairs& material_pairs() const { return mats_; }
  const Particles& particles() const { return p_; }
  Particles& particles() { return p_; }
  const std::vector<Pair>& pairs() const { return nl_.pairs(); }
  const NeighborList& neighbors() const { return nl_; }
  const ThreadChoice& thread_choice() const { return threads_; }

  // Diagnostics.
  double kinetic_energy() const;                // translational + rotational [J]
  double translational_kinetic_energy() const;  // [J]
  int active_contacts() const;  // between particles
  int wall_contacts() const;    // of particles with the walls
  // Contact states of every particle with wall k of params().walls.
  const WallContacts& wall_contacts(std::size_t k) const { return walls_[k]; }
  std::vector<int> contacts_per_particle() const;
  double external_energy() const { return ext_ ? ext_->energy() : 0.0; }
  Vec3 momentum() const;
  Vec3 angular_momentum() const;  // about the origin, spin included

  // Throws DemInstability naming step and particle if a position or velocity is not finite or a
  // particle moves more than its radius per step. step() calls it every 256 steps; callers call it
  // before they record or classify a state.
  void check_state() const;

  // Compute forces for the current state without advancing (first call of step() does it). rebuild:
  // -1 tests whether the neighbour list needs a rebuild, 0 / 1 is that test's answer already known (step()
  // takes it in its parallel drift loop; the reference twin tests here, serially).
  void compute_forces(int rebuild = -1);
  JkrPair jkr_for(std::uint32_t i, std::uint32_t j) const;
  // JKR constants of particle i against `w` (R* = r_i, E* of the wall's material; wall.hpp).
  JkrPair wall_jkr(std::uint32_t i, const Wall& w) const;

  // The complete state between two steps (dem_state.hpp) and its restoration into a system built
  // from the same case (same contact law and external force object); defined in dem_state.cpp.
  DemState state() const;
  void restore(const DemState& s);

 private:
  void attach();  // wall contact slots, drag constants and kick factors of particles added since the last call
  void add_wall_and_body_forces();
  VerletArrays verlet_arrays(bool tracked);  // for kick_drift.hpp (tracked: with the rebuild test)
  void closing_kick();
  static constexpr std::int64_t kVerletChunk = 1024;  // particles per range of the kick and drift loops
  void gather_pair_forces();  // the reference path: per-pair buffer, then a gather per particle
  void accumulate_in_blocks();  // the parallel path: the fast path's sums on blocks of pairs
  void rebuild_list();          // the neighbour list built again (pair kinds and JKR constants of new pairs)
  void ensure_blocks();         // blocks_ (and the crossing buffer) for the current list and thread count
  void pair_phases();           // inside a parallel region: the two phases of the blocks on this thread
  bool parallel_step_applies() const;
  void parallel_step();  // step() as one parallel region (no external force)
  void advance();        // step() without the choice of the thread count and the state check

  Particles p_;
  DemParams params_;
  MaterialPairs mats_;  // pair values of the materials (before law_, which is built from them)
  ContactLaw law_;
  NeighborList nl_;
  ExternalForce* ext_ = nullptr;
  std::vector<PairForce> pair_forces_;
  std::vector<WallContacts> walls_;     // one per params_.walls
  std::vector<PairForce> wall_forces_;  // per particle, of the wall being evaluated
  std::vector<double> decay_, lag_;     // gas drag per particle: E = exp(-dt/(2 tau)), tau (1 - E)
  // Half-kick factors per particle, (dt/2)/m and (dt/2)/I: the same doubles as the division in the kick,
  // computed once (attach(); the masses and dt do not change between steps).
  std::vector<double> kick_v_, kick_w_;
  double dt_ = 0.0, skin_ = 0.0, time_ = 0.0;
  long step_ = 0;
  bool forces_ready_ = false;
  bool reference_ = false;
  // Per thread of parallel_step: whether one of its particles moved beyond half the skin (a cache line each).
  struct alignas(64) ThreadFlag {
    bool far = false;
  };
  std::vector<ThreadFlag> far_;
  ThreadChoice threads_;        // thread count of the steps (wall time only)
  contact::PairBlocks blocks_;  // of the parallel path, for the list of build blocks_builds_ (-1: none)
  long blocks_builds_ = -1;
  std::size_t blocks_pairs_ = 0;
};

// Reference contact period T0 = 2 pi sqrt(m*/k0), k0 = 0.9905 F_C/delta_C, for the smallest pair, every
// particle of the one material c (its material id ignored).
double reference_period(const Particles& p, const ContactParams& c);
// The same with the materials of d (pairs of the three lightest particles and of the lightest of
// each material) and the sphere-wall contacts of the lightest particles (m* = m, R* = r, wall E*).
double reference_period(const Particles& p, const DemParams& d);

}  // namespace agglo::dem
