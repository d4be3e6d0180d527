// agglo.electrostatic_forces: one static solve of charged dielectric spheres given as NumPy arrays
// (docs/model.md Part B; the library call behind the CLI's `agglo electrostatics`). The arguments are
// checked and converted by electrostatic_input.hpp; the solve runs on a worker thread (runner.hpp) while
// the calling thread waits without the GIL and checks for Ctrl-C every 50 ms, which cancels the solve;
// forces, torques and surface samples are returned as NumPy views of the solver's own vectors.
#include <omp.h>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include "agglo/electrostatics/solver.hpp"
#include "agglo/writers/electrostatics.hpp"
#include "bindings.hpp"
#include "electrostatic_input.hpp"
#include "runner.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

static_assert(std::is_standard_layout_v<Vec3> && sizeof(Vec3) == 3 * sizeof(double));
static_assert(std::is_standard_layout_v<es::SurfaceSample>);

struct ElectrostaticResult {
  py::array forces, torques;  // N x 3 [N], [N m]
  double energy = 0.0;        // [J]
  py::dict stats;
  py::object surface = py::none();  // dict of arrays, or None
};

// A capsule that owns `v` (moved to the heap); arrays using it as base view its data without a copy.
template <class T>
std::pair<py::capsule, const std::vector<T>*> owner(std::vector<T>&& v) {
  auto* held = new std::vector<T>(std::move(v));
  return {py::capsule(held, [](void* p) { delete static_cast<std::vector<T>*>(p); }), held};
}

py::array vec3_array(std::vector<Vec3>&& v) {
  auto [cap, held] = owner(std::move(v));
  const auto n = static_cast<py::ssize_t>(held->size());
  return py::array_t<double>({n, py::ssize_t{3}}, &held->data()->x, cap);
}

