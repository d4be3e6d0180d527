// Keeps libagglo_omp_wait.so in every test executable (the linker's --as-needed drops a library that
// nothing references), so that the tests' OpenMP threads wait as the CLI's do, a short spin and then
// sleep (apps/agglo/omp_wait/omp_wait.cpp): two test processes spinning for ms on two cores slow each other down.
extern "C" int agglo_omp_wait_linked();

namespace {
[[maybe_unused]] const int kOmpWaits = agglo_omp_wait_linked();
}  // namespace
