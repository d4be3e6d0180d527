"""agglo.electrostatic_forces: physics checks, agreement with the CLI, input validation."""
import json
import math
import subprocess
import time
import tomllib

import numpy as np
import pytest

from conftest import BUILD

EPS0 = 8.8541878128e-12  # F/m, as agglo/core/constants.hpp
WHERE = "agglo.electrostatic_forces: "


def config_error(agglo):
    return getattr(agglo, "ConfigError", RuntimeError)


def pair(gap_over_r=0.2, kappa=10.0, r=10e-6, q=(1e-14, -0.5e-14)):
    """Two equal spheres on a skew axis, `gap_over_r` * r apart surface to surface."""
    axis = np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8])
    x = np.array([[1e-6, 2e-6, -3e-6], [1e-6, 2e-6, -3e-6]]) + np.outer([0.0, (2 + gap_over_r) * r], axis)
    return x, np.full(2, r), np.array(q), np.full(2, kappa), axis


def cluster():
    """Four dielectric spheres of different sizes, charges and permittivities, no two touching."""
    x = np.array([[0.0, 0.0, 0.0], [23e-6, 1e-6, 0.0], [9e-6, 19e-6, 2e-6], [10e-6, 7e-6, 18e-6]])
    r = np.array([10e-6, 11e-6, 8e-6, 9e-6])
    q = np.array([1.2e-14, -0.8e-14, 0.5e-14, 0.0])
    kappa = np.array([15.0, 4.0, 2.5, 8.0])
    return x, r, q, kappa


def rel(a, b):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) / np.max(np.abs(b))


@pytest.mark.parametrize("kappa0", [1.0, 2.0])
def test_coulomb_law_without_polarisation(agglo_module, kappa0):
    x = np.array([[0.0, 0.0, 0.0], [3e-4, -4e-4, 12e-4]])
    r, q = np.array([1e-6, 1.5e-6]), np.array([2e-15, -3e-15])
    res = agglo_module.electrostatic_forces(x, r, q, np.full(2, kappa0), medium_permittivity=kappa0)
    d = x[0] - x[1]
    dist = np.linalg.norm(d)
    f0 = q[0] * q[1] * d / (4 * math.pi * EPS0 * kappa0 * dist**3)
    assert rel(res.forces, np.array([f0, -f0])) < 1e-12  # kappa_p = kappa_0: exact
    u = (q[0] ** 2 / r[0] / 2 + q[1] ** 2 / r[1] / 2 + q[0] * q[1] / dist) / (4 * math.pi * EPS0 * kappa0)
    assert abs(res.energy - u) < 1e-12 * abs(u)
    assert res.forces.shape == (2, 3) and res.torques.shape == (2, 3) and res.forces.dtype == np.float64


def test_model_reference_pair(agglo_module):
    """docs/model.md §B.4 (kappa_p = 10, gap 0.1 R, charges (1, -1) Q0): fz on sphere 2 = -0.494063 F0."""
    res = agglo_module.electrostatic_forces([[0, 0, 0], [0, 0, 21e-6]], 10e-6, [1e-14, -1e-14], 10.0,
                                            target_accuracy=1e-6)
    f0 = 1e-28 / (4 * math.pi * EPS0 * 1e-10)
    assert abs(res.forces[1, 2] / f0 + 0.494063) < 2e-6
    assert abs(res.forces[0, 2] + res.forces[1, 2]) < 1e-9 * f0


def test_action_reaction(agglo_module):
    x, r, q, kappa = cluster()
    res = agglo_module.electrostatic_forces(x, r, q, kappa, target_accuracy=1e-8)
    fmax = np.max(np.linalg.norm(res.forces, axis=1))
    assert np.linalg.norm(res.forces.sum(axis=0)) < 1e-8 * fmax
    # Total torque about the origin vanishes too (torques about the centres are ~0 for spheres).
    total = np.cross(x, res.forces).sum(axis=0) + res.torques.sum(axis=0)
    assert np.linalg.norm(total) < 1e-8 * fmax * 10e-6


