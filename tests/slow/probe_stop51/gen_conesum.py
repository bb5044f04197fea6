"""Manifold cases: sums holding a cone (cone + polytope/triangle/segment/point/box/capsule/cylinder)
against boxes, polytopes, capsules, at a chosen depth.  usage: gen_conesum.py SEED N"""
import json, sys, numpy as np
from oracle import bounding_radius, minimize, pair_fn
from shapes import Gen
g = Gen(int(sys.argv[1])); N = int(sys.argv[2]); rng = g.rng
def vec(v): return [float(x) for x in v]
for i in range(N):
    cone = {"type": "cone", "radius": g.U(0.1, 0.6), "half_height": g.U(0.05, 0.6)}
    other = g.basic(0.5, ["polytope", "triangle", "segment", "point", "box", "capsule", "cylinder", "sphere", "ellipsoid"])
    B = {"type": "sum", "shapes": [cone, other] if rng.uniform() < 0.5 else [other, cone]}
    A = g.basic(1.0, ["box", "polytope", "capsule", "triangle", "cylinder"])
    pa = {"t": vec(rng.normal(size=3)), "q": g.rquat()}
    size = bounding_radius(A) + bounding_radius(B)
    d = rng.normal(size=3); d /= np.linalg.norm(d)
    pb = {"t": vec(np.array(pa["t"]) + d * g.U(0.3, 1) * size), "q": g.rquat()}
    s, u = minimize(pair_fn(A, pa, B, pb), ngrid=6000, nstarts=3)
    tgt = size * g.LU(1e-5, 0.1)
    pb["t"] = vec(np.array(pb["t"]) + (s - tgt) * u)
    a, b, p1, p2 = (A, B, pa, pb) if rng.uniform() < 0.5 else (B, A, pb, pa)
    print(json.dumps({"id": f"c{i}", "cat": "cone_sum", "a": a, "pa": p1, "b": b, "pb": p2, "wants": ["contact", "manifold"], "variants": True, "target": tgt}))
