import json, sys, numpy as np
from oracle import bounding_radius, minimize, pair_fn

rng = np.random.default_rng(int(sys.argv[1]) if len(sys.argv) > 1 else 50)

def f(x): return float(x)
def U(a, b): return f(rng.uniform(a, b))

def rquat():
    q = rng.normal(size=4); q /= np.linalg.norm(q)
    return [f(v) for v in q]

def small_quat(ang):
    ax = rng.normal(size=3); ax /= np.linalg.norm(ax)
    return [f(np.cos(ang/2))] + [f(v) for v in np.sin(ang/2)*ax]

def qmul(a, b):
    w1, x1, y1, z1 = a; w2, x2, y2, z2 = b
    q = np.array([w1*w2 - x1*x2 - y1*y2 - z1*z2, w1*x2 + x1*w2 + y1*z2 - z1*y2,
                  w1*y2 - x1*z2 + y1*w2 + z1*x2, w1*z2 + x1*y2 - y1*x2 + z1*w2])
    q /= np.linalg.norm(q)
    return [f(v) for v in q]

def pts(n, L, spread=1.0):
    P = rng.normal(size=(n, 3)) * L * np.array([U(0.3, 1), U(0.3, 1), U(0.3, 1)])
    return [[f(c) for c in p] for p in P]

def basic(L, kinds=None):
    kinds = kinds or ["sphere", "box", "capsule", "cylinder", "cone", "ellipsoid", "polytope",
                      "segment", "triangle", "point"]
    k = kinds[rng.integers(len(kinds))]
    if k == "sphere": return {"type": "sphere", "radius": L*U(0.3, 1)}
    if k == "box": return {"type": "box", "half_extents": [L*U(0.1, 1) for _ in range(3)]}
    if k in ("capsule", "cylinder", "cone"):
        return {"type": k, "radius": L*U(0.1, 1), "half_height": L*U(0.1, 1)}
    if k == "ellipsoid": return {"type": "ellipsoid", "radii": [L*U(0.2, 1) for _ in range(3)]}
    if k == "polytope": return {"type": "polytope", "points": pts(int(rng.integers(4, 24)), L)}
    if k == "segment": return {"type": "segment", "points": pts(2, L)}
    if k == "triangle": return {"type": "triangle", "points": pts(3, L)}
    if k == "point": return {"type": "point", "points": pts(1, 0.3*L)}
    raise ValueError(k)

def any_shape(L):
    r = rng.uniform()
    if r < 0.5: return basic(L)
    if r < 0.75: return {"type": "sum", "shapes": [basic(0.6*L), basic(0.6*L)]}
    return {"type": "rounded", "shape": basic(L), "radius": L*U(0.01, 0.5)}

def place(a, b, origin=(0, 0, 0), qa=None, qb=None, frac=None):
    ra, rb = bounding_radius(a), bounding_radius(b)
    d = rng.normal(size=3); d /= np.linalg.norm(d)
    frac = U(0.0, 1.2) if frac is None else frac
    tA = np.array(origin, float) + rng.normal(size=3) * 0.1 * (ra + rb)
    tB = tA + d * frac * (ra + rb)
    return ({"t": [f(v) for v in tA], "q": qa or rquat()}, {"t": [f(v) for v in tB], "q": qb or rquat()})

cases = []
def add(cat, a, b, pa=None, pb=None, **kw):
    if pa is None: pa, pb = place(a, b, **kw)
    cases.append({"cat": cat, "a": a, "pa": pa, "b": b, "pb": pb})

