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
  nl_.restore(s.neighbors, p_.size());
  dt_ = s.dt;
  skin_ = s.skin;
  time_ = s.time;
  step_ = s.step;
  forces_ready_ = s.forces_ready;
  walls_ = s.walls;
  decay_.clear();
  lag_.clear();
  attach();
}

}  // namespace agglo::dem
