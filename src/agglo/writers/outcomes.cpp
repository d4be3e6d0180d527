#include "agglo/writers/outcomes.hpp"

#include <array>
#include <vector>

#include <fmt/format.h>

#include "agglo/acoustics/outcome_table.hpp"

namespace agglo::writers {

namespace {

using impact::OutcomeGridResult;

// P = k/n per node and the Wilson interval's ends, for the counts `k`.
struct Probabilities {
  std::vector<double> p, lo, hi;
};
Probabilities probabilities(const std::vector<std::int64_t>& k, const std::vector<std::int64_t>& n) {
  Probabilities out;
  for (std::size_t i = 0; i < k.size(); ++i) {
    out.p.push_back(n[i] > 0 ? static_cast<double>(k[i]) / static_cast<double>(n[i]) : 0.0);
    const auto w = impact::wilson_interval(k[i], n[i]);
    out.lo.push_back(w.lo);
    out.hi.push_back(w.hi);
  }
  return out;
}

// The grid's coordinate columns: speed and both sizes, then the charge and permittivity axes it has.
io::Table grid_columns(const OutcomeGridResult& r) {
  namespace ac = acoustics;
  const auto& ax = ac::kOutcomeAxes;
  const auto& g = r.spec;
  const std::size_t nd = g.diameters.size();
  std::vector<std::pair<std::string, std::size_t>> rows = {{ax[0], g.speeds.size()}, {ax[1], nd}, {ax[2], nd}};
  if (!g.charges.empty()) {
    rows.emplace_back(ax[ac::kCharge1Axis], g.charges.size());
    rows.emplace_back(ax[ac::kCharge2Axis], g.charges.size());
  }
  if (!g.permittivities.empty()) rows.emplace_back(ax[ac::kPermittivityAxis], g.permittivities.size());
  if (!g.primary_radii.empty()) {
    rows.emplace_back(ax[ac::kPrimaryRadius1Axis], g.primary_radii.size());
    rows.emplace_back(ax[ac::kPrimaryRadius2Axis], g.primary_radii.size());
  }
  io::Table t("outcomes.csv", rows, "{:.8g}");
  t.real(ax[0], ac::kOutcomeAxisUnits[0], ac::kOutcomeAxisMeanings[0], g.speeds).over({ax[0]});
  const bool agg = g.aggregates();
  t.real(ax[1], ac::kOutcomeAxisUnits[1],
         agg ? "volume-equivalent diameter 2 a N^(1/3) of the first aggregate (the target)"
             : "diameter of the first sphere (the target)",
         g.diameters)
      .over({ax[1]});
  t.real(ax[2], ac::kOutcomeAxisUnits[2],
         agg ? "volume-equivalent diameter 2 a N^(1/3) of the second aggregate (the projectile)"
             : "diameter of the second sphere (the projectile)",
         g.diameters)
      .over({ax[2]});
  for (std::size_t k = ac::kCharge1Axis; k <= ac::kPermittivityAxis; ++k) {
    const auto& values = k == ac::kPermittivityAxis ? g.permittivities : g.charges;
    if (!values.empty()) t.real(ax[k], ac::kOutcomeAxisUnits[k], ac::kOutcomeAxisMeanings[k], values).over({ax[k]});
  }
  for (std::size_t k = ac::kPrimaryRadius1Axis; k <= ac::kPrimaryRadius2Axis; ++k)
    if (!g.primary_radii.empty())
      t.real(ax[k], ac::kOutcomeAxisUnits[k], ac::kOutcomeAxisMeanings[k], g.primary_radii).over({ax[k]});
  return t;
}

// The fragment mass distribution (results.nc only): the bin edges and, per node and bin, h_b and mu_b.
void add_fragment_distribution(io::Table& t, const OutcomeGridResult& r) {
  namespace ac = acoustics;
  const auto& e = impact::kFragmentFractionEdges;
  t.add_dim(ac::kFragmentEdgeDim, e.size());
  t.add_dim(ac::kFragmentBinDim, e.size() - 1);
  t.real(ac::kFragmentEdges, "1", ac::kFragmentEdgesMeaning, {e.begin(), e.end()})
      .over({ac::kFragmentEdgeDim})
      .header({});
  std::vector<std::string> dims;
  for (const auto& c : t.columns())
    if (c.dims.size() == 1 && c.dims[0] == c.name && c.name != ac::kFragmentEdges) dims.push_back(c.name);
  dims.emplace_back(ac::kFragmentBinDim);
  t.real(ac::kFragmentDistribution[0], "1", ac::kFragmentDistributionMeanings[0], r.fragment_number).over(dims).header({});
  t.real(ac::kFragmentDistribution[1], "1", ac::kFragmentDistributionMeanings[1], r.fragment_mass).over(dims).header({});
}

}  // namespace

io::Table outcomes_table(const OutcomeGridResult& r) {
  const auto& pn = acoustics::kOutcomeProbabilities;
  io::Table t = grid_columns(r);
  const bool agg = r.spec.aggregates();
  const std::array<const std::vector<std::int64_t>*, 3> counts = {&r.sticks, &r.bounces, &r.breaks};
  const std::array<const char*, 3> what = {"sticks", "bounces", "breaks"};
  for (std::size_t k = 0; k < 3; ++k) {
    Probabilities p = probabilities(*counts[k], r.impacts);
    t.real(pn[k], "1", fmt::format("probability that the pair {}", what[k]), std::move(p.p));
    t.real(std::string(pn[k]) + "_lo", "1", fmt::format("lower end of the 95 % Wilson interval of {}", pn[k]),
           std::move(p.lo));
    t.real(std::string(pn[k]) + "_hi", "1", fmt::format("upper end of the 95 % Wilson interval of {}", pn[k]),
           std::move(p.hi));
  }
  if (agg) {  // over the node's breaks; NaN where none broke (acoustics/outcome_table.hpp reads them)
    const auto& fs = acoustics::kOutcomeFragmentStats;
    t.real(fs[0], "1", acoustics::kOutcomeFragmentMeanings[0], r.fragments);
    t.real(fs[1], "1", acoustics::kOutcomeFragmentMeanings[1], r.largest_fraction);
  }
  if (!r.fragment_number.empty()) add_fragment_distribution(t, r);
  t.integer("impacts", "1", "DEM impacts at the node", r.impacts);
  const std::array<const char*, 3> past = {"stuck", "bounced", "broke"};
  for (std::size_t k = 0; k < 3; ++k)
    t.integer(what[k], "1", fmt::format("impacts at the node that {}", past[k]), *counts[k]);
  return t;
}

void write_outcomes(const OutputDir& out, const OutcomeGridResult& r) { io::write_csv(out, outcomes_table(r)); }

io::Dataset outcomes_dataset(const OutcomeGridResult& r, const std::string& provenance) {
  io::Dataset d;
  outcomes_table(r).add_to(d);
  d.attributes["provenance"] = provenance;
  return d;
}

}  // namespace agglo::writers
