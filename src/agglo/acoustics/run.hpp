#pragma once
// One acoustic DSMC run, from a validated case to its observations (docs/model.md §C.6). The run
// never prints or writes files: warnings go to a callback, and writers/acoustic.hpp writes
//   efficiency.csv  t, concentrations by phase, fine efficiency, pure-droplet fraction, volume
//                   fractions (conservation), guard counters, PM1/PM2.5/PM10 mass (diagnostics.hpp)
//                   and their reductions
//   outcomes_by_pair.csv  collisions that stuck, bounced and broke by pair type over the run
//   psd.csv         dN/dlog10 d by phase at output.psd_times
//   snapshots.csv   samples with x <= snapshot_x_fraction * L_x at output.snapshot_times
//   summary.json    final efficiency and the other scalars below
//   run.log         derived parameters, sampling, Nanbu guard statistics
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "agglo/acoustics/case_config.hpp"
#include "agglo/acoustics/diagnostics.hpp"

namespace agglo::io {
class CheckpointReader;
}

namespace agglo::acoustics {

struct EfficiencyRow {
  double t = 0.0;                 // [s]
  Counts counts;                  // concentrations [1/m^3], volume fractions
  double fine_efficiency = 0.0;
  double pure_droplet_fraction = 0.0;
  std::uint64_t collisions = 0, subcycled = 0;
  PmMass pm;                      // PM mass concentrations [kg/m^3] (DSMC; the sectional run leaves 0)
  double largest_collision_diameter = 0.0;  // [m] max of the samples' collision diameters d (DSMC; else 0)
};

// The DSMC's cells assume particles much smaller than the cell (docs/acoustics.md §1.8 "Cell size"): a run
// whose largest collision diameter (the fractal one of aggregate samples) exceeds this fraction of the
// smallest cell edge at some efficiency row is reported (run.log warning and the run's warnings); the
// parse-time check refuses a start with a diameter >= the edge.
inline constexpr double kCellDiameterFraction = 0.1;

struct PsdRecord {
  double t = 0.0;                              // [s]
  std::array<std::vector<double>, 4> dndlogd;  // by phase (solid, liquid, mixed) and total [1/m^3]
};

struct SnapshotRow {
  double t, x, y, z, d, vol_s, vol_l, w;  // [s], [m], [m], [m], [m], [m^3], [m^3], weight
  std::uint64_t id;
  Phase phase;
};

struct AcousticObservations {
  std::vector<EfficiencyRow> efficiency;
  PsdBins bins;
  std::vector<PsdRecord> psd;
  std::vector<SnapshotRow> snapshots;
  Counts initial, final;
  double last_time_with_pure_droplets = -1.0;  // [s]
  std::size_t samples = 0;
  std::uint64_t steps = 0;
  double u_amp = 0.0;                          // [m/s]
  CollisionStats stats;
  Selection selection = Selection::nanbu;
  bool dry_table = false;                      // outcomes.dry_model = "table": its counters are reported
  bool coulomb_launch = false;                 // ... with charged samples and a launch gap (coulomb_launch.hpp)
  bool wet_table = false;                      // outcomes.wet_model = "table": its counters are reported
  bool wet_coulomb_launch = false;             // ... with charged samples and a launch gap
  bool dsmc = false;                           // a DSMC run: PM columns and outcomes by pair type are written
  double min_cell_edge = 0.0;                  // [m] smallest cell edge of the domain (DSMC)
  std::string log;                             // run.log without its last line (see io)
  double wall_time_s = 0.0;
  std::string interrupted;                     // non-empty: cancelled there; the rows so far are kept
};

struct RunHooks {
  std::function<void(double fraction, double sim_time_s)> progress;  // may be empty
  std::function<void(const std::string&)> warning;                   // may be empty
  std::function<bool()> cancelled;                                    // may be empty; true stops the run
  // Checkpoints (checkpoint.hpp, docs/restart.md): `checkpoint` receives the step, the simulated time [s]
  // and the payload each time the simulated time crosses a multiple of checkpoint_interval [s], when the
  // run is cancelled (before it returns) and at its end. None when empty or the interval is 0.
  double checkpoint_interval = 0.0;
  std::function<void(std::uint64_t step, double t, const std::string& payload)> checkpoint;
  // false: no payload at the end of a run that was not cancelled (the caller would discard it; its
  // serialisation doubled the peak memory of a large run, docs/scaling.md).
  bool checkpoint_at_end = true;
  // Continue from this payload (io::read_checkpoint) instead of t = 0; null = from the start.
  io::CheckpointReader* resume = nullptr;
};

// Runs the case; throws ConfigError for start-up conditions the settings cannot meet (explicit
// stability, Nanbu bound), NumericalError on a blow-up. When cancelled it stops and returns the
// observations so far with `interrupted` saying where (the caller flushes them, marked incomplete).
AcousticObservations run_acoustic(const AcousticCase& c, const RunHooks& hooks = {});

// Start-up checks that need the sampled state (explicit stability, Nanbu bound). Throws ConfigError.
void check_startup(const AcousticCase& c, const Engine& e);

}  // namespace agglo::acoustics
