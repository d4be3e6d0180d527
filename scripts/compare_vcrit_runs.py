#!/usr/bin/env python3
"""Compares two `agglo vcrit` output folders run by run (their journal.jsonl): the outcome (broken,
undecided, projectile contact) of every speed both tried, the speeds only one tried, the brackets and
v_crit; prints steps, electrostatic solves and the runs' summed seconds of each. Exit 1 when an outcome
or v_crit differs. Usage: scripts/compare_vcrit_runs.py BEFORE_DIR AFTER_DIR"""
import json
import sys


def runs(d):
    out = {}
    for line in open(d + "/journal.jsonl"):
        j = json.loads(line)
        out[j["result"]["speed_m_per_s"]] = (j["result"], j["seconds"])
    return out


def main(a, b):
    ra, rb = runs(a), runs(b)
    key = lambda r: (r["broken"], r["undecided"], r["projectile_contact"])
    differ = 0
    for v in sorted(set(ra) | set(rb)):
        if v not in ra or v not in rb:
            print(f"v = {v:.6f} m/s  only in {'before' if v in ra else 'after'}")
            differ += 1
            continue
        (x, sx), (y, sy) = ra[v], rb[v]
        bad = key(x) != key(y)
        differ += bad
        print(f"v = {v:.6f} m/s  broken {x['broken']!s:5} undecided {x['undecided']!s:5}  steps {x['steps']:7d} -> "
              f"{y['steps']:7d}  solves {x['electrostatic_solves']:6d} -> {y['electrostatic_solves']:6d}  "
              f"{sx:6.1f} -> {sy:6.1f} s{'  DIFFERENT' if bad else ''}")
    va, vb = (json.load(open(d + "/vcrit.json")) for d in (a, b))
    tot = lambda r: (sum(x["steps"] for x, _ in r.values()), sum(x["electrostatic_solves"] for x, _ in r.values()),
                     sum(s for _, s in r.values()))
    print("totals before: %d steps, %d solves, %.1f s; after: %d steps, %d solves, %.1f s" % (tot(ra) + tot(rb)))
    print(f"v_crit before {va['v_crit']:.6f} {va['bracket']}, after {vb['v_crit']:.6f} {vb['bracket']}; "
          f"{differ} of {len(set(ra) | set(rb))} speeds differ")
    return 1 if differ or va["v_crit"] != vb["v_crit"] else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