// Strided views of one member of the samples (all views share the owning capsule).
template <class M>
py::array member_view(const py::capsule& cap, const std::vector<es::SurfaceSample>& s, std::size_t offset, int width) {
  const auto n = static_cast<py::ssize_t>(s.size());
  const auto* base = reinterpret_cast<const char*>(s.data()) + offset;
  const auto stride = static_cast<py::ssize_t>(sizeof(es::SurfaceSample));
  py::array a = width == 1 ? py::array_t<M>({n}, {stride}, reinterpret_cast<const M*>(base), cap)
                           : py::array_t<M>({n, py::ssize_t{width}}, {stride, static_cast<py::ssize_t>(sizeof(M))},
                                            reinterpret_cast<const M*>(base), cap);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::dict surface_dict(const es::Solver& solver) {
  auto [cap, s] = owner(solver.surface());
  using S = es::SurfaceSample;
  py::dict d;
  d["position"] = member_view<double>(cap, *s, offsetof(S, position), 3);
  d["normal"] = member_view<double>(cap, *s, offsetof(S, normal), 3);
  d["area"] = member_view<double>(cap, *s, offsetof(S, area), 1);
  d["sigma_free"] = member_view<double>(cap, *s, offsetof(S, sigma_free), 1);
  d["sigma_bound"] = member_view<double>(cap, *s, offsetof(S, sigma_bound), 1);
  d["body"] = member_view<int>(cap, *s, offsetof(S, body), 1);
  if (auto tri = solver.surface_triangles(); !tri.empty()) {
    auto [tcap, t] = owner(std::move(tri));
    const auto k = static_cast<py::ssize_t>(t->size());
    py::array tri_view = py::array_t<int>({k, py::ssize_t{3}}, t->data()->data(), tcap);
    tri_view.attr("setflags")(py::arg("write") = false);
    d["triangles"] = tri_view;
  }
  return d;
}

// Sets the calling thread's OpenMP thread count for its lifetime (0: all cores).
class ThreadScope {
 public:
  explicit ThreadScope(std::optional<int> n) : saved_(omp_get_max_threads()), set_(n.has_value()) {
    if (set_) omp_set_num_threads(*n > 0 ? *n : omp_get_num_procs());
  }
  ~ThreadScope() {
    if (set_) omp_set_num_threads(saved_);
  }
  ThreadScope(const ThreadScope&) = delete;
  ThreadScope& operator=(const ThreadScope&) = delete;

 private:
  int saved_;
  bool set_;
};

ElectrostaticResult electrostatic_forces(py::object positions, py::object radii, py::object charges,
                                         py::object permittivities, py::object solver_name,
                                         py::object medium_permittivity, py::object external_field,
                                         py::object min_gap, bool surface, py::object threads, py::object max_steps,
                                         py::object max_memory, py::kwargs options) {
  const EsInput in = read_es_input({std::move(positions), std::move(radii), std::move(charges),
                                    std::move(permittivities), std::move(solver_name), std::move(medium_permittivity),
                                    std::move(external_field), std::move(min_gap), std::move(threads),
                                    std::move(max_steps), std::move(max_memory), surface, std::move(options)});
  std::unique_ptr<es::Solver> solver;
  es::Solution sol;
  // On the worker of run_released: Ctrl-C sets the run's cancel token, which the solver polls
  // (core/cancel.hpp), and raises agglo.InterruptedError within a fraction of a second.
  (void)run_released(
      [&](const run::RunContext&) {
        const ThreadScope scope(in.threads);
        solver = es::make_solver(in.options);
        sol = solver->solve(in.problem);
        return run::CommandResult{};
      },
      run::RunContext{}, py::none());
  nlohmann::json stats = writers::solve_stats(*solver, in.problem, sol);
  stats["min_gap"] = in.min_gap ? nlohmann::json(*in.min_gap) : nlohmann::json(nullptr);
  ElectrostaticResult r;
  r.energy = sol.energy;
  r.forces = vec3_array(std::move(sol.force));
  r.torques = vec3_array(std::move(sol.torque));
  r.stats = py::module_::import("json").attr("loads")(stats.dump());
  if (surface) r.surface = surface_dict(*solver);
  return r;
}

constexpr const char* kForcesDoc = R"(Electrostatic forces, torques and energy of charged dielectric spheres.

One static solve, the library call behind the CLI's `agglo electrostatics` (docs/model.md Part B):
spheres with uniform free surface charge in a medium of relative permittivity kappa_0, polarised by
each other and by an optional uniform applied field. The spheres are solved exactly as given: no
contact-gap regularisation unless min_gap is passed. Touching or overlapping spheres raise
ConfigError naming the pair and the gap.

Parameters
----------
positions : array_like (N, 3)
    Sphere centres [m], N >= 1, each coordinate in [-1000, 1000] m.
radii : array_like (N,) or scalar
    Sphere radii [m], in (0, 0.1].
charges : array_like (N,) or scalar
    Free charge of each sphere [C], in [-1e-3, 1e-3], spread uniformly over its surface.
permittivities : array_like (N,) or scalar
    Relative permittivity kappa_p of each sphere, in (0, 1e6] (1 in vacuum or air = no polarisation).
    (The ranges of the [[particles]] keys of a case file, docs/config.md.)
solver : str
    "spectral" (default): spherical harmonics up to degree L per sphere, exponentially convergent,
    L chosen from the smallest gap for target_accuracy (docs/model.md §B.2 item 3).
    "bem": collocation boundary elements with GMRES and FMM, first order, about 1 % force error at
    2000 patches per sphere for gaps >= 0.1 r (docs/model.md §B.2 item 2).
    "coulomb": point charges in the medium, no polarisation, zero torque; exact when every
    kappa_p equals medium_permittivity (docs/model.md §B.2 item 1).
medium_permittivity : float
    Relative permittivity kappa_0 of the medium, in (0, 1e6] (default 1).
external_field : array_like (3,) or None
    Uniform applied field [V/m] (potential -E.x, zero at the origin); None = no field.
min_gap : float or None
    None (default): no regularisation. A value g_min in [0, 1) solves spheres of electrostatic radius
    r_E = r / (1 + g_min/2) with unchanged charges and centres, the contact regularisation of
    docs/model.md §B.3 used by the DEM coupling (collide, vcrit, breakup) and by the CLI's
    electrostatics command (whose default is 0.01): touching spheres are then about g_min r apart.
surface : bool
    Also return the surface charge samples (result.surface).
threads : int or None
    OpenMP threads of the solve (0 = all cores; None = the OpenMP default, e.g. OMP_NUM_THREADS).
    The GIL is released while solving, so other Python threads run meanwhile; Ctrl-C stops the solve
    within a fraction of a second and raises agglo.InterruptedError (a KeyboardInterrupt).
max_steps, max_memory : number, str or None
    Budgets of the solve (docs/limits.md), as for the command functions: interaction evaluations
    (e.g. 2e12) and bytes or a size text ("8G"); None = AGGLO_MAX_STEPS / AGGLO_MAX_MEMORY or the
    defaults. The solve's estimate (that of `agglo electrostatics`) beyond one raises LimitError
    before anything is allocated (e.g. patches_per_sphere=10**7, or 1e5 spheres, refused from their
    count before their positions are checked pair by pair).
**options
    Solver settings, named and range-checked as the [electrostatics] keys of a case file
    (docs/config.md):
    max_degree (int, spectral: fixed degree L, 0 = adaptive; default 0),
    target_accuracy (spectral: relative force accuracy of the adaptive degree; default 1e-4),
    max_degree_limit (int, spectral: highest adaptive degree; default 80),
    far_field ("dense" or "fmm", spectral: every pair re-expanded directly, or well-separated pairs
    through an octree; default "dense"),
    preconditioner ("none", "contact_low", or the measuring tools "coarse", "pair", "contact";
    spectral: right preconditioner of GMRES, contact_low the fast one; default "none"),
    preconditioner_steps (int, contact_low: its Neumann steps, 1-16; default 2),
    patches_per_sphere (int, bem; default 2000),
    tolerance (bem, spectral: relative GMRES tolerance; default 1e-6),
    max_iterations (int, most GMRES iterations; default 200),
    matvec ("fmm" or "direct", bem; default "fmm"),
    fmm_order (int, bem: FMM expansion order, 0 = automatic; default 0),
    fmm_leaf_size (int, bem: patches per FMM leaf box; default 64).

Returns
-------
ElectrostaticResult
    .forces (N, 3) [N], .torques (N, 3) [N m] about each centre, .energy [J]
    (U = 1/2 \int phi sigma_f dS including the shells' self energies, docs/model.md §B.1; without
    applied field F = -dU/dx), .stats (dict, as the CLI's stats.json), .surface (dict of arrays or
    None).

Raises
------
ConfigError
    Bad input, with a one-line message naming the argument, the value and what is allowed: array
    shape or dtype, a value outside its range (non-finite, radius or permittivity <= 0, a radius above
    0.1 m, a charge above 1e-3 C), an unknown option or a value outside its range, touching or
    overlapping spheres.
LimitError
    The solve's estimated steps or memory exceed a budget (max_steps, max_memory).
NumericalError
    The solver did not converge (GMRES reached max_iterations).
InterruptedError
    Ctrl-C during the solve.

Example
-------
>>> r = agglo.electrostatic_forces([[0, 0, 0], [0, 0, 21e-6]], 10e-6, [1e-14, -1e-14], 10.0,
...                                target_accuracy=1e-6)
>>> r.forces[1, 2]   # about -4.4404e-09 N (docs/model.md §B.4)
)";

