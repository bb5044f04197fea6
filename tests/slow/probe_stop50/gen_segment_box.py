import json, sys, numpy as np
from helpers import *
from oracle import bounding_radius, minimize, pair_fn
N = int(sys.argv[2])
def seg(k):
    p = pts(2, 1.0)
    return [{"type": "segment", "points": p},
            {"type": "capsule", "radius": 0.0, "half_height": U(0.1, 1)},
            {"type": "capsule", "radius": 1e-9, "half_height": U(0.1, 1)},
            {"type": "rounded", "shape": {"type": "segment", "points": p}, "radius": 0.0},
            {"type": "sum", "shapes": [{"type": "segment", "points": p}, {"type": "point", "points": [[0.0, 0.0, 0.0]]}]},
            {"type": "cylinder", "radius": 0.0, "half_height": U(0.1, 1)}][k]
names = ["segment", "capsule_r0", "capsule_r1e-9", "rounded_seg_r0", "sum_seg_point", "cylinder_r0"]
for i in range(N):
    for k in range(6):
        for flat in (False, True):
            a = seg(k)
            he = [U(0.1, 1) for _ in range(3)]
            if flat: he[rng.integers(3)] = 0.0
            b = {"type": "box", "half_extents": he}
            pa, pb = place(a, b)
            s, u = minimize(pair_fn(a, pa, b, pb), ngrid=20000)
            size = bounding_radius(a) + bounding_radius(b)
            g = 10**U(-13, -5) * size
            tB = np.array(pb["t"]) + (s + g) * u
            add(f"segbox:{names[k]}-{'flatbox' if flat else 'box'}", a, b, pa, {"t": [f(v) for v in tB], "q": pb["q"]})
            cases[-1]["gap_rel"] = g / size
for i, c in enumerate(cases):
    c["id"] = 400000 + i
    print(json.dumps(c))
