"""Manifold cases: random pairs of every kind moved to a chosen depth or gap, and resting contact.
usage: gen_manifold.py SEED N > cases.jsonl"""
import json, sys, numpy as np
from oracle import bounding_radius, minimize, pair_fn
from shapes import Gen, quat_to_R, qmul

g = Gen(int(sys.argv[1]))
N = int(sys.argv[2])
rng = g.rng
cases = []

def add(cat, a, pa, b, pb, **kw):
    c = {"cat": cat, "a": a, "pa": pa, "b": b, "pb": pb, "wants": ["contact", "manifold"], "variants": True}
    c.update(kw)
    cases.append(c)

def vec(v): return [float(x) for x in v]

# 1. random pairs of every kind at a chosen depth / gap
for i in range(N):
    a, b = g.any_shape(1.0), g.any_shape(g.LU(0.3, 1.0))
    size = bounding_radius(a) + bounding_radius(b)
    pa = {"t": vec(rng.normal(size=3)), "q": g.rquat()}
    d = rng.normal(size=3); d /= np.linalg.norm(d)
    pb = {"t": vec(np.array(pa["t"]) + d * g.U(0.2, 1.0) * size), "q": g.rquat()}
    s, u = minimize(pair_fn(a, pa, b, pb), ngrid=8000, nstarts=4)
    mode = rng.integers(4)
    if mode == 0: target, margin = size * g.LU(1e-6, 0.2), None
    elif mode == 1: target, margin = size * g.LU(1e-6, 0.2), size * g.LU(1e-4, 0.1)
    elif mode == 2:
        gap = size * g.LU(1e-7, 0.05); target, margin = -gap, gap * g.U(1.2, 4)
    else:
        gap = size * g.LU(1e-4, 0.05); target, margin = -gap, gap * g.U(0.2, 0.8)
    pb["t"] = vec(np.array(pb["t"]) + (s - target) * u)
    kw = {"target": target}
    if margin is not None: kw["margin"] = margin
    add("man_random", a, pa, b, pb, **kw)

# 2. resting contact: a feature of B resting on the top face (local +z) of A, tilted slightly
def big_face_shape():
    k = rng.integers(5)
    hx, hy, hz = g.U(1.5, 3), g.U(1.5, 3), g.U(0.2, 1)
    if k == 0: return {"type": "box", "half_extents": [hx, hy, hz]}, hz
    if k == 1: return {"type": "polytope", "points": [[x*hx, y*hy, z*hz] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]}, hz
    if k == 2:
        r = g.U(0.01, 0.2)
        return {"type": "rounded", "shape": {"type": "box", "half_extents": [hx, hy, hz]}, "radius": r}, hz + r
    if k == 3: return {"type": "cylinder", "radius": g.U(2.5, 3.5), "half_height": hz}, hz
    return g.prism(int(rng.integers(5, 12)), g.U(3, 4), hz, even=True), hz

