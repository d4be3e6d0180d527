#include "agglo/sectional/case_config.hpp"

#include <fmt/format.h>

#include "agglo/acoustics/kernels/keys.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::sectional {

namespace {
const settings::AcousticSettings& keys() { return settings::acoustic_settings(); }

SectionalSettings parse_grid(const ConfigSection& root) {
  const auto& k = keys().sectional;
  const ConfigSection s = k.t.open(root);
  SectionalSettings g;
  g.bins_per_decade = static_cast<int>(k.bins_per_decade.read(s));
  g.d_min = k.d_min.read(s);
  g.d_max = k.d_max.read(s);
  g.tolerance = k.tolerance.read(s);
  if (g.d_max <= g.d_min) k.d_max.reject(s, fmt::format("must exceed {}", k.d_min.dotted()));
  return g;
}

// The limits of the solver (header), each reported against its key.
void check_supported(const ConfigSection& root, const acoustics::EngineSettings& e) {
  const auto& K = keys();
  const auto& KK = acoustics::kernel_keys();
  const ConfigSection kern = KK.t.open(root);
  if (e.kernel.model == acoustics::kAcousticModel)
    KK.model.reject(kern, "the sectional solver needs a kernel of the sizes only: one mechanism alone");
  if (e.kernel.exclude_same_population)
    KK.exclude_same_population.reject(kern, "the sectional solver has one component: must be false");
  if (!e.outcomes.always_coalesce)
    K.outcomes.always_coalesce.reject(K.outcomes.t.open(root), "the sectional solver merges on every collision: "
                                                               "must be true");
  const auto pops = K.population.t.elements(root);
  for (std::size_t i = 0; i < e.populations.size() && i < pops.size(); ++i)
    if (e.populations[i].structure.fractal)
      K.population.structure.reject(pops[i], "the sectional solver has compact spheres only");
  for (std::size_t i = 1; i < e.populations.size(); ++i) {
    if (e.populations[i].phase != e.populations[0].phase)
      K.population.phase.reject(pops[i], "the sectional solver has one component: every population the same phase");
    if (e.populations[i].density != e.populations[0].density)
      K.population.density.reject(pops[i], "the sectional solver has one component: every population the same "
                                           "density");
  }
}
}  // namespace

SectionalCase parse_sectional_case(Config& cfg) {
  SectionalCase c;
  ConfigSection root = cfg.root();
  c.grid = parse_grid(root);  // read first: parse_acoustic_case rejects keys nobody has read
  c.base = acoustics::parse_acoustic_case(cfg);
  check_supported(root, c.base.engine);
  return c;
}

}  // namespace agglo::sectional
