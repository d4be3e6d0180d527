#pragma once
// Seeds of an ensemble (`agglo sweep ... --seeds N`, `agglo acoustic CASE --seeds N`, run/ensemble_request.hpp):
// every point of the grid (the case alone when nothing is swept) runs N members that differ only in their
// random seed. The seed is the grid's last, fastest axis, with the same member seeds at every point, so
// member 0 of a point is the run of the plain sweep (the case's own seed) and the points share their random
// numbers (differences between points are less noisy than with independent seeds). Per point, the mean and
// standard error over its members (io/ensemble_stats.hpp) of every summary scalar, time series and size
// distribution; the statistics come from the jobs' results alone ({"summary", "data"}, SweepPlan::keep_data),
// never from the member folders, so they are the same whichever thread or MPI rank ran a member.
//
// Member seeds depend on the base seed b (the case's seed) and the member index k only:
//   s_0 = b (member 0 is the single run of the case),
//   s_k = mix(mix(b) + k) & (2^63 - 1) for k >= 1 (the seed key's range is 0..2^63-1),
// where mix is the SplitMix64 finaliser (Steele, Lea & Flood 2014); a value equal to an earlier
// member's seed is mixed again until it is new.
#include <cstdint>
#include <vector>

#include "agglo/io/dataset.hpp"
#include "agglo/io/sweep_points.hpp"
#include "agglo/run/sweep.hpp"

namespace agglo::run {

std::vector<std::int64_t> member_seeds(std::int64_t base, std::size_t n);

// `axes` with the seed axis of n >= 2 members (member_seeds of the base case's seed) appended. ConfigError
// (one line naming --seeds, the value and what is allowed) when `cmd` has no random seed, or when an axis
// already varies the seed.
std::vector<SweepAxis> with_seed_axis(const Command& cmd, const Config& base, std::vector<SweepAxis> axes,
                                      long long n);

// The points of a finished grid whose last axis is the seed axis of `members` members: the cases come in
// grid order, so point p holds cases p*members .. p*members + members - 1. Each point's values (the seed
// dropped), member 0's folder, its member count and the statistics of its members' summary scalars.
std::vector<io::SweepPoint> sweep_points(const SweepResult& res, std::size_t members);

// The whole statistics of the point whose members are cases first .. first + members - 1 of `res` (their
// job results carry data): io::ensemble_dataset of the members' data (every time series and distribution
// as <name>_mean, <name>_stderr), the sweep table of the members (dim `case`: their summary scalars, `keys`
// their swept keys with the seed last) with member_seed (int64, exact), and the global attributes members
// (N) and seeds (int64 array). std::invalid_argument when a member has no data.
io::Dataset point_dataset(const SweepResult& res, std::size_t first, std::size_t members,
                          const std::vector<std::string>& keys);

}  // namespace agglo::run
