"""Pairs with an exactly known answer: a curved (or sphere-swept) shape C placed so that its
support point (or the middle of its support set) along -n lies exactly `gap` beyond a point e of
a face, edge or corner of a polyhedral shape P along n, with n inside that feature's normal cone.
Then (separated) distance = gap, normal = n (P -> C), point on P = e, point on C = c = e + gap n;
overlapping (gap < 0), n gives a separation of -gap and is checked to be the least by search.

usage: python3 gen_exact.py SEED N [general] > cases.jsonl
With `general`, the same shapes are placed at random and C is moved along a searched normal to
the wanted gap: no known answer (exp.n is null); check.py then takes a long-double search as
the reference.
Each case: id, cat (P kind:feature | C kind | regime | scale), a = P, pa, b = C, pb, and exp:
n, e, c (world, floats), gap, unique (whether C's support point along -n is the only one)."""
import json, sys
import numpy as np
from common import (LD, ld, unit, support_point, quat_of_R, quat_to_R, frame_with, spin, hull_faces,
                    polyhedral_points, bounding_radius, pose_of)

seed, N = int(sys.argv[1]), int(sys.argv[2])
GENERAL = len(sys.argv) > 3 and sys.argv[3] == "general"
rng = np.random.default_rng(seed)
U = lambda a, b: float(rng.uniform(a, b))
LU = lambda a, b: float(10 ** rng.uniform(np.log10(a), np.log10(b)))
def pick(xs, w=None):
    w = None if w is None else np.array(w, float) / np.sum(w)
    return xs[int(rng.choice(len(xs), p=w))]

def rrot():
    q = rng.normal(size=4); q /= np.linalg.norm(q)
    return quat_to_R(q)

def pts(n, L):
    P = rng.normal(size=(n, 3)) * L * np.array([U(0.4, 1) for _ in range(3)])
    return [[float(c) for c in p] for p in P]

