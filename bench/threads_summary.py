#!/usr/bin/python3
"""Medians and thread ratios of a table of timed runs (bench/dem_threads.sh; usable by any script that
times variants of one thread against several in rounds).

TABLE is tab-separated with a header and the columns SYSTEM (what was run), variant, round, wall_s, CPU
(the CPU seconds column) and load (1-min load average). Per system: the median wall and CPU of each
variant, and for each the speed-up wall(one) / wall(variant) and CPU(variant) / CPU(one), where `one` is
ONE (e.g. t1), or ONE_before for a variant ending in _before.

  bench/threads_summary.py TABLE [--system system] [--cpu cpu_s] [--one t1]
"""
import argparse
import csv
import statistics


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("table")
    ap.add_argument("--system", default="system")
    ap.add_argument("--cpu", default="cpu_s")
    ap.add_argument("--one", default="t1")
    a = ap.parse_args()
    with open(a.table) as f:
        table = list(csv.DictReader(f, delimiter="\t"))
    for name in dict.fromkeys(r[a.system] for r in table):
        mine = [r for r in table if r[a.system] == name]
        variants = dict.fromkeys(r["variant"] for r in mine)
        medians = {v: (statistics.median(float(r["wall_s"]) for r in mine if r["variant"] == v),
                       statistics.median(float(r[a.cpu]) for r in mine if r["variant"] == v)) for v in variants}
        rounds = len({r["round"] for r in mine})
        load = [float(r["load"]) for r in mine]
        print(f"{name}: medians over {rounds} rounds (1-min load average {min(load):.1f}-{max(load):.1f})")
        for v, (wall, cpu) in medians.items():
            one = a.one + "_before" if v.endswith("_before") else a.one
            ref = medians.get(one)
            ratio = (f"  speed-up {ref[0] / wall:.2f}x, CPU {cpu / ref[1]:.2f}x of {one}"
                     if ref and wall > 0 and ref[1] > 0 else "")
            print(f"  {v:16s} wall {wall:8.3f} s  CPU {cpu:8.3f} s{ratio}")


if __name__ == "__main__":
    main()