def test_spectral_agrees_with_bem(agglo_module):
    x, r, q, kappa, _ = pair(gap_over_r=0.5, kappa=4.0)
    spectral = agglo_module.electrostatic_forces(x, r, q, kappa, target_accuracy=1e-8)
    bem = agglo_module.electrostatic_forces(x, r, q, kappa, solver="bem", patches_per_sphere=2000)
    assert bem.stats["solver"] == "bem" and spectral.stats["solver"] == "spectral"
    # docs/model.md §B.2: BEM at 2000 patches per sphere, gaps >= 0.1 r: 0.3-0.9 % force error.
    assert rel(bem.forces, spectral.forces) < 1e-2
    assert abs(bem.energy - spectral.energy) < 1e-2 * abs(spectral.energy)


def test_force_is_minus_energy_gradient(agglo_module):
    x, r, q, kappa, _ = pair(gap_over_r=0.2, kappa=10.0)
    opts = dict(max_degree=40, tolerance=1e-13, target_accuracy=1e-11)
    f = agglo_module.electrostatic_forces(x, r, q, kappa, **opts).forces[1]
    e = np.array([0.6, 0.0, 0.8])  # a direction oblique to the pair axis
    h = 1e-3 * r[0]
    u = []
    for s in (1, -1):
        xs = x.copy()
        xs[1] += s * h * e
        u.append(agglo_module.electrostatic_forces(xs, r, q, kappa, **opts).energy)
    fd = -(u[0] - u[1]) / (2 * h)
    assert abs(fd - f @ e) < 1e-5 * np.linalg.norm(f)


def test_mirror_and_permutation_symmetry(agglo_module):
    x, r, q, kappa = cluster()
    base = agglo_module.electrostatic_forces(x, r, q, kappa, max_degree=20)
    m = np.diag([-1.0, 1.0, 1.0])
    mirrored = agglo_module.electrostatic_forces(x @ m, r, q, kappa, max_degree=20)
    fmax = np.max(np.abs(base.forces))
    assert np.max(np.abs(mirrored.forces - base.forces @ m)) < 1e-12 * fmax
    assert abs(mirrored.energy - base.energy) < 1e-12 * abs(base.energy)
    p = [2, 0, 3, 1]
    permuted = agglo_module.electrostatic_forces(x[p], r[p], q[p], kappa[p], max_degree=20)
    assert np.max(np.abs(permuted.forces - base.forces[p])) < 1e-12 * fmax


def run_cli(case_path, tmp_path, name):
    out = tmp_path / name
    subprocess.run([str(BUILD / "agglo"), "electrostatics", str(case_path), "--out", str(out)], check=True,
                   capture_output=True)
    forces = np.loadtxt(out / "forces.csv", delimiter=",", skiprows=1, ndmin=2)
    energy = json.loads((out / "energy.json").read_text())["energy_J"]
    return forces[:, 1:4], forces[:, 4:7], energy


@pytest.mark.parametrize("case", ["electrostatics_two_spheres.toml", "electrostatics_tetrahedron.toml"])
def test_same_as_cli(agglo_module, source_dir, tmp_path, case):
    path = source_dir / "cases" / case
    c = tomllib.loads(path.read_text())
    es = dict(c["electrostatics"])
    options = {k: es.pop(k) for k in list(es) if k not in ("solver", "min_gap", "medium_permittivity")}
    p = c["particles"]
    res = agglo_module.electrostatic_forces(
        np.array([s["position"] for s in p]), np.array([s["radius"] for s in p]),
        np.array([s.get("charge", 0.0) for s in p]), np.array([s.get("permittivity", 1.0) for s in p]),
        solver=es.get("solver", "spectral"), min_gap=es.get("min_gap", 0.01),
        medium_permittivity=es.get("medium_permittivity", 1.0), **options)
    forces, torques, energy = run_cli(path, tmp_path, case)
    fmax = np.max(np.abs(forces))
    assert np.max(np.abs(res.forces - forces)) < 1e-11 * fmax  # forces.csv has 12 significant digits
    assert np.max(np.abs(res.torques - torques)) < 1e-11 * fmax * 1e-5
    assert abs(res.energy - energy) < 1e-12 * abs(energy)


