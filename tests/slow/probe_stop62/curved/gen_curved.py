"""Curved against curved at special feature pairs, with an exactly known answer (probe 62).

A's support set along +n contains e, B's support set along -n contains c = e + gap n (both
shapes curved or with curved parts). Then for gap >= 0: distance = gap, normal = n, witnesses in
the two support sets with difference gap n (the pair e, c itself when one set is a single point).
For gap < 0, n gives -gap: an upper bound on the depth (checked by search in ../../probe_stop52/check.py).

Support sets are computed in closed form (long double) as a base point plus generators
(segments, discs): support_set(). Feature kinds by the set's dimension: P (point), L (segment),
F (disc, rectangle, stadium...).

usage: python3 gen_curved.py SEED N > cases.jsonl
modes: exact (aligned special pair), tilt_exact (B tilted 1e-9..1e-4 rad, its true support point
placed at e + gap n: still exact), tilt_search (the exact pair, then B turned by 1e-9..1e-4 rad
about c: no known answer, exp.n = None, exp.hint = n)."""
import json, sys, os
import numpy as np
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "probe_stop52"))
from common import (LD, ld, unit, quat_of_R, quat_to_R, frame_with, spin, bounding_radius, pose_of,
                    h_world)

TOL_SET = 1e-13


# ------------------------------------------------------------------ support sets (local, long double)
def _disc_basis(axis):
    a = ld([1, 0, 0]) if abs(axis[0]) < 0.6 else ld([0, 1, 0])
    e1 = np.cross(axis, a); e1 /= np.sqrt(np.sum(e1 * e1))
    return e1, np.cross(axis, e1)


def support_set(s, d):
    """(base point, generators) of shape s's support set along local direction d; generators:
    ('seg', v) adds t v, t in [0,1]; ('disc', axis, r) adds any vector of length <= r normal to axis"""
    t = s["type"]
    d = ld(d); d = d / np.sqrt(np.sum(d * d))
    if t == "sphere": return LD(s["radius"]) * d, []
    if t == "ellipsoid":
        r = ld(s["radii"]); return r * r * d / np.sqrt(np.sum((r * d) ** 2)), []
    if t == "point": return ld(s["points"][0]), []
    if t == "segment":
        a, b = ld(s["points"][0]), ld(s["points"][1]); v = b - a
        L = np.sqrt(np.sum(v * v)); x = d @ v
        if abs(x) <= TOL_SET * L: return a, [("seg", v)]
        return (b if x > 0 else a), []
    if t == "box":
        h = ld(s["half_extents"]); p = np.zeros(3, dtype=LD); g = []
        for i in range(3):
            if abs(d[i]) <= TOL_SET:
                p[i] = -h[i]; v = np.zeros(3, dtype=LD); v[i] = 2 * h[i]; g.append(("seg", v))
            else: p[i] = h[i] * np.sign(d[i])
        return p, g
    if t in ("capsule", "cylinder", "cone"):
        r, h = LD(s["radius"]), LD(s["half_height"])
        rho = np.sqrt(d[0] ** 2 + d[1] ** 2)
        if t == "capsule":
            if abs(d[2]) <= TOL_SET: return ld([0, 0, -h]) + r * d, [("seg", ld([0, 0, 2 * h]))]
            return ld([0, 0, h * np.sign(d[2])]) + r * d, []
        if t == "cylinder":
            g = []
            if abs(d[2]) <= TOL_SET: z = -h; g.append(("seg", ld([0, 0, 2 * h])))
            else: z = h * np.sign(d[2])
            if rho <= TOL_SET: return ld([0, 0, z]), g + [("disc", ld([0, 0, 1]), r)]
            return ld([r * d[0] / rho, r * d[1] / rho, z]), g
        apex, rim = h * d[2], r * rho - h * d[2]
        if rho <= TOL_SET and d[2] < 0: return ld([0, 0, -h]), [("disc", ld([0, 0, 1]), r)]
        if abs(apex - rim) <= TOL_SET * (r + h):
            rp = ld([r * d[0] / rho, r * d[1] / rho, -h]); return rp, [("seg", ld([0, 0, h]) - rp)]
        if apex > rim: return ld([0, 0, h]), []
        return ld([r * d[0] / rho, r * d[1] / rho, -h]), []
    if t == "sum":
        p, g = support_set(s["shapes"][0], d); q, k = support_set(s["shapes"][1], d)
        return p + q, g + k
    if t == "rounded":
        p, g = support_set(s["shape"], d); return p + LD(s["radius"]) * d, g
    raise ValueError(t)


