#!/usr/bin/python3
"""Serial fraction and Amdahl efficiency of a two-thread run from callgrind's per-thread counts
(issue 27 item 3; docs/acoustics.md §5.6, docs/benchmarks_dem.md §5).

Input: callgrind output of the same work run on one thread (ONE, a `--separate-threads=yes` file
ending in -01) and on T threads (MANY: the prefix of its files MANY-01, MANY-02, ...), both with
`--separate-threads=yes`; optionally the same pair for a shorter run (--minus ONE0 MANY0), whose
counts are subtracted (the difference leaves the steps between the two lengths: no start-up, no
output). STEP is the function that runs one step (inclusive counts; e.g. `Engine::step()`).

  T1        = STEP on the one-thread run
  serial    = STEP on thread 1 of MANY minus thread 1's GOMP_parallel (what runs outside the parallel
              regions) plus every --serial function (single-thread parts inside a region), on all threads
  parallel  = thread 1's GOMP_parallel + every other thread's total, minus the --serial functions
  Amdahl    T_T = serial + parallel / T; speed-up T1 / T_T, efficiency T1 / (T T_T)
Instructions only: no barrier wait, no cache effect, no other tenant of the machine.

  bench/callgrind_threads.py ONE MANY --step NAME [--serial NAME ...] [--minus ONE0 MANY0] [--per N]
--per N divides the printed counts by N (e.g. samples x steps).
"""
import argparse
import glob
import re
import subprocess


def parse_annotate(lines):
    """(total, {function name: largest inclusive count}) from the lines of `callgrind_annotate
    --inclusive=yes` (also used by bench/dsmc_sample_cost.sh)."""
    total, inc = 0, {}
    for line in lines:
        m = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+(.*)$", line)
        if not m:
            continue
        n, rest = int(m.group(1).replace(",", "")), m.group(2)
        if rest.startswith("PROGRAM TOTALS"):
            total = n
        elif ":" in rest:
            name = rest.split(":", 1)[1]
            inc[name] = max(inc.get(name, 0), n)
    return total, inc


def inclusive(path):
    """parse_annotate of one callgrind output file."""
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path],
                          capture_output=True, text=True, check=True).stdout
    return parse_annotate(text.splitlines())


def count(inc, key):
    """Largest inclusive count of a function whose name contains key (its clones are inside it)."""
    return max([v for k, v in inc.items() if key in k and "._omp_fn" not in k] or [0])


def split(one, many, step, serial_names):
    t1 = count(inclusive(one)[1], step)
    files = sorted(glob.glob(glob.escape(many) + "-[0-9][0-9]"))
    threads = [inclusive(f) for f in files]
    inside = sum(count(inc, s) for _, inc in threads for s in serial_names)
    first = threads[0][1]
    region1 = max([v for k, v in first.items() if k.startswith("GOMP_parallel ")] or [0])
    serial = count(first, step) - region1 + inside
    parallel = region1 + sum(total for total, _ in threads[1:]) - inside
    return t1, serial, parallel, len(files)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("one")
    ap.add_argument("many")
    ap.add_argument("--step", required=True)
    ap.add_argument("--serial", action="append", default=[])
    ap.add_argument("--minus", nargs=2)
    ap.add_argument("--per", type=float, default=1.0)
    a = ap.parse_args()
    t1, s, p, nt = split(a.one, a.many, a.step, a.serial)
    if a.minus:
        t10, s0, p0, _ = split(a.minus[0], a.minus[1], a.step, a.serial)
        t1, s, p = t1 - t10, s - s0, p - p0
    t_many = s + p / nt
    print(f"one thread: {t1 / a.per:.6g}; {nt} threads: serial {s / a.per:.6g}, parallel (all threads) "
          f"{p / a.per:.6g}")
    print(f"serial fraction {100 * s / t1:.2f} % of the one-thread count; Amdahl from instructions: "
          f"speed-up {t1 / t_many:.3f}, efficiency {t1 / (nt * t_many):.3f}")


if __name__ == "__main__":
    main()
