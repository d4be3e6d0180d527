// Checkpoint state of the DEM engine (dem_state.hpp).
#include "agglo/dem/dem_state.hpp"

#include "agglo/dem/dem_system.hpp"

namespace agglo::dem {

NeighborState NeighborList::state() const { return NeighborState{pairs_, x_at_build_, builds_}; }

void NeighborList::restore(const NeighborState& s, std::size_t n_particles) {
  pairs_ = s.pairs;
  x_at_build_ = s.x_at_build;
  builds_ = s.builds;
  index(n_particles);
}

DemState DemSystem::state() const {
  return DemState{p_, nl_.state(), dt_, skin_, time_, step_, forces_ready_, walls_};
}

void DemSystem::restore(const DemState& s) {
  p_ = s.particles;
  p_.mat.resize(p_.size(), 0);
  nl_.restore(s.neighbors, p_.size());
  blocks_builds_ = -1;  // the parallel path's blocks are made again for the restored list
  for (auto& pr : nl_.pairs()) pr.kind = mats_.kind(p_.mat[pr.i], p_.mat[pr.j]);
  dt_ = s.dt;
  skin_ = s.skin;
  time_ = s.time;
  step_ = s.step;
  forces_ready_ = s.forces_ready;
  walls_ = s.walls;
  for (auto& wc : walls_) wc.kind.clear();  // recomputed by attach() from the particles' materials
  decay_.clear();
  lag_.clear();
  kick_v_.clear();  // the restored masses and dt
  kick_w_.clear();
  attach();
}

}  // namespace agglo::dem
