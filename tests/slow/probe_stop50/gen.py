import json, sys, numpy as np
from oracle import bounding_radius, minimize, pair_fn

from helpers import *  # the random shapes, poses and the seed (argv[1])

N = int(sys.argv[2]) if len(sys.argv) > 2 else 150
for i in range(N):
    L = 1.0
    add("sum_box_sphere", {"type": "sum", "shapes": [basic(L, ["box"]), basic(0.5, ["sphere"])]}, any_shape(L))
    add("sum_cyl_cone", {"type": "sum", "shapes": [basic(L, ["cylinder"]), basic(L, ["cone"])]}, any_shape(L))
    add("sum_poly_seg", {"type": "sum", "shapes": [basic(L, ["polytope"]), basic(L, ["segment"])]}, any_shape(L))
    add("sum_ell_box", {"type": "sum", "shapes": [basic(L, ["ellipsoid"]), basic(L, ["box"])]}, any_shape(L))
    add("sum_vs_sum", {"type": "sum", "shapes": [basic(L), basic(L)]}, {"type": "sum", "shapes": [basic(L), basic(L)]})
    add("rounded", {"type": "rounded", "shape": basic(L, ["box", "polytope", "cylinder", "cone", "triangle", "segment"]), "radius": L*U(0.001, 0.5)}, any_shape(L))
    add("tri_seg", basic(L, ["triangle", "segment"]), basic(L, ["triangle", "segment", "box", "sphere", "cylinder", "cone", "ellipsoid", "polytope", "capsule"]))
    # degenerate polytopes
    k = rng.integers(4)
    P = np.array(pts(int(rng.integers(4, 12)), L))
    if k == 0:  # duplicates
        P = np.concatenate([P, P[rng.integers(len(P), size=len(P))]])
    elif k == 1:  # coplanar
        P[:, 2] = 0.0
    elif k == 2:  # 4 almost coplanar
        P = P[:4]; P[:, 2] = 0.0; P[3, 2] = 10**U(-12, -4)
    else:  # coplanar points + interior points, cube-ish with face points
        c = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float) * U(0.3, 1)
        extra = c[rng.integers(8, size=6)] * 0.5 + c[rng.integers(8, size=6)] * 0.5
        P = np.concatenate([c, extra, c[:3]])
    poly = {"type": "polytope", "points": [[f(c) for c in p] for p in P]}
    add("degen_poly", poly, any_shape(L))
    # flat boxes
    he = [L*U(0.1, 1) for _ in range(3)]; he[rng.integers(3)] = 0.0
    if rng.uniform() < 0.2: he[(rng.integers(2) + 1) % 3] = 0.0
    add("flat_box", {"type": "box", "half_extents": he}, any_shape(L) if rng.uniform() < 0.6 else {"type": "box", "half_extents": [L*U(0.1, 1), 0.0, L*U(0.1, 1)]})
    # far from origin
    off = rng.normal(size=3); off *= 10**U(4, 6) / np.linalg.norm(off)
    add("far", any_shape(L), any_shape(L), origin=off)
    # size ratio
    s = 10**U(-3, 3)
    a, b = any_shape(1.0), any_shape(s)
    add("size_ratio", a, b)
    # random general
    add("random", any_shape(L), any_shape(L))

# nearly parallel faces
for i in range(N):
    ang = 10**U(-9, -2)
    t = rng.integers(5)
    he = [U(0.3, 1) for _ in range(3)]
    qa = rquat()
    # A box/poly face with normal along A's local z, B resting on it
    if t == 0:
        a = {"type": "box", "half_extents": he}; b = {"type": "box", "half_extents": [U(0.1, 1) for _ in range(3)]}
        hb = b["half_extents"][2]
    elif t == 1:
        a = {"type": "box", "half_extents": he}; b = {"type": "cylinder", "radius": U(0.1, 1), "half_height": U(0.1, 1)}
        hb = b["half_height"]
    elif t == 2:
        a = {"type": "rounded", "shape": {"type": "box", "half_extents": he}, "radius": U(0.01, 0.3)}
        b = {"type": "sum", "shapes": [{"type": "box", "half_extents": [U(0.1, 1), U(0.1, 1), U(0.1, 0.5)]}, {"type": "sphere", "radius": U(0.01, 0.3)}]}
        hb = b["shapes"][0]["half_extents"][2] + b["shapes"][1]["radius"]
    elif t == 3:
        c = [[x*he[0], y*he[1], z*he[2]] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
        a = {"type": "polytope", "points": c}
        b = {"type": "triangle", "points": [[U(-1, 1), U(-1, 1), 0.0] for _ in range(3)]}
        hb = 0.0
    else:
        a = {"type": "box", "half_extents": he}
        b = {"type": "sum", "shapes": [{"type": "triangle", "points": [[U(-1, 1), U(-1, 1), 0.0] for _ in range(3)]}, {"type": "cylinder", "radius": U(0.05, 0.3), "half_height": U(0.05, 0.3)}]}
        hb = b["shapes"][1]["half_height"]
    ha = a.get("half_extents", he)[2] if a["type"] != "rounded" else he[2] + a["radius"]
    if a["type"] == "polytope": ha = he[2]
    gap = rng.choice([0.0, 1.0, -1.0]) * 10**U(-12, -2)
    from oracle import quat_to_R
    RA = quat_to_R(qa)
    local = np.array([U(-0.3, 0.3)*he[0], U(-0.3, 0.3)*he[1], ha + hb + gap])
    tA = np.array([U(-1, 1), U(-1, 1), U(-1, 1)])
    tB = tA + RA @ local
    qb = qmul(qa, small_quat(ang))
    add("parallel_faces", a, b, {"t": [f(v) for v in tA], "q": qa}, {"t": [f(v) for v in tB], "q": qb})

# touching: take pairs from the first categories, move B along the oracle's normal by the oracle's depth
base = [c for c in cases if c["cat"] in ("sum_box_sphere", "sum_cyl_cone", "sum_poly_seg", "sum_ell_box", "sum_vs_sum", "rounded", "tri_seg", "degen_poly", "flat_box", "random")]
sel = rng.choice(len(base), size=min(len(base), N * 3), replace=False)
for j in sel:
    c = base[j]
    s, u = minimize(pair_fn(c["a"], c["pa"], c["b"], c["pb"]), ngrid=20000)
    tB = np.array(c["pb"]["t"]) + s * u
    cases.append({"cat": "touching", "src": c["cat"], "a": c["a"], "pa": c["pa"], "b": c["b"],
                  "pb": {"t": [f(v) for v in tB], "q": c["pb"]["q"]}})

for i, c in enumerate(cases):
    c["id"] = i
    print(json.dumps(c))
