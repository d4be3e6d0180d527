#pragma once
// Collision outcomes (docs/model.md §C.5; Zhao et al. 2023, section 2.4, eqs. 13-14, 22-24).
//  - any pair with a pure droplet: coalescence;
//  - solid-solid ("dry"): coalesce iff |G.n| <= v_cr,dry (Sgrott & Sommerfeld 2019, eq. 13)
//      v_cr,dry = A sqrt(1-e^2) / (pi d_min z0^2 e^2 sqrt(6 p_c rho_min (1 + d_min/d_max)));
//  - solid-mixed, mixed-mixed ("wet"): coalesce iff |G.n| <= v_cr,wet (Ennis 1991, eq. 14)
//      v_cr,wet = 9 mu_l (d_i+d_j) / (8 rho_s d_i d_j) (1 + 1/e) ln(delta/h_a);
//  - with outcomes.dry_model / outcomes.wet_model = "table": stick, bounce or break of that pair type drawn
//    from its outcome table (outcome_table.hpp, cell_events.hpp) instead of the critical velocity;
//  - otherwise hard-sphere rebound with friction (eqs. 22-23); wet pairs use
//      e_wet = e - 9 mu_l (d_i+d_j)(1+e) ln(delta/h_a) / (8 rho_s d_i d_j |G.n|)   (eq. 24).
// G = v_i - v_j, n = unit vector from i to j at contact (approaching: G.n > 0).
#include <array>
#include <memory>
#include <vector>

#include "agglo/acoustics/outcome_table.hpp"
#include "agglo/core/settings_acoustic.hpp"
#include "agglo/core/vec3.hpp"

namespace agglo::acoustics {

inline const settings::AcousticSettings::Outcomes& outcome_keys() { return settings::acoustic_settings().outcomes; }

enum class PairType { droplet, dry, wet };
inline constexpr std::array<const char*, 3> kPairTypeNames = {"droplet", "dry", "wet"};  // by PairType

// An outcome model of dry pairs (outcomes.dry_model) or wet pairs (outcomes.wet_model): the pair type's
// closed-form critical velocity (default) or a table (outcome_table.hpp, one format for both).
enum class OutcomeModel { critical_velocity, table };

// Defaults are the declared [outcomes] settings (agglo/core/settings_acoustic.hpp).
struct OutcomeParams {
  bool always_coalesce = outcome_keys().always_coalesce.def();     // test kernels: every collision coalesces
  double hamaker = outcome_keys().hamaker.def();                   // A [J]
  double z0 = outcome_keys().contact_distance.def();               // minimum contact distance [m]
  double contact_pressure = outcome_keys().contact_pressure.def(); // p_c [Pa]
  double restitution = outcome_keys().restitution.def();           // e
  double friction = outcome_keys().friction.def();                 // f_p
  double liquid_viscosity = outcome_keys().liquid_viscosity.def(); // mu_l [Pa s]
  double film_ratio = outcome_keys().film_roughness_ratio.def();   // delta / h_a
  double solid_density = outcome_keys().solid_density.def();       // rho_s in eqs. 14, 24 [kg/m^3]
  bool energy_compensation = outcome_keys().energy_compensation.def();  // Zhao et al. 2023, eq. 30
  OutcomeModel dry_model = OutcomeModel::critical_velocity;
  std::shared_ptr<const OutcomeTable> dry_table;  // set when dry_model == table
  OutcomeModel wet_model = OutcomeModel::critical_velocity;
  std::shared_ptr<const OutcomeTable> wet_table;  // set when wet_model == table
  // kappa_p by population, when a table (dry or wet) has a permittivity axis (else empty): a pair is looked up at
  // the mean of its two samples' populations' kappa_p (docs/acoustics.md §1.7).
  std::vector<double> permittivities;
};

double critical_velocity_dry(const OutcomeParams& o, double di, double dj, double rhoi, double rhoj);
double critical_velocity_wet(const OutcomeParams& o, double di, double dj);
double wet_restitution(const OutcomeParams& o, double di, double dj, double gn);

// Post-collision velocities of an equal-weight hard-sphere pair (eqs. 22-23), masses mi, mj,
// restitution e, friction f. n must be a unit vector with G.n > 0.
void hard_sphere_rebound(const Vec3& vi, const Vec3& vj, double mi, double mj, const Vec3& n, double e, double f,
                         Vec3& vi_out, Vec3& vj_out);

}  // namespace agglo::acoustics