def gen_vectors(g):
    out = []
    for x in g:
        if x[0] == "seg": out.append(x[1])
        else:
            e1, e2 = _disc_basis(x[1]); out += [e1 * x[2], e2 * x[2]]
    return out


def set_dim(g):
    V = gen_vectors(g)
    if not V: return 0
    M = np.array([np.asarray(v, float) / np.linalg.norm(np.asarray(v, float)) for v in V])
    sv = np.linalg.svd(M, compute_uv=False)
    return int(np.sum(sv > 1e-9 * sv[0]))


def line_dir(g):
    V = [v for v in gen_vectors(g)]
    v = max(V, key=lambda v: float(np.sum(v * v)))
    return v / np.sqrt(np.sum(v * v))


# ------------------------------------------------------------------ random
seed, N = int(sys.argv[1]), int(sys.argv[2])
rng = np.random.default_rng(seed)
U = lambda a, b: float(rng.uniform(a, b))
LU = lambda a, b: float(10 ** rng.uniform(np.log10(a), np.log10(b)))
def pick(xs, w=None):
    w = None if w is None else np.array(w, float) / np.sum(w)
    return xs[int(rng.choice(len(xs), p=w))]
def rrot():
    q = rng.normal(size=4); q /= np.linalg.norm(q); return quat_to_R(q)
def vec(v): return [float(x) for x in v]


# ------------------------------------------------------------------ shapes
def rh(L):
    """radius, half height: ordinary, needle (radius 1e-3 of the length) or flat disc"""
    a = pick(["plain", "needle", "disc"], [6, 1, 1])
    if a == "plain": return L * U(0.2, 1), L * U(0.15, 1), a
    if a == "needle": return L * LU(3e-4, 3e-3), L * U(0.5, 1), a
    return L * U(0.5, 1), L * LU(3e-4, 3e-3), a