constexpr const char* kResultDoc = R"(Result of agglo.electrostatic_forces.

Attributes
----------
forces : ndarray (N, 3), float64
    Force on each sphere [N].
torques : ndarray (N, 3), float64
    Torque on each sphere about its centre [N m].
energy : float
    U = 1/2 \int phi sigma_f dS [J] (docs/model.md §B.1): the self energies of the charged shells are
    included, the applied potential -E.x is zero at the origin.
stats : dict
    As the CLI's stats.json: solver, iterations (GMRES), residual (final relative residual),
    time_s (wall time of the solve [s]), degree (spectral: expansion degree L; bem: patches per
    sphere), particles, smallest_gap_m (smallest surface gap between the spheres the solver saw [m]),
    extra (solver specific, e.g. spectral: estimated_relative_error, degree_capped), and min_gap
    (the g_min used, or None).
surface : dict of ndarrays, or None
    With surface=True: M surface samples, 'position' (M, 3) [m], 'normal' (M, 3) (outward unit
    normal), 'area' (M,) [m^2], 'sigma_free' and 'sigma_bound' (M,) [C/m^2], 'body' (M,) int (sphere
    index) and, when the solver triangulates its samples (spectral, bem), 'triangles' (K, 3) int
    (sample indices, counter-clockwise seen from outside, as in the CLI's surface.vtu). The arrays
    are read-only views of the solver's output (no copies).
)";

}  // namespace

void bind_electrostatic_forces(py::module_& m) {
  py::class_<ElectrostaticResult>(m, "ElectrostaticResult", kResultDoc)
      .def_readonly("forces", &ElectrostaticResult::forces)
      .def_readonly("torques", &ElectrostaticResult::torques)
      .def_readonly("energy", &ElectrostaticResult::energy)
      .def_readonly("stats", &ElectrostaticResult::stats)
      .def_readonly("surface", &ElectrostaticResult::surface)
      .def("__repr__", [](const ElectrostaticResult& r) {
        return fmt::format("<agglo.ElectrostaticResult: {} spheres, solver {}, energy {:.6g} J>",
                           r.forces.shape(0), py::str(r.stats["solver"]).cast<std::string>(), r.energy);
      });
  m.def("electrostatic_forces", &electrostatic_forces, kForcesDoc, py::arg("positions"),
        py::arg("radii"), py::arg("charges"), py::arg("permittivities"), py::arg("solver") = "spectral",
        py::arg("medium_permittivity") = 1.0, py::arg("external_field") = py::none(),
        py::arg("min_gap") = py::none(), py::arg("surface") = false, py::arg("threads") = py::none(),
        py::arg("max_steps") = py::none(), py::arg("max_memory") = py::none());
}

}  // namespace agglo::python
