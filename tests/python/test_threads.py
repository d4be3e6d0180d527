"""Runs release the GIL, report progress on the calling thread, and stop cleanly on Ctrl-C."""
import _thread
import json
import os
import resource
import signal
import threading
import time

import numpy as np
import pytest

from agglo_cases import short
from conftest import BUILD

LONG = {"time.after_contact": 0.1, "time.early_stop": False}  # about a second on one thread


def _tasks():
    """The ids of the process's threads (a thread left running would be a new one; others may end meanwhile)."""
    return set(os.listdir("/proc/self/task"))


def _tasks_settle(baseline, limit=2.0):
    """_tasks() once it is within baseline, or after `limit` seconds: a cancelled worker's OpenMP team
    ends when its master thread has exited, a moment after the run returned."""
    end = time.monotonic() + limit
    while not _tasks() <= baseline and time.monotonic() < end:
        time.sleep(0.02)
    return _tasks()


def test_two_threads_overlap(agglo_module):
    """Each thread's progress callbacks span an interval; with the GIL held during a run they could not overlap."""
    agglo = agglo_module
    spans = {}
    barrier = threading.Barrier(2)

    def work(tag):
        calls = []
        barrier.wait()
        agglo.collide(short(agglo, extra=LONG), threads=1, progress=lambda f, t: calls.append(time.monotonic()))
        spans[tag] = (calls[0], calls[-1])

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    start = time.monotonic()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    (a0, a1), (b0, b1) = spans[0], spans[1]
    print(f"spans {a0 - start:.3f}-{a1 - start:.3f} s and {b0 - start:.3f}-{b1 - start:.3f} s")
    assert max(a0, b0) < min(a1, b1)


def test_gil_released_while_running(agglo_module):
    """A Python thread keeps running while a collide goes on in the main thread."""
    agglo = agglo_module
    ticks, stop = [], threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.005)

    t = threading.Thread(target=ticker)
    t.start()
    try:
        start = time.monotonic()
        agglo.collide(short(agglo, extra=LONG), threads=1)
        end = time.monotonic()
    finally:
        stop.set()
        t.join()
    inside = [x for x in ticks if start < x < end]
    assert len(inside) >= 10, (len(inside), end - start)


def test_progress_on_calling_thread(agglo_module):
    agglo = agglo_module
    calls = []
    agglo.collide(short(agglo, extra=LONG), threads=2,
                  progress=lambda f, t: calls.append((threading.get_ident(), f, t)))
    assert calls and {c[0] for c in calls} == {threading.get_ident()}
    fractions = [c[1] for c in calls]
    assert all(0.0 <= f <= 1.0 for f in fractions) and fractions == sorted(fractions)
    assert all(t >= 0.0 for _, _, t in calls)


def test_callback_exception_cancels(agglo_module):
    agglo = agglo_module
    baseline = _tasks()

    def fail(fraction, sim_time):
        raise RuntimeError("stop here")

    start = time.monotonic()
    with pytest.raises(RuntimeError, match="stop here"):
        agglo.collide(short(agglo, extra={"time.after_contact": 1.0, "time.early_stop": False}), threads=1, progress=fail)
    assert time.monotonic() - start < 5.0
    assert _tasks() <= baseline


def test_ctrl_c_interrupts(agglo_module, tmp_path):
    agglo = agglo_module
    agglo.collide(short(agglo), threads=1)  # warm-up: thread pools that persist exist before the baseline
    baseline = _tasks()
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(agglo.InterruptedError) as err:
            agglo.collide(short(agglo, extra={"time.after_contact": 1.0, "time.early_stop": False}), threads=1, out=tmp_path / "run")
    finally:
        timer.cancel()
    elapsed = time.monotonic() - start
    assert isinstance(err.value, KeyboardInterrupt) and str(err.value) == "interrupted"
    assert elapsed < 3.0, elapsed
    timer.join()
    assert _tasks_settle(baseline) <= baseline  # the worker thread and its OpenMP team are gone
    assert json.loads((tmp_path / "run" / "run.json").read_text())["status"] == "incomplete"
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # the module installs no handler


def _lattice(n=4, gap_over_r=0.02, r=10e-6):
    """n^3 nearly touching dielectric spheres with alternating charges: a spectral solve of many seconds."""
    k = np.arange(n)
    x = np.stack(np.meshgrid(k, k, k, indexing="ij"), -1).reshape(-1, 3) * (2 + gap_over_r) * r
    q = np.where(np.arange(len(x)) % 2 == 0, 1.0, -1.0) * 1e-14
    return x, np.full(len(x), r), q, np.full(len(x), 3.8)


@pytest.mark.parametrize("solver,n,options", [("spectral", 7, {"target_accuracy": 1e-6}),
                                              ("spectral", 8, {"target_accuracy": 1e-6, "far_field": "fmm"}),
                                              ("bem", 3, {"patches_per_sphere": 2000})])
