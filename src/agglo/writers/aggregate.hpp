#pragma once
// Results of agglo aggregate (docs/outputs.md): aggregate.csv (one row per primary: x, y, z, radius [m],
// coordination, and charge [C], permittivity when the structure has them), aggregate.vtp (the spheres
// for ParaView: radius and coordination per point), result.json (N, abar, both R_g, the coordination
// distribution, the target and growth-fitted D_f and k_f) and results.nc (the table's variables and
// result.json's scalars).
#include <nlohmann/json.hpp>

#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/io/table.hpp"
#include "agglo/structure/observables.hpp"

namespace agglo::writers {

// The request the structure was built for (null D_f / k_f when not a fractal request).
struct AggregateTarget {
  std::string shape;
  std::optional<double> fractal_dimension, fractal_prefactor;
};

io::Table aggregate_table(const structure::Aggregate& a, const structure::Summary& s);
nlohmann::json aggregate_json(const structure::Summary& s, const AggregateTarget& target);
void write_aggregate(const OutputDir& out, const structure::Aggregate& a, const structure::Summary& s,
                     const nlohmann::json& result);
io::Dataset aggregate_dataset(const structure::Aggregate& a, const structure::Summary& s, const nlohmann::json& result);

}  // namespace agglo::writers
