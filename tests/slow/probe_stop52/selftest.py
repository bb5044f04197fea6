"""Checks gen_exact.py's constructions without the tool: e on P's surface and on its support plane
along n, c on C's and on its support plane along -n, F(n) = -gap, and no direction beats n (a
global search, then long-double refinement).  usage: python3 selftest.py cases.jsonl"""
import json, sys
import numpy as np
from common import LD, ld, pair_fn, minimize, refine, bounding_radius, h_world, signed_distance, EPS

worst = {}
def note(k, v, cid):
    if v > worst.get(k, (0, ""))[0]: worst[k] = (v, cid)

for l in open(sys.argv[1]):
    c = json.loads(l)
    P, pa, C, pb, exp = c["a"], c["pa"], c["b"], c["pb"], c["exp"]
    if exp["n"] is None: continue   # no construction to check (check.py searches instead)
    size = bounding_radius(P) + bounding_radius(C)
    T = max(np.max(np.abs(pa["t"])), np.max(np.abs(pb["t"])))
    n = np.array(exp["n"]); e = np.array(exp["e"]); cc = np.array(exp["c"])
    note("e_support_plane", abs(n @ e - h_world(P, pa, n)) / size, c["id"])
    note("c_support_plane", abs(-n @ cc - h_world(C, pb, -n)) / size, c["id"])
    for nm, s, p, x in (("e_surface", P, pa, e), ("c_surface", C, pb, cc)):
        d = signed_distance(s, p, x)
        if d is not None: note(nm, abs(d) / size, c["id"])
    F = pair_fn(P, pa, C, pb, LD)
    fn = float(F(ld(n)[None, :])[0])
    note("F(n)+gap", abs(fn + exp["gap"]) / size, c["id"])
    if exp["gap"] > 0:
        v, u = minimize(pair_fn(P, pa, C, pb), ngrid=8000, nstarts=4, extra=[n])
        v2, _ = refine(F, u, r0=1e-5)
        note("beaten_sep", max(0.0, fn - float(v2)) / size, c["id"])
for k, (v, cid) in sorted(worst.items()):
    print(f"{k:18s} {v:.2e}  {cid}")