def test_same_as_cli_bem_without_min_gap(agglo_module, tmp_path):
    """min_gap=None solves the spheres as given, as a case file with min_gap = 0 does."""
    x, r, q, kappa = cluster()
    case = ['[electrostatics]', 'solver = "bem"', 'min_gap = 0.0', 'patches_per_sphere = 400', 'matvec = "direct"',
            'tolerance = 1e-8', 'medium_permittivity = 1.5']
    for i in range(len(r)):
        case += ['[[particles]]', f'position = [{x[i, 0]!r}, {x[i, 1]!r}, {x[i, 2]!r}]', f'radius = {r[i]!r}',
                 f'charge = {q[i]!r}', f'permittivity = {kappa[i]!r}']
    path = tmp_path / "cluster.toml"
    path.write_text("\n".join(case) + "\n")
    res = agglo_module.electrostatic_forces(x, r, q, kappa, solver="bem", patches_per_sphere=400, matvec="direct",
                                            tolerance=1e-8, medium_permittivity=1.5)
    forces, _, energy = run_cli(path, tmp_path, "out")
    assert res.stats["min_gap"] is None and res.stats["degree"] == 400
    assert np.max(np.abs(res.forces - forces)) < 1e-11 * np.max(np.abs(forces))
    assert abs(res.energy - energy) < 1e-12 * abs(energy)


def test_preconditioner_reaches_the_solver(agglo_module):
    """preconditioner="contact_low" (electrostatics.preconditioner): fewer GMRES iterations for touching
    kappa_p = 15 spheres (a chain of four, min_gap 0.01), the same forces to the GMRES tolerance."""
    x = np.array([[0.0, 0.0, 0.0], [20e-6, 0.0, 0.0], [30e-6, 17.320508e-6, 0.0], [50e-6, 17.320508e-6, 0.0]])
    args = (x, np.full(4, 10e-6), np.array([1.25e-14, -1.25e-14, 1.25e-14, -1.25e-14]), np.full(4, 15.0))
    none = agglo_module.electrostatic_forces(*args, min_gap=0.01)
    low = agglo_module.electrostatic_forces(*args, min_gap=0.01, preconditioner="contact_low")
    assert low.stats["iterations"] <= none.stats["iterations"] - 2, (low.stats, none.stats)
    scale = np.max(np.linalg.norm(none.forces, axis=1))
    assert np.max(np.linalg.norm(low.forces - none.forces, axis=1)) < 1e-5 * scale
    # preconditioner_steps (electrostatics.preconditioner_steps) reaches it as well: another iterate
    four = agglo_module.electrostatic_forces(*args, min_gap=0.01, preconditioner="contact_low", preconditioner_steps=4)
    assert (four.stats["iterations"], four.energy) != (low.stats["iterations"], low.energy)
    assert np.max(np.linalg.norm(four.forces - none.forces, axis=1)) < 1e-5 * scale
    with pytest.raises(config_error(agglo_module), match="preconditioner_steps"):
        agglo_module.electrostatic_forces(*args, min_gap=0.01, preconditioner_steps=0)


