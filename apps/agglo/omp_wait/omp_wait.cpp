// Short OpenMP spin waits for the agglo executable (docs/acoustics.md §5.2, "Threads on a shared machine").
// libgomp reads OMP_WAIT_POLICY and GOMP_SPINCOUNT once, in its own constructor, before main runs; with
// neither set, a waiting thread spins for about 300000 iterations (a few ms) before it sleeps, and on a
// machine whose cores are busy with other work the spinning thread takes the time slices the working
// thread needs (measured: --threads 2 two to four times slower than --threads 1). Sleeping at once
// (OMP_WAIT_POLICY=passive, agglo's setting until session 48) costs a wake-up of tens of µs at every
// barrier of a sub-millisecond step (DSMC parallel efficiency 0.70-0.78, DEM block 1.43x on two idle
// cores). So agglo spins kSpinCount iterations (tens of µs) and then sleeps: efficiency 0.95 / 1.8x there,
// and on a busy machine the steps' timed probes (core/thread_choice.hpp) still choose one thread.
// This tiny shared library is linked into agglo after every other library, so the dynamic loader runs
// its constructor after libc's and before libgomp's (dependencies first, the last-listed of siblings
// first; tests/cli/omp_wait_policy.sh checks the order through OMP_DISPLAY_ENV): it sets GOMP_SPINCOUNT
// unless the user set OMP_WAIT_POLICY or GOMP_SPINCOUNT, which keep their meaning. Child processes (plot
// scripts, MPI ranks) inherit the setting.
#include <cstdlib>

namespace {

constexpr const char* kSpinCount = "1000";

__attribute__((constructor)) void agglo_short_omp_waits() {
  if (std::getenv("OMP_WAIT_POLICY") == nullptr && std::getenv("GOMP_SPINCOUNT") == nullptr)
    setenv("GOMP_SPINCOUNT", kSpinCount, 0);
}

}  // namespace

// Referenced by main() so that the linker keeps the library (--as-needed).
extern "C" int agglo_omp_wait_linked() { return 1; }