def test_ctrl_c_interrupts_electrostatic_forces(agglo_module, solver, n, options):
    """Ctrl-C 0.5 s into a static solve raises agglo.InterruptedError after at most one second of work per
    thread (the solver polls the cancel token in its set-up and after every GMRES operator application;
    before, the solve ran to its end, ~60 s on a 30-sphere case). The work is the process's CPU time
    (2 threads: 2 s), so that a shared machine does not count; the wall time is bounded at 5 s. The
    lattice's solve takes far longer than the 0.5 s (spectral: 343 spheres, 3.5 s of wall on 2 threads at
    297c443; the 64 of before took 0.5 s once the solver kept its scratch per thread; spectral with the fast
    far field, issue 25: 512 spheres, 7.7 s of wall and 4.7 s of CPU on 2 threads under a load of 8, interrupted
    at 0.58 s)."""
    agglo = agglo_module
    baseline = _tasks()
    fired = []

    def interrupt():
        fired.append((time.monotonic(), _cpu_seconds()))
        _thread.interrupt_main()

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    try:
        with pytest.raises(agglo.InterruptedError):
            agglo.electrostatic_forces(*_lattice(n), solver=solver, min_gap=0.01, threads=2, **options)
    finally:
        timer.cancel()
    wall, cpu = time.monotonic(), _cpu_seconds()
    assert fired, "the solve ended before the interrupt"
    assert cpu - fired[0][1] < 2.0, cpu - fired[0][1]
    assert wall - fired[0][0] < 5.0, wall - fired[0][0]
    timer.join()
    assert _tasks_settle(baseline) <= baseline  # the worker thread and its OpenMP team are gone


def _cpu_seconds():
    """User + system CPU time of the process, all threads [s]."""
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


_SIGINT_CHILD = r"""
import sys, time
import numpy as np
import agglo
k = np.arange(8)  # 512 spheres: the whole solve takes about 12 s on an idle core (64 took 1.2 s, a race)
x = np.stack(np.meshgrid(k, k, k, indexing="ij"), -1).reshape(-1, 3) * 2.02e-5
q = np.where(np.arange(len(x)) % 2 == 0, 1.0, -1.0) * 1e-14
print("solving", flush=True)
start = time.monotonic()
try:
    agglo.electrostatic_forces(x, 1e-5, q, 3.8, min_gap=0.01, threads=1, target_accuracy=1e-6)
except agglo.InterruptedError:
    print(f"interrupted after {time.monotonic() - start:.2f} s", flush=True)
    raise
print("finished", flush=True)
"""


def test_sigint_stops_electrostatic_forces_in_a_subprocess(agglo_module, tmp_path):
    """A real SIGINT (the terminal's Ctrl-C) sent to a Python process inside electrostatic_forces: Python's
    handler sets its flag, the waiting thread sees it (PyErr_CheckSignals) and cancels the solve, which
    polls the token; the process ends with KeyboardInterrupt (agglo.InterruptedError) after at most one
    second of CPU time (one solver thread) instead of finishing the solve (about 12 s)."""
    import subprocess
    import sys
    path = [str(BUILD / "python"), os.environ.get("PYTHONPATH", "")]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in path if p))
    children = _children_cpu()
    child = subprocess.Popen([sys.executable, "-c", _SIGINT_CHILD], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=env)
    try:
        assert child.stdout.readline().strip() == "solving"
        time.sleep(1.0)  # inside the solve (its set-up alone takes longer)
        before = _child_cpu(child.pid)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=30)
        wall = time.monotonic() - sent
    finally:
        child.kill()
    assert child.returncode != 0 and "agglo.InterruptedError: interrupted" in err, (out, err)
    assert "interrupted after" in out and "finished" not in out, out
    after = _children_cpu() - children - before  # the child's CPU time after the signal
    assert after < 1.0, after
    assert wall < 5.0, wall


def _children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _child_cpu(pid):
    """User + system CPU seconds of a running process (None once gone)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
    except OSError:
        return None
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _gomp_spincount(env):
    """GOMP_SPINCOUNT that libgomp reports (OMP_DISPLAY_ENV=verbose) when a fresh Python imports agglo."""
    import re
    import subprocess
    import sys
    env = dict(env) | {"OMP_DISPLAY_ENV": "verbose", "PYTHONPATH": str(BUILD / "python")}
    proc = subprocess.run([sys.executable, "-c", "import agglo"], capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    m = re.search(r"GOMP_SPINCOUNT = '(\d+)'", proc.stderr)
    if m is None:
        pytest.skip("the OpenMP runtime is not libgomp (no GOMP_SPINCOUNT in OMP_DISPLAY_ENV)")
    return int(m.group(1))


def test_import_sets_short_openmp_spin_waits():
    """Importing agglo (which loads libgomp) makes OpenMP threads spin 1000 iterations and then sleep unless
    the user chose (apps/agglo/omp_wait/omp_wait.cpp; docs/acoustics.md §5.2): libgomp's default spin made two
    threads slower than one on a shared machine, sleeping at once cost a wake-up at every barrier."""
    base = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    assert _gomp_spincount(base) == 1000
    assert _gomp_spincount(base | {"OMP_WAIT_POLICY": "passive"}) == 0
    assert _gomp_spincount(base | {"OMP_WAIT_POLICY": "active"}) > 1000000
    assert _gomp_spincount(base | {"GOMP_SPINCOUNT": "1234"}) == 1234