def test_touching_spheres_need_min_gap(agglo_module):
    x = np.array([[0.0, 0.0, 0.0], [20e-6, 0.0, 0.0]])
    args = (x, np.full(2, 10e-6), np.array([1e-14, -1e-14]), np.full(2, 5.0))
    with pytest.raises(config_error(agglo_module)) as err:
        agglo_module.electrostatic_forces(*args)
    msg = str(err.value)
    assert msg.startswith(WHERE) and "\n" not in msg
    assert "spheres 0 and 1 touch or overlap: surface gap 0 m" in msg and "min_gap" in msg
    res = agglo_module.electrostatic_forces(*args, min_gap=0.01)
    assert np.all(np.isfinite(res.forces)) and res.forces[0, 0] > 0  # attraction
    assert res.stats["min_gap"] == 0.01
    assert res.stats["smallest_gap_m"] == pytest.approx(20e-6 - 2 * 10e-6 / 1.005, rel=1e-12)
    with pytest.raises(config_error(agglo_module), match=r"spheres 0 and 1 touch or overlap: .* min_gap = 0\.01"):
        agglo_module.electrostatic_forces(x * 0.9, *args[1:], min_gap=0.01)


GOOD = dict(positions=[[0.0, 0.0, 0.0], [0.0, 0.0, 30e-6]], radii=[10e-6, 10e-6], charges=[1e-14, 0.0],
            permittivities=[5.0, 5.0])


@pytest.mark.parametrize("change, expected", [
    (dict(positions=[[0.0, 0.0], [0.0, 1.0]]), "positions has shape (2, 2) (must be (N, 3)"),
    (dict(positions=[[0.0, 0.0, math.nan], [0.0, 0.0, 30e-6]]), "positions[0] = [0, 0, nan] m (must be in [-1000, 1000] m, the range of particles.position)"),
    (dict(radii=[10e-6, -1e-6]), "radii[1] = -1e-06 m (must be in (0, 0.1] m, the range of particles.radius)"),
    (dict(radii=[10e-6, 10e-6, 10e-6]), "radii has shape (3,) (must be (2,)"),
    (dict(charges=[1e-14, math.inf]), "charges[1] = inf C (must be in [-0.001, 0.001] C, the range of particles.charge)"),
    (dict(permittivities=[0.0, 5.0]), "permittivities[0] = 0 (must be in (0, 1e+06], the range of particles.permittivity)"),
    (dict(charges=["a", "b"]), "charges has dtype <U1 (must be real numbers"),
    (dict(radii=np.array([1e-5, 1e-5], dtype=complex)), "radii has dtype complex128"),
    (dict(external_field=[1.0, 2.0]), "external_field has shape (2,) (must be (3,), in V/m, or None)"),
    (dict(solver="fem"), "argument 'solver' = \"fem\""),
    (dict(medium_permittivity=-1.0), "argument 'medium_permittivity' = -1"),
    (dict(min_gap=1.5), "argument 'min_gap' = 1.5"),
    (dict(max_degree=500), "argument 'max_degree' = 500"),
    (dict(max_degree=2.5), "argument 'max_degree' = 2.5"),
    (dict(tolerance="small"), "argument 'tolerance' = \"small\""),
    (dict(preconditioner="ilu"), "argument 'preconditioner' = \"ilu\""),
    (dict(matvec=[1]), "argument 'matvec' has type list (must be a number or a string)"),
    (dict(degree=10), "unknown option 'degree' (allowed: max_degree, target_accuracy, max_degree_limit, "
                      "far_field, preconditioner, preconditioner_steps, patches_per_sphere, tolerance, max_iterations, matvec, fmm_order, fmm_leaf_size)"),
    (dict(threads=-1), "argument 'threads' = -1 (must be a whole number >= 0"),
    # The physical ranges of the CLI's [[particles]] and [electrostatics] keys (issue 23 item 10: all ran).
    (dict(radii=10.0), "radii[0] = 10 m (must be in (0, 0.1] m, the range of particles.radius)"),
    (dict(charges=1.0), "charges[0] = 1 C (must be in [-0.001, 0.001] C"),
    (dict(positions=[[0.0, 0.0, 0.0], [0.0, 0.0, 2e3]]), "positions[1] = [0, 0, 2000] m (must be in [-1000, 1000] m"),
    (dict(permittivities=1e7), "permittivities[0] = 10000000 (must be in (0, 1e+06]"),
    (dict(medium_permittivity=1e300), "argument 'medium_permittivity' = 1e+300: out of range, allowed (0, 1e+06]"),
    (dict(max_steps="lots"), "max_steps = 'lots': not a step count"),
    (dict(max_memory=True), "argument 'max_memory' = True (must be a number or a size text"),
])
def test_bad_input_one_line_message(agglo_module, change, expected):
    with pytest.raises(config_error(agglo_module)) as err:
        agglo_module.electrostatic_forces(**{**GOOD, **change})
    msg = str(err.value)
    assert msg.startswith(WHERE) and "\n" not in msg
    assert expected in msg


