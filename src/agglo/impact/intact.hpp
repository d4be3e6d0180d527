#pragma once
// Intact for good: when an impact can no longer break the agglomerate, so that its run may stop early
// with the outcome of the full-length run (time.intact_stop, docs/model.md §A.3; the mirror of the
// early stop of a clearly broken run, impact_run.cpp). Energies of a JKR contact from contact_barrier.hpp
// (phi, x = a/a0; x_0: formation at delta = 0, x_b: the break point). Common condition:
//  1. the model conserves or dissipates energy and stores none tangentially: JKR normal contacts, damping
//     "alpha" or none, tangential "ruan_li" (friction, no spring), no rolling or twisting spring, no walls,
//     no gas drag (uniform gravity is allowed: it does not act on relative motion). Damping, friction and
//     the snap-off of a contact only remove energy; a contact forms at delta = 0 (phi(x_0)) and breaks
//     at x_b, so with the energy of a pair out of contact set to phi(x_0) the total energy E never rises.
// An other particle (the projectile) is "out of reach for good" when it touches nothing, is
// electrostatically invisible (uncharged, kappa_p = kappa_0), and it and the agglomerate (and every other
// such particle) recede: their centres of mass move ballistically relative to each other, so their
// distance D(t) never falls below D(0) when D . W >= 0 (W the relative velocity), and D(0) exceeds the sum
// of their extents (max |x_k - X| + r_k, plus 4 delta_C per contact for the deformations).
// Bound A (no electrostatics): the system S is the agglomerate, plus the other particles unless they are
// out of reach for good; n = |S| <= 12. At the instant a fragment appears, the contact breaking last is at
// x_b and every other active contact lies inside one of the two parts, each part of k spheres holding at
// most m(k) = min(k(k-1)/2, k K/2) contacts (K = 2 / (1 - cos theta), sin theta = r_min/(r_min + r_max),
// the kissing bound), each at least phi(1) - phi(x_0) = -0.607 F_C delta_C. So with
//   E_A = E_kin(S, centre-of-mass frame, spins) + sum_active [phi(x_c) - phi(x_0)] F_C delta_C
//         + max_k [m(k) + m(n - k)] max_pairs [phi(x_0) - phi(1)] F_C delta_C
// a break needs E_A >= B_A = min_pairs [phi(x_b) - phi(x_0)] F_C delta_C (0.935 F_C delta_C, Marshall).
// Bound B (with or without electrostatics; the other particles out of reach for good):
//  2. the agglomerate is a clique of active contacts: every pair touches, so all pair distances are fixed
//     up to the contact deformations, the shape is rigid, no contact can form among the primaries and a
//     fragment needs some contact stretched to x_b;
//  3. the electrostatic forces on the primaries are internal pair forces: the least-squares tensions G_c
//     along the contact lines (F_k = sum_c G_c e_c; normal equations, unique since a clique's contact
//     lines are independent, else not decided) reproduce them within 1e-3 of the largest. Over the
//     few delta_C a contact moves before it breaks they act as constant loads L_c (first order; the
//     gap of the electrostatic regularisation, g_min r, is an order of magnitude larger);
// then with psi_c, the loaded potential and B_c its barrier (contact_barrier.hpp),
//   E_B = E_kin(agglomerate, centre-of-mass frame, spins) - (1 - eps) L^T I^-1 L / 2
//         + sum_c [psi_c(x_c) - psi_c(x_min,c)] F_C,c delta_C,c
// (L the angular momentum, I the inertia tensor of the rigid clique: the rotation keeps that energy, up
// to the growth of I by the deformations, eps) and a break needs E_B >= B_B = min_c B_c F_C,c delta_C,c.
// The run stops when E <= kIntactMargin B for either bound. The margin 1/2 covers the integrator's
// energy error (velocity Verlet at T0/50: well under 1 % of the vibration energy), the second-order change
// of the electrostatic loads and the held electrostatic forces between solves. With no fragment possible
// and nothing left that can touch, the final classification equals the present one: not broken, not
// undecided, and the projectile (with B: out of reach) attached or not as it is now.
// Not decided (the run goes to full length): a charged agglomerate that is not a clique or still near its
// projectile, and any state whose free energy could still pay for a break, e.g. a hinged (floppy)
// tetrahedron that lost one contact and keeps a few F_C delta_C of motion (the near-critical intact runs
// of the seed cases): there the outcome is not certain from energy alone.
#include <cstddef>
#include <string>
#include <vector>

#include "agglo/core/vec3.hpp"
#include "agglo/dem/dem_system.hpp"

namespace agglo::impact {

inline constexpr double kIntactMargin = 0.5;

struct IntactBound {
  bool applies = false;  // the conditions of bound A or B hold
  std::string failed;    // the first condition that does not hold (empty when applies)
  double energy = 0.0;   // E_A or E_B [J]
  double barrier = 0.0;  // B_A or B_B [J]; infinite for a single primary (B)
  bool intact() const { return applies && energy <= kIntactMargin * barrier; }
};

// The criterion for the current state of `sys`, whose first n_agg particles are the agglomerate.
// `es_force`: the electrostatic force on every particle at this step [N] (null: no electrostatics),
// `kappa0`: the medium permittivity (electrostatic invisibility of the other particles).
IntactBound intact_bound(const dem::DemSystem& sys, std::size_t n_agg, const std::vector<Vec3>* es_force,
                         double kappa0);

}  // namespace agglo::impact