def make_shape(L):
    k = pick(["cylinder", "cone", "capsule", "ellipsoid", "sphere", "rounded_cylinder", "rounded_cone",
              "rounded_box", "sum_cyl_sphere", "sum_cone_segment", "sum_cyl_segment", "sum_ell_segment",
              "sum_cone_sphere", "sum_capsule_cyl"],
             [5, 5, 3, 2, 1, 2, 2, 1.5, 1.5, 2, 1.5, 1, 1, 0.7])
    if k in ("cylinder", "cone", "capsule"):
        r, h, a = rh(L); return {"type": k, "radius": r, "half_height": h}, k + ("" if a == "plain" else "/" + a)
    if k == "ellipsoid": return {"type": "ellipsoid", "radii": [L * U(0.15, 1) for _ in range(3)]}, k
    if k == "sphere": return {"type": "sphere", "radius": L * U(0.2, 1)}, k
    if k.startswith("rounded"):
        if k == "rounded_box": core = {"type": "box", "half_extents": [0.8 * L * U(0.1, 1) for _ in range(3)]}
        else:
            r, h, a = rh(0.8 * L); core = {"type": k.split("_")[1], "radius": r, "half_height": h}
        return {"type": "rounded", "shape": core, "radius": L * LU(1e-3, 0.3)}, k
    if k == "sum_cyl_sphere":
        r, h, a = rh(0.7 * L)
        parts = [{"type": "cylinder", "radius": r, "half_height": h}, {"type": "sphere", "radius": L * LU(1e-3, 0.3)}]
    elif k == "sum_cone_sphere":
        r, h, a = rh(0.7 * L)
        parts = [{"type": "cone", "radius": r, "half_height": h}, {"type": "sphere", "radius": L * LU(1e-3, 0.3)}]
    elif k == "sum_capsule_cyl":
        r, h, a = rh(0.5 * L); r2, h2, _ = rh(0.5 * L)
        parts = [{"type": "cylinder", "radius": r, "half_height": h}, {"type": "capsule", "radius": r2, "half_height": h2}]
    else:
        base = {"sum_cone_segment": "cone", "sum_cyl_segment": "cylinder", "sum_ell_segment": "ellipsoid"}[k]
        if base == "ellipsoid": first = {"type": "ellipsoid", "radii": [0.7 * L * U(0.15, 1) for _ in range(3)]}
        else:
            r, h, a = rh(0.7 * L); first = {"type": base, "radius": r, "half_height": h}
        ln = 0.4 * L * U(0.1, 1)
        o = pick(["x", "z", "rand"])
        v = {"x": np.array([1.0, 0, 0]), "z": np.array([0, 0, 1.0]), "rand": unit(rng.normal(size=3))}[o]
        if o == "rand": pts = [vec(-ln * v), vec(ln * v)]
        else: pts = [vec(-ln * v), vec(ln * v)]
        parts = [first, {"type": "segment", "points": pts}]
        k = k + "/" + o
    if rng.uniform() < 0.5: parts = parts[::-1]
    return {"type": "sum", "shapes": parts}, k


def core_of(s):
    """the revolution/box core that carries the special features, and the shape's kind"""
    t = s["type"]
    if t == "rounded": return s["shape"]
    if t == "sum":
        for p in s["shapes"]:
            if p["type"] in ("cylinder", "cone", "ellipsoid"): return p
        return s["shapes"][0]
    return s


def feature_dir(s, want):
    """a local direction d at a feature of the core of s whose set dimension we hope is `want`
    ('F', 'L', 'P'); returns (d, feature name)"""
    c = core_of(s); t = c["type"]
    phi = U(0, 2 * np.pi); cp, sp = LD(np.cos(phi)), LD(np.sin(phi))
    sg = LD(1 if rng.uniform() < 0.5 else -1)
    if t in ("ellipsoid", "sphere"):
        return unit(ld(rng.normal(size=3))), "smooth"
    if t == "box":
        i, j = rng.permutation(3)[:2]
        d = np.zeros(3, dtype=LD)
        if want == "F": d[i] = sg; return d, "face"
        if want == "L": d[i] = sg * LD(U(0.05, 1)); d[j] = LD(pick([-1, 1]) * U(0.05, 1)); return unit(d), "edge"
        return unit(ld(rng.normal(size=3))), "corner"
    r, h = LD(c["radius"]), LD(c["half_height"])
    if t == "capsule":
        if want == "L": return ld([cp, sp, 0]), "side"
        return unit(ld([cp, sp, sg * LD(U(0.05, 3))])), "end"
    if t == "cylinder":
        if want == "F": return ld([0, 0, sg]), "cap"
        if want == "L": return ld([cp, sp, 0]), "side"
        a = LD(pick([U(0.03, 1.54), LU(1e-6, 1e-2), np.pi / 2 - LU(1e-6, 1e-2)], [6, 1, 1]))
        return ld([np.sin(a) * cp, np.sin(a) * sp, sg * np.cos(a)]), "rim"
    if t == "cone":
        slant = ld([2 * h * cp, 2 * h * sp, r]); slant /= np.sqrt(np.sum(slant * slant))
        if want == "F": return ld([0, 0, -1]), "base"
        if want == "L": return slant, "slant"
        if rng.uniform() < 0.5:
            tt = LD(pick([U(0.03, 0.97), LU(1e-6, 1e-2), 1 - LU(1e-6, 1e-2)], [6, 1, 1]))
            return unit(tt * slant + (1 - tt) * ld([0, 0, -1])), "rim"
        tt = LD(pick([U(0.03, 0.97), LU(1e-6, 1e-2), 1 - LU(1e-6, 1e-2)], [6, 1, 1]))
        return unit(tt * slant + (1 - tt) * ld([0, 0, 1])), "apex"
    raise ValueError(t)


