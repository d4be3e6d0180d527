#pragma once
// Weighted samples of the DSMC (structure of arrays; DEM particles are dem/particles.hpp). Sample i
// stands for w_i real particles (integer-valued weight stored as double) that share position,
// velocity, solid volume, liquid volume and mass. Diameter and density follow from them (Zhao et al. 2023, eqs. 15-16):
//   d = (6 (V_s + V_l) / pi)^(1/3),  rho = m / (V_s + V_l).
// Phase (docs/model.md §C.5): solid (V_l = 0), liquid (V_s = 0), mixed (both > 0).
// Derived per-sample quantities used by motion and kernels are cached and refreshed by
// `refresh(i, ...)` after every change of size or mass.
// Aggregate structure (structure.hpp): when some population is fractal (structure_laws not empty) every
// sample also carries its primary count n_p and primary radius r_p, and the caches hold the collision
// diameter d = 2 R_c and the mobility diameter d_m = 2 R_m (tau, C_c, Re from d_m); otherwise (compact
// runs) those three arrays stay empty, d = d_m is the volume-equivalent diameter and nothing else changes.
#include <cstdint>
#include <vector>

#include "agglo/acoustics/gas.hpp"
#include "agglo/acoustics/sound.hpp"
#include "agglo/acoustics/structure.hpp"

namespace agglo::acoustics {

enum class Phase : std::uint8_t { solid = 0, liquid = 1, mixed = 2 };
const char* phase_name(Phase p);

struct SampleSet {
  // State.
  std::vector<double> x, y, z;        // position [m]
  std::vector<double> vx, vy, vz;     // velocity [m/s]
  std::vector<double> vol_s, vol_l;   // solid / liquid volume of one real particle [m^3]
  std::vector<double> mass;           // mass of one real particle [kg]
  std::vector<double> w;              // number weight (integer valued)
  std::vector<double> debt;           // kinetic energy owed by split-merge (Zhao et al. 2023, eq. 29) [J]
  std::vector<double> debt_ref;       // w m of the particle that incurred the debt [kg] (Zhao et al. 2023, eq. 30)
  std::vector<int> pop;               // population of origin (largest volume wins on merging)
  std::vector<std::uint64_t> id;      // stable id
  // Aggregate structure (empty unless structure_laws is set): primary count n_p (real-valued, V_s / v_p;
  // 0 for a droplet), primary radius r_p [m], and the derived mobility diameter d_m [m].
  std::vector<double> np, rp, dm;
  std::vector<StructureLaw> structure_laws;  // by population; empty: every sample compact
  // Charge (docs/acoustics.md §1.7, charged outcome tables): when some population declares a charge
  // (carries_charge, set by the case before sampling) every sample carries the charge q of one real
  // particle [C]; merging sums it (q_i + q_j), a broken pair's fragments share it in proportion to mass.
  // Otherwise q stays empty and nothing else changes. Charge enters only the outcome table's lookup, at the
  // sample's surface charge density q / (pi d_v^2).
  bool carries_charge = false;
  std::vector<double> q;
  // Derived caches.
  std::vector<double> d, rho;         // (collision) diameter [m], density m / (V_s + V_l) [kg/m^3]
  std::vector<double> cc;             // Cunningham slip correction
  std::vector<double> tau;            // Stokes relaxation time with slip, C_I = 1 [s]
  std::vector<double> slip_l;         // slip coefficient l = w tau / sqrt(1 + (w tau)^2)
  std::vector<double> cphi, sphi;     // cos/sin of phase lag phi = atan(w tau)
  std::vector<double> phase_code;     // Phase as double (0 solid, 1 liquid, 2 mixed) for SIMD-free lookups
  std::vector<double> dl;             // d l [m] (kernel majorant, CellBounds)
  std::vector<double> ccd;            // C_c / d [1/m] (kernel majorant, CellBounds)
  std::vector<double> acc_z;          // -g (rho - rho_g) / rho [m/s^2]: gravity + buoyancy per unit tau (motion)
  // Wave-phase cache of the exact integrator (drag.cpp): sin, cos(k x_ref) at x_ref (NaN = empty).
  // sin(k x) is obtained from it by a small rotation k (x - x_ref) while |k (x - x_ref)| is small.
  std::vector<double> x_ref, skx, ckx;

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n);
  void reserve(std::size_t n);
  // Append one sample; returns its index (caches refreshed).
  std::size_t add(double x, double y, double z, double vol_s, double vol_l, double mass, double w, int pop,
                  const Gas& gas, const Sound& sound);
  Phase phase(std::size_t i) const { return static_cast<Phase>(static_cast<int>(phase_code[i])); }
  void refresh(std::size_t i, const Gas& gas, const Sound& sound);
  // The derived caches of `to` from those of `from` (both with the same volumes and mass).
  void copy_derived(std::size_t from, std::size_t to);
  void copy_sample(std::size_t from, std::size_t to);
  // Reorders the samples: new sample k = old sample order[k] (memory locality of cells). With parts > 1,
  // only the per-sample arrays j with j % parts == part (the arrays shared out between the threads of a
  // team, engine.cpp; every part of 0..parts-1 once gives the whole permutation).
  void permute(const std::vector<std::uint32_t>& order, int part = 0, int parts = 1);
  double volume(std::size_t i) const { return vol_s[i] + vol_l[i]; }

  bool structured() const { return !structure_laws.empty(); }
  // Volume-equivalent diameter d_v = (6 V / pi)^(1/3) [m] (= d in compact runs).
  double volume_diameter(std::size_t i) const;
  // The diameters the drag uses (d_m; d in compact runs).
  const std::vector<double>& mobility_diameters() const { return structured() ? dm : d; }
  // The primary radius of sample i for an outcome table over primary radii [m]: r_p of an aggregate
  // sample (n_p > 0), else d_v / 2 (a compact sphere is one primary).
  double query_primary_radius(std::size_t i) const {
    return structured() && np[i] > 0.0 ? rp[i] : 0.5 * volume_diameter(i);
  }
  // Sample i (of a fractal population) becomes an aggregate of primaries of radius r [m] holding its solid
  // volume (n_p = V_s / ((4/3) pi r^3)); caches refreshed.
  void set_primaries(std::size_t i, double r, const Gas& gas, const Sound& sound);

 private:
  void refresh_structured(std::size_t i, const Gas& gas, const Sound& sound);
  // The optional per-sample arrays: aggregate structure, charge.
  template <class F>
  void each_structure_array(F&& f) {
    if (structured())
      for (auto* v : {&np, &rp, &dm}) f(*v);
    if (carries_charge) f(q);
  }
};


}  // namespace agglo::acoustics
