#pragma once
// Files of agglo outcomes (docs/outcomes.md): outcomes.csv and results.nc from one io::Table over
// (speed, diameter_1, diameter_2): the grid's coordinates, P_stick, P_bounce, P_break with their 95 %
// Wilson intervals and the counts. results.nc is an outcome table of the DSMC
// (acoustics/outcome_table.hpp: outcomes.dry_model = "table", outcomes.table = ".../results.nc").
#include <string>

#include "agglo/impact/outcome_grid.hpp"
#include "agglo/io/dataset.hpp"
#include "agglo/io/output_dir.hpp"
#include "agglo/io/table.hpp"

namespace agglo::writers {

io::Table outcomes_table(const impact::OutcomeGridResult& r);
void write_outcomes(const OutputDir& out, const impact::OutcomeGridResult& r);
// `provenance`: one line naming the DEM case and the sampling (global attribute of the table).
io::Dataset outcomes_dataset(const impact::OutcomeGridResult& r, const std::string& provenance);

}  // namespace agglo::writers