def point_in(p, g, mode):
    """a point of the set: 'mid' (middle), 'rand', 'edge' (near a set boundary)"""
    x = p.copy()
    for gg in g:
        if mode == "mid": t = 0.5
        elif mode == "edge": t = pick([LU(1e-7, 0.05), 1 - LU(1e-7, 0.05)])
        else: t = U(0, 1)
        if gg[0] == "seg": x = x + LD(t) * gg[1]
        else:
            e1, e2 = _disc_basis(gg[1]); a = U(0, 2 * np.pi)
            rr = 0 if mode == "mid" else (np.sqrt(U(0, 1)) if mode == "rand" else 1 - LU(1e-7, 0.05))
            x = x + gg[2] * LD(rr) * (LD(np.cos(a)) * e1 + LD(np.sin(a)) * e2)
    return x


def scale_regime():
    r = rng.uniform()
    if r < 0.65: return 1.0, 0.0
    if r < 0.77: return 1e-6, 0.0
    if r < 0.89: return 1e6, 0.0
    return 1.0, 1e6


def gap_regime(size):
    r = pick(["sep", "near_sep", "touch", "near_pen", "pen"], [3, 3, 1, 2.5, 1.5])
    if r == "sep": return r, size * LU(1e-3, 0.3)
    if r == "near_sep": return r, size * LU(1e-12, 1e-6)
    if r == "near_pen": return r, -size * LU(1e-12, 1e-6)
    if r == "pen": return r, -size * LU(1e-6, 1e-3)
    return r, 0.0


CLASSES = [("F", "P", 5), ("F", "L", 4), ("F", "F", 3), ("L", "L:cross", 4), ("L", "L:nearpar", 3),
           ("L", "L:par", 3), ("L", "P", 4), ("P", "P", 5)]


