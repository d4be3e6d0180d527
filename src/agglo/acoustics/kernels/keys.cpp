#include "agglo/acoustics/kernels/keys.hpp"

#include <fmt/format.h>

#include "agglo/acoustics/kernels/registry.hpp"
#include "agglo/core/settings_catalogue.hpp"

namespace agglo::acoustics {

namespace {
// The value of the deprecated brownian_form that selected the Fuchs form.
constexpr std::string_view kFuchsForm = "fuchs";
}  // namespace

KernelKeys::KernelKeys()
    : brownian{t,
               {"kernels.brownian", "", "Brownian term of the acoustic sum"},
               Brownian::name,
               &brownian_term_names,
               {.if_true = Brownian::name, .if_false = kNoMechanism}} {}

const KernelKeys& kernel_keys() {
  static const KernelKeys k;
  static const bool listed = settings::add_table(k.t, settings::acoustic_settings().domain.t);
  (void)listed;
  return k;
}

KernelSettings read_kernels(const ConfigSection& s) {
  const auto& k = kernel_keys();
  KernelSettings ks;
  ks.model = k.model.read(s);
  ks.orthokinetic = k.orthokinetic.read(s);
  ks.acoustic_wake = k.acoustic_wake.read(s);
  ks.radiation_pressure = k.radiation_pressure.read(s);
  ks.brownian = k.brownian.read(s);
  if (k.brownian_form.present(s)) {
    const bool fuchs = k.brownian_form.read(s) == kFuchsForm;
    s.warn(k.brownian_form.leaf(), fmt::format("deprecated: use {} = \"{}\" (the Fuchs form) or \"{}\"",
                                               k.brownian.dotted(), BrownianFuchs::name, Brownian::name));
    if (fuchs && ks.brownian == Brownian::name) ks.brownian = BrownianFuchs::name;
  }
  ks.collision_efficiency = k.collision_efficiency.read(s);
  ks.exclude_same_population = k.exclude_same_population.read(s);
  if (ks.model == ConstantKernel::name) ks.constant_coefficient = k.constant_coefficient.read(s);
  if (ks.model == AdditiveKernel::name) ks.additive_coefficient = k.additive_coefficient.read(s);
  return ks;
}

}  // namespace agglo::acoustics
