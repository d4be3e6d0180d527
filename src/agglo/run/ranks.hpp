#pragma once
// The processes of one agglo run. Without MPI (or not launched by mpirun) there is one process and it
// writes everything. Under `mpirun -n K` every rank runs the same pipeline, the ensemble runner spreads
// its jobs over the ranks (run/ensemble.hpp), and only rank 0 writes the run's top-level outputs
// (other ranks write into a private scratch folder that is removed at the end; the folders of a sweep's
// cases are written by the rank that runs the case).
namespace agglo::run {

// True in the process that writes a run's top-level outputs (always without MPI; rank 0 under mpirun).
bool is_output_rank();

// Number of processes of this run (1 without MPI).
int rank_count();

}  // namespace agglo::run
