"""Extreme scales and near-degenerate polytopes.  usage: gen_misc.py SEED N > cases.jsonl"""
import json, sys, numpy as np
from oracle import bounding_radius, minimize, pair_fn
from shapes import Gen, quat_to_R, qmul, scale_shape

g = Gen(int(sys.argv[1]))
N = int(sys.argv[2])
rng = g.rng
cases = []
ALL = ["contact", "intersect", "distance", "manifold"]

def vec(v): return [float(x) for x in v]

def add(cat, a, pa, b, pb, **kw):
    c = {"cat": cat, "a": a, "pa": pa, "b": b, "pb": pb, "wants": ALL, "variants": True}
    c.update(kw); cases.append(c)

def at_target(a, pa, b, pb, target):
    """move B along the oracle's normal so that the signed depth is about target"""
    s, u = minimize(pair_fn(a, pa, b, pb), ngrid=8000, nstarts=4)
    pb = dict(pb); pb["t"] = vec(np.array(pb["t"]) + (s - target) * u)
    return pb

def rand_pair_poses(a, b, origin, frac=(0.2, 1.0)):
    size = bounding_radius(a) + bounding_radius(b)
    pa = {"t": vec(np.array(origin) + rng.normal(size=3) * 0.1 * size), "q": g.rquat()}
    d = rng.normal(size=3); d /= np.linalg.norm(d)
    pb = {"t": vec(np.array(pa["t"]) + d * g.U(*frac) * size), "q": g.rquat()}
    return pa, pb

def target_of(size, small):
    m = rng.integers(3)
    if m == 0: return small * g.LU(1e-6, 0.5)       # penetrating
    if m == 1: return -small * g.LU(1e-6, 0.5)      # separated
    return small * rng.choice([-1, 1]) * g.LU(1e-13, 1e-9) * size / small  # nearly touching

# ---- extreme scales ----
for i in range(N):
    # both shapes tiny or huge
    k = float(rng.choice([1e-6, 1e6]))
    a, b = scale_shape(g.any_shape(1.0), k), scale_shape(g.any_shape(g.LU(0.3, 1)), k)
    pa, pb = rand_pair_poses(a, b, rng.normal(size=3) * k)
    size = bounding_radius(a) + bounding_radius(b)
    pb = at_target(a, pa, b, pb, target_of(size, size))
    add("scale_" + ("tiny" if k < 1 else "huge"), a, pa, b, pb, margin=size * g.LU(1e-4, 0.1), scale=k)

for i in range(N):
    # size ratio up to 1e6: a small shape against a huge box / polytope / cylinder / cone / rounded box
    ratio = g.LU(1e2, 1e6)
    big = g.basic(1.0, ["box", "polytope", "cylinder", "cone", "capsule"])
    if rng.uniform() < 0.2: big = {"type": "rounded", "shape": big, "radius": g.U(0.01, 0.2)}
    small = scale_shape(g.basic(1.0, ["sphere", "box", "capsule", "cylinder", "cone", "polytope", "point", "triangle", "segment"]), 1 / ratio)
    a, b = (big, small) if rng.uniform() < 0.5 else (small, big)
    pa, pb = rand_pair_poses(a, b, rng.normal(size=3), frac=(0.5, 1.0))
    size = bounding_radius(a) + bounding_radius(b)
    pb = at_target(a, pa, b, pb, target_of(size, bounding_radius(small)))
    add("size_ratio", a, pa, b, pb, margin=bounding_radius(small) * g.LU(0.1, 2), ratio=ratio)

for i in range(N):
    # unit shapes 1e6..1e8 from the origin
    off = rng.normal(size=3); off *= g.LU(1e6, 1e8) / np.linalg.norm(off)
    a, b = g.any_shape(1.0), g.any_shape(g.LU(0.3, 1))
    pa, pb = rand_pair_poses(a, b, off)
    size = bounding_radius(a) + bounding_radius(b)
    pb = at_target(a, pa, b, pb, target_of(size, size) if rng.uniform() < 0.7 else size * g.LU(1e-7, 1e-3) * rng.choice([-1, 1]))
    add("far", a, pa, b, pb, margin=size * g.LU(1e-4, 0.1), far=float(np.linalg.norm(off)))

# ---- near-degenerate polytopes ----
def degen_poly():
    k = int(rng.integers(6))
    if k == 0: return "flat_thick", g.poly_flat(1.0, g.LU(1e-12, 1e-7))
    if k == 1:  # flat polygon + apex at tiny height (flat pyramid)
        p = g.poly_flat(1.0, None); P = np.array(p["points"])
        nrm = np.cross(P[1] - P[0], P[2] - P[0]); nrm /= np.linalg.norm(nrm)
        apex = P.mean(axis=0) + nrm * g.LU(1e-12, 1e-7)
        return "flat_pyramid", {"type": "polytope", "points": p["points"] + [vec(apex)]}
    if k == 2:  # many duplicates of a near-coplanar set
        p = g.poly_flat(1.0, g.LU(1e-12, 1e-7)); P = p["points"]
        idx = rng.integers(len(P), size=int(rng.integers(50, 300)))
        return "flat_dups", {"type": "polytope", "points": P + [P[int(i)] for i in idx]}
    if k == 3: return "needle", g.poly_needle(1.0, g.LU(1e-12, 1e-7))
    if k == 4:  # needle with points along it, offset by tiny amounts
        d = rng.normal(size=3); d /= np.linalg.norm(d)
        ts = rng.uniform(-1, 1, size=int(rng.integers(4, 40)))
        P = ts[:, None] * d + rng.normal(size=(len(ts), 3)) * g.LU(1e-12, 1e-7)
        return "needle_line", {"type": "polytope", "points": [vec(p) for p in P]}
    # a slab: polygon and a copy shifted by a tiny amount along its normal
    p = g.poly_flat(1.0, None); P = np.array(p["points"])
    nrm = np.cross(P[1] - P[0], P[2] - P[0]); nrm /= np.linalg.norm(nrm)
    return "slab", {"type": "polytope", "points": [vec(x) for x in np.concatenate([P, P + nrm * g.LU(1e-12, 1e-7)])]}

for i in range(2 * N):
    kind, poly = degen_poly()
    other = g.any_shape(g.LU(0.3, 1), ["sphere", "box", "capsule", "cylinder", "cone", "ellipsoid", "polytope", "triangle", "segment"]) if rng.uniform() < 0.8 else degen_poly()[1]
    a, b = (poly, other) if rng.uniform() < 0.5 else (other, poly)
    pa, pb = rand_pair_poses(a, b, rng.normal(size=3))
    size = bounding_radius(a) + bounding_radius(b)
    pb = at_target(a, pa, b, pb, target_of(size, size))
    add("degen_" + kind, a, pa, b, pb, margin=size * g.LU(1e-4, 0.1))

for i, c in enumerate(cases):
    c["id"] = f"x{i}"
    print(json.dumps(c))
