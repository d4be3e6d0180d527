#pragma once
// Spreading the samples of a population over the cells at t = 0 (section [sampling];
// docs/model.md §C.4 "Sampling over cells", docs/acoustics.md §2).
//
// Why: partners are taken from the same cell only, and fines practically never leave their cell, so a
// fine meets only the droplet samples of its own cell. With a random droplet count per cell the mean
// fine survival is <exp(-beta n_d,cell t)> over the cells, larger than exp(-beta n_d t) (Jensen).
//
//  - placement "stratified": sample m of a population (in its sampled order: by size, clones of one
//    sample consecutive) goes to cell perm_r[m mod C] with C cells and r = floor(m / C), perm_r a random
//    permutation of the cells per round r (Philox keyed by seed, population and r). Every cell thus holds
//    floor(N/C) or ceil(N/C) samples of every population, the seeded draw decides which cells get the
//    extra one, and each cell gets one sample of every run of C consecutive sizes. Position uniform
//    inside the cell (same Philox stream per sample as the random placement).
//  - placement "random": uniform in the periodic box (Zhao et al.'s method; the positions are those of
//    earlier versions for the same seed).
//  - min_samples_per_cell M: a population with N < M C samples is split into clones, clone factor
//    k = ceil(M C / N). A sample of integer weight w becomes min(k, w) clones of weights floor(w/k') or
//    ceil(w/k') (k' = min(k, w); the larger ones first) that add up to w exactly, every clone carrying
//    the sample's per-particle state (volumes, mass, velocity). Number, volume, mass and momentum are
//    therefore conserved exactly. The clones are placed like the other samples.
//  - Zhao et al.'s method is placement = "random", min_samples_per_cell = 0.
#include <cstddef>
#include <cstdint>

#include "agglo/acoustics/drag.hpp"
#include "agglo/acoustics/samples.hpp"
#include "agglo/core/settings_acoustic.hpp"

namespace agglo::acoustics {

struct AcousticCase;

enum class Placement { stratified, random };

// Defaults are the declared [sampling] settings (agglo/core/settings_acoustic.hpp).
struct SamplingSettings {
  Placement placement =
      settings::acoustic_settings().sampling.placement.def() == "random" ? Placement::random : Placement::stratified;
  std::int64_t min_samples_per_cell = settings::acoustic_settings().sampling.min_samples_per_cell.def();
};

// Most samples the cloning may produce in one case (the same limit as population.samples).
inline constexpr std::int64_t kMaxSamplesAfterCloning = 100000000;

// Clone factor k = ceil(M C / N) of a population of N samples in C cells (1 when N >= M C or M = 0).
std::int64_t clone_factor(std::int64_t samples, std::int64_t cells, std::int64_t min_samples_per_cell);

// Upper bound of the number of samples after cloning (sum over populations of N k; exact unless a
// sample's weight is below k). For budget checks before a run.
std::size_t sample_count_after_cloning(const AcousticCase& c);

// Splits the samples [first, first + count) of p (the last range of p) into clones as above; returns
// the new count of the range. The clones of a sample follow each other; ids are left to the caller.
std::size_t split_into_clones(SampleSet& p, std::size_t first, std::size_t count, std::int64_t k);

// Sets the positions of the samples [first, first + count) of population `population`.
void place_samples(SampleSet& p, std::size_t first, std::size_t count, Placement placement, const Domain& dom,
                   std::uint64_t seed, int population);

}  // namespace agglo::acoustics
