"""A [[particles]] list of N touching polydisperse charged spheres (used by tests/cli/*.sh; not a test).

A random sequential cluster (fixed seed): each sphere touches an earlier one with a 1 nm overlap and
overlaps no other; radii 5-15 um, charges alternating +-10 uC/m^2 x 4 pi r^2, permittivity KAPPA.
Usage: list_cluster.py N KAPPA [DETACHED]  (DETACHED: index of a sphere moved off to touch nothing)
"""
import math
import random
import sys

n = int(sys.argv[1])
kappa = float(sys.argv[2])
detached = int(sys.argv[3]) if len(sys.argv) > 3 else -1
rng = random.Random(7)
pts = []
while len(pts) < n:
    r = rng.uniform(5e-6, 15e-6)
    if not pts:
        pts.append(((0.0, 0.0, 0.0), r))
        continue
    parent, rp = pts[rng.randrange(len(pts))]
    u = [rng.gauss(0, 1) for _ in range(3)]
    s = math.sqrt(sum(x * x for x in u))
    d = rp + r - 1e-9
    x = tuple(parent[i] + d * u[i] / s for i in range(3))
    if all(math.dist(x, q) >= rq + r for q, rq in pts if q is not parent):
        pts.append((x, r))
if detached >= 0:  # far from every other sphere
    (x, r) = pts[detached]
    pts[detached] = ((x[0], x[1], x[2] + 1e-3), r)
for k, (x, r) in enumerate(pts):
    q = (1 if k % 2 == 0 else -1) * 10e-6 * 4 * math.pi * r * r
    print(f"[[particles]]\nposition = [{x[0]:.9e}, {x[1]:.9e}, {x[2]:.9e}]\nradius = {r:.9e}\n"
          f"charge = {q:.6e}\npermittivity = {kappa}\n")
