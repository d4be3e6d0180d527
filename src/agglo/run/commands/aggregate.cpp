// agglo aggregate: builds (or reads) the structure of [agglomerate] shape = fractal, bpca, bcca or file and
// writes it with its observables (writers/aggregate.hpp; docs/model.md, structure builder).
#include <fmt/format.h>

#include "agglo/core/settings_impact.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/impact/structure_target.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/structure/validate.hpp"
#include "agglo/writers/aggregate.hpp"

namespace agglo::run {

namespace {

class Aggregate final : public Command {
 public:
  std::string_view name() const override { return "aggregate"; }
  std::string_view help() const override {
    return "Build a fractal, BPCA or BCCA aggregate (or read one): CSV, VTK, R_g, coordination, D_f";
  }

  void parse(Config& cfg) const override {
    (void)spec(cfg);
    cfg.check_unknown_keys();
  }
  long long seed(const Config& cfg) const override {
    Config probe = cfg.clone();
    const auto& ka = settings::impact_settings().agglomerate;
    return ka.seed.read(ka.t.open(probe.root()));
  }
  const settings::Setting* seed_key() const override { return &settings::impact_settings().agglomerate.seed; }

  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    const impact::AgglomerateSpec a = spec(cfg).agglomerate;
    const auto contacts = structure::validate_structure(a.structure, "shape");
    const structure::Summary s = structure::summarize(a.structure, contacts, a.shape != "file");
    writers::AggregateTarget target{a.shape, std::nullopt, std::nullopt};
    if (a.shape == "fractal") target.fractal_dimension = a.fractal_dimension, target.fractal_prefactor = a.fractal_prefactor;
    CommandResult r;
    r.summary = writers::aggregate_json(s, target);
    r.seed = a.shape == "file" ? 0 : a.seed;
    if (ctx.formats.csv) writers::write_aggregate(out, a.structure, s, r.summary);
    r.data = std::make_shared<const io::Dataset>(writers::aggregate_dataset(a.structure, s, r.summary));
    ctx.report().info(fmt::format("{} aggregate: N = {}, R_g = {:.6g} m (point mass), {:.6g} m (spheres), mean "
                                  "coordination {:.3g}; outputs in {}",
                                  a.shape, s.primaries, s.rg_point_mass, s.rg_spheres, s.mean_coordination,
                                  out.path().string()));
    return r;
  }

 private:
  // [agglomerate] and the top level, the structure built and checked; with materials in the case
  // (impact::parse_aggregate_case), each primary's material name and density in the structure.
  static impact::ImpactCase spec(Config& cfg) {
    const auto& keys = settings::impact_settings();
    bool materials = false;
    impact::ImpactCase c = impact::parse_aggregate_case(cfg, materials);
    auto& a = c.agglomerate;
    if (!impact::is_structure_shape(a.shape))
      keys.agglomerate.shape.reject(keys.agglomerate.t.open(cfg.root()),
                                    "agglo aggregate builds shape = \"fractal\", \"bpca\", \"bcca\" or \"file\"");
    if (!materials) return c;
    auto& s = a.structure;
    s.material.assign(s.size(), {});
    s.density.assign(s.size(), 0.0);
    for (std::size_t k = 0; k < s.size(); ++k) {
      s.material[k] = impact::material_name(c, a.material_of(k));
      s.density[k] = impact::material_density(c, a.material_of(k));
    }
    return c;
  }
};

}  // namespace

const Command& aggregate_command() {
  static const Aggregate c;
  return c;
}

}  // namespace agglo::run