def _many_spheres(n):
    k = np.arange(n)
    return np.stack([k % 100, k // 100 % 100, k // 10000], -1) * 3e-5, 1e-5, 1e-15, 3.0


@pytest.mark.parametrize("args, options, expected", [
    ((), dict(solver="bem", patches_per_sphere=10**7), "the estimated memory"),  # 26 GiB
    ("many", {}, "the estimated memory"),                                        # 1e5 spheres: 4.7 TiB
    ((), dict(max_steps=1), "exceeds the step budget 1 steps"),
    ((), dict(max_memory="1K"), "exceeds the memory budget 1 KiB"),
])
def test_budgets(agglo_module, args, options, expected):
    """The budgets of `agglo electrostatics` (issue 23 item 10: patches_per_sphere=10**7 and 1e5 spheres
    ran): a LimitError in one line naming the keyword that raises the budget, before any allocation and,
    for 1e5 spheres, from their count before their positions are compared pair by pair (about 10 s)."""
    call = dict(GOOD)
    if args == "many":
        call.update(zip(("positions", "radii", "charges", "permittivities"), _many_spheres(100000)))
    start = time.monotonic()
    with pytest.raises(agglo_module.LimitError) as err:
        agglo_module.electrostatic_forces(**call, **options)
    assert time.monotonic() - start < 2.0
    msg = str(err.value)
    assert msg.startswith(WHERE) and "\n" not in msg and expected in msg, msg
    assert ("max_steps=" if "step" in expected else "max_memory=") in msg and "--max" not in msg


def test_budget_keywords_raise_the_environment(agglo_module, monkeypatch):
    """max_steps= wins over AGGLO_MAX_STEPS, which wins over the default."""
    monkeypatch.setenv("AGGLO_MAX_STEPS", "1")
    with pytest.raises(agglo_module.LimitError, match="AGGLO_MAX_STEPS"):
        agglo_module.electrostatic_forces(**GOOD)
    assert agglo_module.electrostatic_forces(**GOOD, max_steps=1e9).energy != 0.0


def test_input_conversion_and_scalars(agglo_module):
    a = agglo_module.electrostatic_forces(**GOOD)
    b = agglo_module.electrostatic_forces(GOOD["positions"], 10e-6, np.array([1e-14, 0]), 5, threads=1)
    assert np.array_equal(a.forces, b.forces) and a.energy == b.energy
    c = agglo_module.electrostatic_forces(np.asfortranarray(GOOD["positions"]), GOOD["radii"], GOOD["charges"],
                                          np.array([5, 5], dtype=np.int32), threads=0)
    assert np.array_equal(a.forces, c.forces)
    x32 = np.array(GOOD["positions"], dtype=np.float32)
    d = agglo_module.electrostatic_forces(x32, GOOD["radii"], GOOD["charges"], GOOD["permittivities"])
    e = agglo_module.electrostatic_forces(x32.astype(np.float64), GOOD["radii"], GOOD["charges"],
                                          GOOD["permittivities"])
    assert np.array_equal(d.forces, e.forces)
    # A neutral dielectric sphere is attracted by the charged one: the force on sphere 1 points to it.
    assert a.forces[1, 2] < 0 and a.forces[0, 2] > 0


def test_external_field_on_single_charge(agglo_module):
    e = np.array([1e3, -2e3, 5e2])
    res = agglo_module.electrostatic_forces([[1e-6, 0.0, 0.0]], [5e-6], [3e-15], [1.0], solver="coulomb",
                                            external_field=e)
    assert rel(res.forces[0], 3e-15 * e) < 1e-12


def test_surface_samples(agglo_module):
    x, r, q, kappa, _ = pair(gap_over_r=0.5, kappa=4.0)
    for solver in ("spectral", "bem"):
        res = agglo_module.electrostatic_forces(x, r, q, kappa, solver=solver, surface=True, patches_per_sphere=500)
        s = res.surface
        m = s["position"].shape[0]
        assert s["position"].shape == (m, 3) and s["normal"].shape == (m, 3)
        for key in ("area", "sigma_free", "sigma_bound", "body"):
            assert s[key].shape == (m,)
        assert set(np.unique(s["body"])) == {0, 1}
        for i in range(2):
            on = s["body"] == i
            assert np.sum(s["area"][on]) == pytest.approx(4 * math.pi * r[i] ** 2, rel=1e-6)
            assert np.sum(s["sigma_free"][on] * s["area"][on]) == pytest.approx(q[i], rel=1e-6)
            dist = np.linalg.norm(s["position"][on] - x[i], axis=1)
            assert np.allclose(dist, r[i], rtol=1e-9)
        assert not s["position"].flags.writeable
        if solver == "bem":
            t = s["triangles"]
            assert t.shape[1] == 3 and t.min() >= 0 and t.max() < m
            assert np.all(s["body"][t[:, 0]] == s["body"][t[:, 2]])  # a triangle stays on one sphere
    assert agglo_module.electrostatic_forces(x, r, q, kappa).surface is None


def test_help_documents_parameters_and_units(agglo_module):
    doc = agglo_module.electrostatic_forces.__doc__
    for word in ("positions", "[m]", "[C]", "min_gap", "docs/model.md", "spectral", "bem", "coulomb", "threads",
                 "max_degree", "[N m]", "[J]"):
        assert word in doc
    assert "forces" in agglo_module.ElectrostaticResult.__doc__


def test_gmres_failure_is_a_numerical_error(agglo_module):
    x, r, q, kappa = cluster()
    with pytest.raises(getattr(agglo_module, "NumericalError", RuntimeError)) as err:
        agglo_module.electrostatic_forces(x, r, q, kappa, max_iterations=1, tolerance=1e-12)
    assert "GMRES did not converge" in str(err.value) and "\n" not in str(err.value)


def test_results_are_views_of_the_solver_output(agglo_module):
    res = agglo_module.electrostatic_forces(**GOOD)
    for a in (res.forces, res.torques):
        assert not a.flags.owndata and a.base is not None and a.flags.c_contiguous
    single = agglo_module.electrostatic_forces([[0.0, 0.0, 0.0]], [2e-6], [1e-15], [3.0], medium_permittivity=2.0)
    assert np.array_equal(single.forces, np.zeros((1, 3)))
    assert single.energy == pytest.approx(1e-30 / (8 * math.pi * EPS0 * 2.0 * 2e-6), rel=1e-12)


def test_concurrent_calls_from_python_threads(agglo_module):
    """The GIL is released during the solve: two threads solving at once get the sequential results."""
    import threading
    x, r, q, kappa = cluster()
    jobs = [dict(solver="spectral", target_accuracy=1e-8), dict(solver="bem", patches_per_sphere=300, matvec="direct")]
    expected = [agglo_module.electrostatic_forces(x, r, q, kappa, threads=1, **j).forces for j in jobs]
    got = [None, None]

    def run(i):
        got[i] = agglo_module.electrostatic_forces(x, r, q, kappa, threads=1, **jobs[i]).forces

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for g, e in zip(got, expected):
        assert np.array_equal(g, e)