def rester():
    """(shape, q in A's face frame, height of its lowest point above its origin, expected count)"""
    k = int(rng.integers(11))
    flat = [1, 0, 0, 0]
    if k == 0:
        he = [g.U(0.1, 0.8), g.U(0.1, 0.8), g.U(0.05, 0.5)]
        return "box", {"type": "box", "half_extents": he}, g.axis_quat(g.U(0, 6.28), [0, 0, 1]), he[2], 4
    if k == 1:
        n = int(rng.integers(3, 9)); hz = g.U(0.05, 0.5)
        return f"prism{n}", g.prism(n, g.U(0.2, 0.8), hz), flat, hz, min(n, 4)
    if k == 2:
        he = [g.U(0.1, 0.8), g.U(0.1, 0.8), g.U(0.05, 0.5)]; r = g.U(0.01, 0.2)
        return "rounded_box", {"type": "rounded", "shape": {"type": "box", "half_extents": he}, "radius": r}, flat, he[2] + r, 4
    if k == 3:
        he = [g.U(0.1, 0.8), g.U(0.1, 0.8), g.U(0.05, 0.5)]; r = g.U(0.01, 0.2)
        return "sum_box_sphere", {"type": "sum", "shapes": [{"type": "box", "half_extents": he}, {"type": "sphere", "radius": r}]}, flat, he[2] + r, 4
    if k == 4:
        r, h = g.U(0.05, 0.5), g.U(0.1, 0.8)
        return "capsule_lying", {"type": "capsule", "radius": r, "half_height": h}, g.axis_quat(np.pi / 2, [np.cos(th := g.U(0, 6.28)), np.sin(th), 0]), r, 2
    if k == 5:
        r, h = g.U(0.1, 0.8), g.U(0.05, 0.8)
        return "cylinder_standing", {"type": "cylinder", "radius": r, "half_height": h}, flat, h, 4
    if k == 6:
        r, h = g.U(0.1, 0.8), g.U(0.05, 0.8)
        return "cylinder_lying", {"type": "cylinder", "radius": r, "half_height": h}, g.axis_quat(np.pi / 2, [np.cos(th := g.U(0, 6.28)), np.sin(th), 0]), r, 2
    if k == 7:
        r, h = g.U(0.1, 0.8), g.U(0.05, 0.8)
        return "cone_standing", {"type": "cone", "radius": r, "half_height": h}, flat, h, 4
    if k == 8:
        P = [[g.U(-0.8, 0.8), g.U(-0.8, 0.8), 0.0] for _ in range(3)]
        return "triangle_flat", {"type": "triangle", "points": P}, flat, 0.0, 3
    if k == 9:
        P = [[g.U(-0.8, 0.8), g.U(-0.8, 0.8), 0.0] for _ in range(2)]
        return "segment_flat", {"type": "segment", "points": P}, flat, 0.0, 2
    r = g.U(0.05, 0.3)
    return "rounded_triangle_flat", {"type": "rounded", "shape": {"type": "triangle", "points": [[g.U(-0.8, 0.8), g.U(-0.8, 0.8), 0.0] for _ in range(3)]}, "radius": r}, flat, r, 3

for i in range(N):
    A, ha = big_face_shape()
    name, B, qloc, hb, expect = rester()
    tilt = g.LU(1e-9, 1e-4) if rng.uniform() < 0.85 else 0.0
    qloc = qmul(g.tilt_quat(tilt), qloc) if tilt else qloc
    extent = bounding_radius(B)
    spread = 2 * tilt * extent + 1e-12
    mode = rng.integers(3)
    margin = None
    if mode == 0: pen = g.LU(max(4 * spread, 1e-6), 1e-2)
    elif mode == 1: pen = g.LU(max(4 * spread, 1e-6), 1e-2); margin = g.LU(1e-4, 1e-2)
    else:
        gap = g.LU(1e-6, 1e-2); pen = -gap; margin = gap + 4 * spread + g.LU(1e-5, 1e-2)
    qa = g.rquat(); RA = quat_to_R(qa)
    tA = rng.normal(size=3)
    # B's origin: above a point of A's face well inside, so that B's footprint stays on the face
    lx = g.U(-0.3, 0.3); ly = g.U(-0.3, 0.3)
    local = np.array([lx, ly, ha + hb - pen])
    tB = tA + RA @ local
    qb = qmul(qa, qloc)
    pa = {"t": vec(tA), "q": qa}; pb = {"t": vec(tB), "q": qb}
    kw = {"expect_count": expect, "rest": name, "tilt": tilt, "target": pen}
    if margin is not None: kw["margin"] = margin
    if rng.uniform() < 0.5:
        add("man_resting", A, pa, B, pb, **kw)
    else:
        add("man_resting_swapped", B, pb, A, pa, **kw)

for i, c in enumerate(cases):
    c["id"] = f"m{i}"
    print(json.dumps(c))