# ------------------------------------------------------------------ polyhedral side P
def poly_shape(L):
    k = pick(["random", "sphere", "boxlike", "prism"])
    if k == "random": return {"type": "polytope", "points": pts(int(rng.integers(4, 20)), L)}
    if k == "sphere":
        P = rng.normal(size=(int(rng.integers(6, 36)), 3)); P /= np.linalg.norm(P, axis=1)[:, None]
        P *= L * np.array([U(0.3, 1) for _ in range(3)])
        return {"type": "polytope", "points": [[float(c) for c in p] for p in P]}
    if k == "boxlike":
        h = [L * U(0.1, 1) for _ in range(3)]
        P = [[sx * h[0], sy * h[1], sz * h[2]] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
        if rng.uniform() < 0.5:  # perturbed
            P = [[c + L * U(-0.05, 0.05) for c in p] for p in P]
        return {"type": "polytope", "points": [[float(c) for c in p] for p in P]}
    m = int(rng.integers(3, 9)); r = L * U(0.3, 1); hz = L * U(0.1, 1)
    ang = np.arange(m) * 2 * np.pi / m + U(0, 1)
    P = [[float(r * np.cos(a)), float(r * np.sin(a)), float(z)] for z in (-hz, hz) for a in ang]
    return {"type": "polytope", "points": P}

def small_part(L, kinds):
    k = pick(kinds)
    if k == "box": return {"type": "box", "half_extents": [L * U(0.1, 1) for _ in range(3)]}
    if k == "segment": return {"type": "segment", "points": pts(2, L)}
    if k == "triangle": return {"type": "triangle", "points": pts(3, L)}
    if k == "polytope": return {"type": "polytope", "points": pts(int(rng.integers(4, 9)), L)}
    raise ValueError(k)

def hull_feature(shape, feature):
    """a feature of a (full-dimensional) polyhedral shape: local e, n"""
    P = polyhedral_points(shape)
    F = hull_faces(P)
    if len(F) < 4: return None
    PL = ld(P)
    if feature == "face":
        nrm, o, idx = F[int(rng.integers(len(F)))]
        w = rng.dirichlet(np.ones(len(idx)))
        return ld(w) @ PL[idx], nrm
    if feature == "edge":
        pairs = []
        for i in range(len(F)):
            for j in range(i + 1, len(F)):
                sh = sorted(set(F[i][2]) & set(F[j][2]))
                if len(sh) >= 2:
                    Q = PL[sh]
                    D = np.max(np.abs(Q[:, None, :] - Q[None, :, :]), axis=2)
                    k1, k2 = np.unravel_index(np.argmax(D), D.shape)
                    if D[k1, k2] > 1e-6 * np.max(np.abs(PL)): pairs.append((i, j, Q[k1], Q[k2]))
        if not pairs: return None
        i, j, p1, p2 = pairs[int(rng.integers(len(pairs)))]
        t = LD(U(0.05, 0.95))
        w1, w2 = U(0.05, 1), U(0.05, 1)
        n = ld(w1) * F[i][0] + ld(w2) * F[j][0]
        return p1 + t * (p2 - p1), n / np.sqrt(np.sum(n * n))
    # corner: a point on >= 3 faces with independent normals
    cnt = {}
    for k, (nrm, o, idx) in enumerate(F):
        for i in idx: cnt.setdefault(i, []).append(k)
    cands = [i for i, ks in cnt.items() if len(ks) >= 3 and
             np.linalg.matrix_rank(np.array([F[k][0] for k in ks], float), tol=1e-6) == 3]
    if not cands: return None
    i = cands[int(rng.integers(len(cands)))]
    w = rng.dirichlet(np.ones(len(cnt[i])))
    n = sum(ld(w[m]) * F[k][0] for m, k in enumerate(cnt[i]))
    return PL[i].copy(), n / np.sqrt(np.sum(n * n))

def make_P(L):
    """returns (shape, kind, feature, e_local, n_local)"""
    kind = pick(["box", "polytope", "sum_poly", "cylinder", "cone", "triangle", "segment"],
                [4, 4, 3, 1.5, 1.5, 0.5, 0.5])
    for _ in range(20):
        if kind == "box":
            h = ld([L * U(0.1, 1.5) for _ in range(3)])
            shape = {"type": "box", "half_extents": [float(v) for v in h]}
            feature = pick(["face", "edge", "corner"])
            free = {"face": 2, "edge": 1, "corner": 0}[feature]
            first = int(rng.integers(3))
            e = ld([0, 0, 0]); n = ld([0, 0, 0])
            for k in range(3):
                ax = (first + k) % 3; sg = 1 if rng.uniform() < 0.5 else -1
                if k < free: e[ax] = LD(U(-0.95, 0.95)) * h[ax]
                else: e[ax] = sg * h[ax]; n[ax] = sg * LD(U(0.05, 1))
            return shape, kind, feature, e, n / np.sqrt(np.sum(n * n))
        if kind in ("polytope", "sum_poly"):
            if kind == "polytope": shape = poly_shape(L)
            else:
                kinds = ["box", "segment", "triangle", "polytope"]
                a = small_part(0.6 * L, ["box", "polytope"])
                b = small_part(0.6 * L, kinds)
                if rng.uniform() < 0.3 and a["type"] == "box":  # two boxes in one frame: aligned faces
                    b = small_part(0.6 * L, ["box"])
                shape = {"type": "sum", "shapes": [a, b]}
            feature = pick(["face", "edge", "corner"])
            r = hull_feature(shape, feature)
            if r is None: continue
            return shape, kind, feature, r[0], r[1]
        if kind == "cylinder":
            r, h = L * U(0.2, 1), L * U(0.1, 1)
            shape = {"type": "cylinder", "radius": r, "half_height": h}
            feature = pick(["cap", "side", "rim"])
            phi = U(0, 2 * np.pi); rad = ld([np.cos(phi), np.sin(phi), 0])
            sg = 1 if rng.uniform() < 0.5 else -1
            if feature == "cap":
                e = rad * LD(r * np.sqrt(U(0, 0.9))); e[2] = sg * LD(h); n = ld([0, 0, sg])
            elif feature == "side":
                e = rad * LD(r); e[2] = LD(U(-0.95, 0.95) * h); n = rad
            else:
                a = U(0.05, 1.5)
                e = rad * LD(r); e[2] = sg * LD(h); n = rad * LD(np.sin(a)); n[2] = sg * LD(np.cos(a))
            return shape, kind, feature, e, n / np.sqrt(np.sum(n * n))
        if kind == "cone":
            r, h = L * U(0.2, 1), L * U(0.1, 1)
            shape = {"type": "cone", "radius": r, "half_height": h}
            feature = pick(["base", "rim", "slant", "apex"])
            phi = U(0, 2 * np.pi); rad = ld([np.cos(phi), np.sin(phi), 0])
            slant = rad * LD(2 * h); slant[2] = LD(r); slant /= np.sqrt(np.sum(slant * slant))
            if feature == "base":
                e = rad * LD(r * np.sqrt(U(0, 0.9))); e[2] = LD(-h); n = ld([0, 0, -1])
            elif feature == "rim":
                t = U(0.03, 0.97); e = rad * LD(r); e[2] = LD(-h); n = LD(t) * slant + LD(1 - t) * ld([0, 0, -1])
            elif feature == "slant":
                t = LD(U(0.05, 0.95)); e = (rad * LD(r) + ld([0, 0, -h])) * t + ld([0, 0, h]) * (1 - t); n = slant
            else:
                t = U(0.03, 0.97); e = ld([0, 0, h]); n = LD(t) * slant + LD(1 - t) * ld([0, 0, 1])
            return shape, kind, feature, e, n / np.sqrt(np.sum(n * n))
        if kind == "triangle":
            P = ld(pts(3, L)); shape = {"type": "triangle", "points": [[float(c) for c in p] for p in P]}
            nrm = np.cross(P[1] - P[0], P[2] - P[0]); nrm /= np.sqrt(np.sum(nrm * nrm))
            sg = LD(1 if rng.uniform() < 0.5 else -1)
            feature = pick(["face", "edge", "corner"])
            w = ld(rng.dirichlet(np.ones(3)))
            if feature == "face": return shape, kind, feature, w @ P, sg * nrm
            i = int(rng.integers(3)); j = (i + 1) % 3; k = (i + 2) % 3
            def outward(i, j, k):
                d = P[j] - P[i]; m = np.cross(d, nrm); m /= np.sqrt(np.sum(m * m))
                return m if m @ (P[i] - P[k]) > 0 else -m
            if feature == "edge":
                t = LD(U(0.05, 0.95)); e = P[i] + t * (P[j] - P[i])
                n = LD(U(-1, 1)) * nrm + LD(U(0.05, 1)) * outward(i, j, k)
            else:
                e = P[i].copy()
                n = LD(U(-1, 1)) * nrm + LD(U(0.05, 1)) * outward(i, j, k) + LD(U(0.05, 1)) * outward(k, i, j)
            return shape, kind, feature, e, n / np.sqrt(np.sum(n * n))
        if kind == "segment":
            P = ld(pts(2, L)); shape = {"type": "segment", "points": [[float(c) for c in p] for p in P]}
            d = P[1] - P[0]; d /= np.sqrt(np.sum(d * d))
            feature = pick(["edge", "corner"])
            v = ld(rng.normal(size=3)); v -= (v @ d) * d; v /= np.sqrt(np.sum(v * v))
            if feature == "edge":
                return shape, kind, feature, P[0] + LD(U(0.05, 0.95)) * (P[1] - P[0]), v
            n = v + LD(U(0.05, 2)) * d
            return shape, kind, feature, P[1].copy(), n / np.sqrt(np.sum(n * n))
    return None

# ------------------------------------------------------------------ curved side C
def basic_curved(L, k):
    if k == "ellipsoid": return {"type": "ellipsoid", "radii": [L * U(0.15, 1) for _ in range(3)]}
    if k == "sphere": return {"type": "sphere", "radius": L * U(0.2, 1)}
    if k in ("cylinder", "cone", "capsule"): return {"type": k, "radius": L * U(0.15, 1), "half_height": L * U(0.1, 1)}
    if k in ("box", "segment", "triangle", "polytope"): return small_part(L, [k])
    if k == "point": return {"type": "point", "points": pts(1, 0.3 * L)}
    raise ValueError(k)

C_KINDS = {
    # kind: (weight, builder)
    "ellipsoid": 4, "rounded_ellipsoid": 3, "sum_ellipsoid": 5, "cylinder": 3, "cone": 3,
    "rounded_cyl_cone": 2, "sum_cyl_cone": 3, "sphere_swept": 2, "aligned": 4,
}

def make_C(L):
    """returns (shape, kind, mode) with mode 'generic' (unique support point wanted) or an
    alignment spec: ('aligned', d_loc, c_loc_mid) / ('tilted', d_loc, c_loc)"""
    ks = list(C_KINDS); kind = pick(ks, [C_KINDS[k] for k in ks])
    if kind == "ellipsoid": return basic_curved(L, "ellipsoid"), kind, "generic"
    if kind == "rounded_ellipsoid":
        return {"type": "rounded", "shape": basic_curved(0.8 * L, "ellipsoid"), "radius": L * LU(1e-3, 0.3)}, kind, "generic"
    if kind == "sum_ellipsoid":
        other = pick(["box", "polytope", "segment", "triangle", "cylinder", "cone", "ellipsoid", "sphere", "capsule", "point"])
        parts = [basic_curved(0.6 * L, "ellipsoid"), basic_curved(0.6 * L, other)]
        if rng.uniform() < 0.5: parts = parts[::-1]
        return {"type": "sum", "shapes": parts}, kind + "+" + other, "generic"
    if kind in ("cylinder", "cone"): return basic_curved(L, kind), kind, "generic"
    if kind == "rounded_cyl_cone":
        k = pick(["cylinder", "cone"])
        return {"type": "rounded", "shape": basic_curved(0.8 * L, k), "radius": L * LU(1e-3, 0.3)}, "rounded_" + k, "generic"
    if kind == "sum_cyl_cone":
        k = pick(["cylinder", "cone"]); other = pick(["box", "polytope", "segment", "triangle", "cylinder", "cone", "capsule"])
        parts = [basic_curved(0.6 * L, k), basic_curved(0.6 * L, other)]
        if rng.uniform() < 0.5: parts = parts[::-1]
        return {"type": "sum", "shapes": parts}, "sum_" + k + "+" + other, "generic"
    if kind == "sphere_swept":
        k = pick(["sphere", "capsule", "rounded_box", "rounded_polytope", "rounded_triangle"])
        if k in ("sphere", "capsule"): return basic_curved(L, k), k, "generic"
        return {"type": "rounded", "shape": basic_curved(0.8 * L, k.split("_")[1]), "radius": L * LU(1e-3, 0.3)}, k, "generic"
    # aligned: the support set along -n a segment or a face (or tilted off it by 1e-9..1e-4 rad)
    k = pick(["cyl_side", "cyl_cap", "cone_base", "cone_slant", "capsule_side", "rcyl_side", "rcyl_cap", "ell+box_face"])
    phi = U(0, 2 * np.pi); rad = np.array([np.cos(phi), np.sin(phi), 0.0])
    if k.startswith("cyl") or k.startswith("rcyl") or k.startswith("cone") or k.startswith("capsule"):
        base = {"cyl": "cylinder", "rcyl": "cylinder", "cone": "cone", "capsule": "capsule"}[k.split("_")[0]]
        s = basic_curved(L if base != "cone" else L, base)
        r, h = s["radius"], s["half_height"]
        if k.endswith("side"): d = rad; mid = np.array([r * rad[0], r * rad[1], 0.0])
        elif k.endswith("cap"): sg = 1 if rng.uniform() < 0.5 else -1; d = np.array([0, 0, sg]); mid = np.array([0, 0, sg * h])
        elif k == "cone_base": d = np.array([0, 0, -1.0]); mid = np.array([0, 0, -h])
        else:
            d = unit(np.array([2 * h * rad[0], 2 * h * rad[1], r])); mid = 0.5 * np.array([r * rad[0], r * rad[1], 0.0])
        if base == "capsule": mid = mid * 0 + r * d  # the segment's middle swept by the radius
        if k.startswith("rcyl"):
            rr = L * LU(1e-3, 0.3); s = {"type": "rounded", "shape": s, "radius": rr}; mid = mid + rr * d
    else:
        e = basic_curved(0.6 * L, "ellipsoid"); b = basic_curved(0.6 * L, "box")
        ax = int(rng.integers(3)); sg = 1 if rng.uniform() < 0.5 else -1
        d = np.zeros(3); d[ax] = sg
        r = np.array(e["radii"]); mid = r * r * d / np.linalg.norm(r * d)
        mid[ax] += sg * b["half_extents"][ax]
        s = {"type": "sum", "shapes": [e, b] if rng.uniform() < 0.5 else [b, e]}
    if rng.uniform() < 0.35:
        th = LU(1e-9, 1e-4)
        ax = unit(np.cross(d, rng.normal(size=3)))
        d2 = spin(ax, th) @ d
        return s, "tilted_" + k, ("tilted", d2, None)
    return s, "aligned_" + k, ("aligned", d, mid)

def scale_regime():
    r = rng.uniform()
    if r < 0.7: return 1.0, 0.0
    if r < 0.8: return 1e-6, 0.0
    if r < 0.9: return 1e6, 0.0
    return 1.0, 1e6

def gap_regime(size):
    r = pick(["sep", "near_sep", "near_pen", "pen", "touch"], [2, 4, 3, 2, 0.5])
    if r == "sep": return r, size * LU(1e-3, 0.3)
    if r == "near_sep": return r, size * LU(1e-12, 1e-3)
    if r == "near_pen": return r, -size * LU(1e-12, 1e-3)
    if r == "pen": return r, -size * LU(1e-3, 0.03)
    return r, 0.0

def vec(v): return [float(x) for x in v]

out = 0
tries = 0
while out < N and tries < 50 * N:
    tries += 1
    k, far = scale_regime()
    Pr = make_P(k)
    if Pr is None: continue
    P, pkind, feature, e_loc, n_loc = Pr
    C, ckind, mode = make_C(k * U(0.3, 1.5))
    # P's pose
    off = unit(rng.normal(size=3)) * far if far else np.zeros(3)
    pa = {"t": vec(off + k * rng.normal(size=3)), "q": quat_of_R(rrot())}
    tP, RP = pose_of(pa, LD)
    e = RP @ e_loc + tP
    n = RP @ n_loc; n /= np.sqrt(np.sum(n * n))
    if GENERAL:
        from common import minimize, pair_fn
        size = bounding_radius(P) + bounding_radius(C)
        regime, gap = gap_regime(size)
        pb = {"t": vec(np.array(pa["t"]) + unit(rng.normal(size=3)) * U(0.3, 1.0) * size), "q": quat_of_R(rrot())}
        for _ in range(2):
            v, u = minimize(pair_fn(P, pa, C, pb), ngrid=8000, nstarts=4)
            pb["t"] = vec(np.array(pb["t"]) + (v + gap) * u)
        scale = "1e-6" if k < 1 else ("1e6" if k > 1 else ("far1e6" if far else "1"))
        ckind = ckind if mode == "generic" else ckind.split("_", 1)[1]
        print(json.dumps({"id": f"g{seed}_{out}", "cat": f"{pkind}:random|{ckind}|{regime}|{scale}", "a": P, "pa": pa,
                          "b": C, "pb": pb, "exp": {"n": None, "gap": gap, "unique": False}}))
        out += 1
        continue
    # C's rotation: generic with a margin, or aligned so that R_C d_loc = -n
    if mode == "generic":
        ok = False
        for _ in range(60):
            qC = quat_of_R(rrot())
            _, RC = pose_of({"q": qC}, LD)
            c_loc, uniq = support_point(C, RC.T @ (-n), thr=0.03)
            if uniq: ok = True; break
        if not ok: continue
    else:
        tag, d_loc, mid = mode
        R0 = frame_with(d_loc, -np.asarray(n, float))
        R = spin(-np.asarray(n, float), U(0, 2 * np.pi)) @ R0
        qC = quat_of_R(R)
        _, RC = pose_of({"q": qC}, LD)
        if tag == "aligned":
            c_loc, uniq = ld(mid), False
        else:
            c_loc, _ = support_point(C, RC.T @ (-n)); uniq = False
    size = bounding_radius(P) + bounding_radius(C)
    regime, gap = gap_regime(size)
    tC = e + LD(gap) * n - RC @ c_loc
    pb = {"t": vec(tC), "q": qC}
    # recompute with the rounded pose
    tC2, RC2 = pose_of(pb, LD)
    c = RC2 @ c_loc + tC2
    gap2 = float(n @ (c - e))
    scale = "1e-6" if k < 1 else ("1e6" if k > 1 else ("far1e6" if far else "1"))
    cid = f"s{seed}_{out}"
    case = {"id": cid, "cat": f"{pkind}:{feature}|{ckind}|{regime}|{scale}", "a": P, "pa": pa, "b": C, "pb": pb,
            "exp": {"n": vec(n), "e": vec(e), "c": vec(c), "gap": gap2, "unique": bool(uniq)}}
    print(json.dumps(case))
    out += 1