def main():
    out, tries = 0, 0
    while out < N and tries < 200 * N:
        tries += 1
        kA, kB, w = CLASSES[int(rng.choice(len(CLASSES), p=np.array([c[2] for c in CLASSES], float) / sum(c[2] for c in CLASSES)))]
        ll = kB.split(":")[1] if ":" in kB else None
        kB = kB.split(":")[0]
        if rng.uniform() < 0.5 and kA != kB: kA, kB = kB, kA
        k, far = scale_regime()
        A, nameA = make_shape(k)
        B, nameB = make_shape(k * U(0.3, 1.5))
        dA, fA = feature_dir(A, kA); dB, fB = feature_dir(B, kB)
        pA, gA = support_set(A, dA); pB, gB = support_set(B, dB)
        if set_dim(gA) != {"F": 2, "L": 1, "P": 0}[kA] or set_dim(gB) != {"F": 2, "L": 1, "P": 0}[kB]: continue
        mode = pick(["exact", "tilt_exact", "tilt_search"], [7, 1.5, 1.5])
        # A's pose
        off = unit(rng.normal(size=3)) * far if far else np.zeros(3)
        pa = {"t": vec(off + k * rng.normal(size=3)), "q": quat_of_R(rrot())}
        tA, RA = pose_of(pa, LD)
        n = RA @ dA; n /= np.sqrt(np.sum(n * n))
        # B's rotation: R0 takes dB to -n; then a spin about n, set for line pairs
        R0 = frame_with(np.asarray(dB, float), -np.asarray(n, float))
        psi = U(0, 2 * np.pi); angle = None
        if kA == "L" and kB == "L":
            a_w = RA @ line_dir(gA); b_w = ld(R0) @ line_dir(gB)
            a_w = a_w - (a_w @ n) * n; b_w = b_w - (b_w @ n) * n
            nn = np.asarray(n, float)
            ang0 = float(np.arctan2(float(np.cross(b_w, a_w) @ n), float(a_w @ b_w)))
            if ll == "cross": angle = pick([U(0.01, np.pi / 2), LU(1e-3, 0.1)], [3, 1])
            elif ll == "nearpar": angle = LU(1e-9, 1e-3)
            else: angle = 0.0
            psi = ang0 + pick([1, -1]) * angle + pick([0, np.pi])
        RB = spin(-np.asarray(n, float), 0) @ R0
        RB = spin(np.asarray(n, float), psi) @ R0
        tilt = None
        if mode != "exact":
            tilt = LU(1e-9, 1e-4)
            axis = unit(np.cross(np.asarray(n, float), rng.normal(size=3)))
        if mode == "tilt_exact":
            RB = spin(axis, tilt) @ RB
        qB = quat_of_R(RB)
        _, RBl = pose_of({"q": qB}, LD)
        # the points: e in A's set, c_loc in B's set (along B's own local -n after rounding)
        modeA = pick(["mid", "rand", "edge"], [2, 3, 2]); modeB = pick(["mid", "rand", "edge"], [2, 3, 2])
        e_loc = point_in(pA, gA, modeA)
        e = RA @ e_loc + tA
        dB_act = RBl.T @ (-n)
        if mode == "tilt_exact":
            pB2, gB2 = support_set(B, dB_act)
            c_loc = point_in(pB2, gB2, modeB); uniqB = not gB2
        else:
            c_loc = point_in(pB, gB, modeB); uniqB = not gB
        size = bounding_radius(A) + bounding_radius(B)
        regime, gap = gap_regime(size)
        tB = e + LD(gap) * n - RBl @ c_loc
        pb = {"t": vec(tB), "q": qB}
        tB2, RB2 = pose_of(pb, LD)
        c = RB2 @ c_loc + tB2
        gap2 = float(n @ (c - e))
        unique = (not gA) or uniqB
        exp = {"n": vec(n), "e": vec(e), "c": vec(c), "gap": gap2, "unique": bool(unique)}
        if mode == "tilt_search":
            # turn B by `tilt` about c: no known answer
            Rt = spin(axis, tilt)
            RBt = Rt @ np.asarray(RB2, float)
            qB = quat_of_R(RBt)
            _, RBtl = pose_of({"q": qB}, LD)
            tBt = c - RBtl @ c_loc
            pb = {"t": vec(tBt), "q": qB}
            exp = {"n": None, "hint": vec(n), "gap": gap2, "unique": False}
        # validate the construction (long double): A's support value along n at e, B's along -n at c
        if mode != "tilt_search":
            hA = h_world(A, pa, n); hB = h_world(B, pb, -n)
            errA = abs(hA - float(n @ e)) / size; errB = abs(hB + float(n @ c)) / size
            T = max(np.max(np.abs(pa["t"])), np.max(np.abs(pb["t"])), 1e-300)
            if errA > 1e-13 + 4e-16 * T / size or errB > 1e-13 + 4e-16 * T / size:
                print(f"construction off: {errA:.2e} {errB:.2e} {nameA} {fA} {nameB} {fB}", file=sys.stderr); continue
        scale = "1e-6" if k < 1 else ("1e6" if k > 1 else ("far1e6" if far else "1"))
        cls = f"{kA}-{kB}" + (f":{ll}" if ll else "")
        cls = "-".join(sorted([kA, kB])) + (f":{ll}" if ll else "")
        case = {"id": f"c{seed}_{out}", "cls": cls, "mode": mode,
                "cat": f"{nameA}:{fA}|{nameB}:{fB}|{regime}|{scale}|{modeA},{modeB}",
                "tilt": tilt, "angle": angle, "a": A, "pa": pa, "b": B, "pb": pb, "exp": exp}
        print(json.dumps(case))
        out += 1


main()
