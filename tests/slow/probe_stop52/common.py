"""Shared pieces of probe 52: long-double support points in closed form, a brute-force hull,
signed distances, and a long-double pattern search on the unit sphere.

Reuses probe 50's oracle (support functions, pair_fn, member_fn, minimize) and probe 51's
closed-form signed distances (exact.py) by import, not by copy."""
import os, sys, itertools
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.append(os.path.join(HERE, "..", "probe_stop51"))   # oracle.py (-> probe 50's) and exact.py
import oracle                      # noqa: E402
from oracle import bounding_radius, pair_fn, member_fn, support_local, pose_of, quat_to_R, minimize  # noqa
import exact                       # noqa: E402

LD = np.longdouble
EPS = 2.220446049250313e-16
TOOL = os.environ.get("MINK", os.path.join(HERE, "..", "..", "..", "build", "release", "tools", "mink", "mink"))


def ld(v):
    return np.array(v, dtype=LD)


def unit(v):
    v = np.asarray(v)
    return v / np.sqrt(np.sum(v * v))


# ---------------------------------------------------------------- support points (local frame)
def support_point(s, d, thr=1e-9):
    """Support point of shape s (JSON, local frame) along direction d (long double, 3,), and
    whether it is the only one (a single point on the support plane, to 1e-9 relative)."""
    t = s["type"]
    d = ld(d)
    dn = np.sqrt(np.sum(d * d))
    if t == "sphere":
        return LD(s["radius"]) * d / dn, True
    if t == "ellipsoid":
        r = ld(s["radii"])
        return r * r * d / np.sqrt(np.sum((r * d) ** 2)), True
    if t == "box":
        h = ld(s["half_extents"])
        return h * np.sign(d), bool(np.all(np.abs(d) > thr * dn))
    if t in ("polytope", "point", "segment", "triangle"):
        P = ld(s["points"])
        v = P @ d
        i = int(np.argmax(v))
        ext = float(np.max(np.abs(P))) if len(P) else 1.0
        others = v[np.abs(P - P[i]).max(axis=1) > 1e-12 * ext]
        unique = len(others) == 0 or float(v[i] - others.max()) > thr * ext * float(dn)
        return P[i].copy(), unique
    if t == "capsule":
        h = LD(s["half_height"]); r = LD(s["radius"])
        return ld([0, 0, h * np.sign(d[2])]) + r * d / dn, bool(abs(d[2]) > thr * dn)
    if t == "cylinder":
        h = LD(s["half_height"]); r = LD(s["radius"])
        rho = np.sqrt(d[0] ** 2 + d[1] ** 2)
        unique = bool(rho > thr * dn and abs(d[2]) > thr * dn)
        if rho == 0:
            return ld([0, 0, h * np.sign(d[2])]), False
        return ld([r * d[0] / rho, r * d[1] / rho, h * np.sign(d[2])]), unique
    if t == "cone":
        h = LD(s["half_height"]); r = LD(s["radius"])
        rho = np.sqrt(d[0] ** 2 + d[1] ** 2)
        apex, rim = h * d[2], r * rho - h * d[2]
        if rho == 0 and d[2] < 0:
            return ld([0, 0, -h]), False
        if apex >= rim:
            return ld([0, 0, h]), bool(apex - rim > thr * dn * (r + h))
        return ld([r * d[0] / rho, r * d[1] / rho, -h]), bool(rim - apex > thr * dn * (r + h) and rho > thr * dn)
    if t == "sum":
        p, u1 = support_point(s["shapes"][0], d, thr)
        q, u2 = support_point(s["shapes"][1], d, thr)
        return p + q, u1 and u2
    if t == "rounded":
        p, u = support_point(s["shape"], d, thr)
        return p + LD(s["radius"]) * d / dn, u
    raise ValueError(t)


def world_support(s, pose, n, thr=1e-9):
    """world support point along world direction n (long double)"""
    t, R = pose_of(pose, LD)
    p, u = support_point(s, R.T @ ld(n), thr)
    return R @ p + t, u


def h_world(s, pose, n):
    t, R = pose_of(pose, LD)
    n = ld(n)
    return float(n @ t + support_local(s, (n @ R)[None, :])[0])


# ---------------------------------------------------------------- rotations
def quat_of_R(R):
    R = np.asarray(R, float)
    tr = np.trace(R)
    if tr > 0:
        S = np.sqrt(tr + 1.0) * 2
        q = [0.25 * S, (R[2, 1] - R[1, 2]) / S, (R[0, 2] - R[2, 0]) / S, (R[1, 0] - R[0, 1]) / S]
    elif R[0, 0] > R[1, 1] and R[0, 0] > R[2, 2]:
        S = np.sqrt(1.0 + R[0, 0] - R[1, 1] - R[2, 2]) * 2
        q = [(R[2, 1] - R[1, 2]) / S, 0.25 * S, (R[0, 1] + R[1, 0]) / S, (R[0, 2] + R[2, 0]) / S]
    elif R[1, 1] > R[2, 2]:
        S = np.sqrt(1.0 + R[1, 1] - R[0, 0] - R[2, 2]) * 2
        q = [(R[0, 2] - R[2, 0]) / S, (R[0, 1] + R[1, 0]) / S, 0.25 * S, (R[1, 2] + R[2, 1]) / S]
    else:
        S = np.sqrt(1.0 + R[2, 2] - R[0, 0] - R[1, 1]) * 2
        q = [(R[1, 0] - R[0, 1]) / S, (R[0, 2] + R[2, 0]) / S, (R[1, 2] + R[2, 1]) / S, 0.25 * S]
    q = np.array(q); q /= np.linalg.norm(q)
    if q[0] < 0: q = -q
    return [float(v) for v in q]


def frame_with(a, b):
    """a rotation R (float) with R @ a = b (unit vectors), random spin to be added by the caller"""
    a = unit(np.asarray(a, float)); b = unit(np.asarray(b, float))
    v = np.cross(a, b); c = float(a @ b)
    if np.linalg.norm(v) < 1e-12:
        if c > 0: return np.eye(3)
        p = unit(np.cross(a, [1, 0, 0] if abs(a[0]) < 0.6 else [0, 1, 0]))
        return 2 * np.outer(p, p) - np.eye(3)
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + K + K @ K / (1 + c)


def spin(axis, ang):
    axis = unit(np.asarray(axis, float))
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(ang) * K + (1 - np.cos(ang)) * K @ K


# ---------------------------------------------------------------- brute-force hull
def hull_faces(P, rel_tol=1e-11):
    """Faces of the hull of points P (n,3), full-dimensional sets only: list of
    (outward unit normal, offset, indices on the face). Brute force over triples (n <= ~70)."""
    P = ld(P)
    n = len(P)
    ext = float(np.max(np.abs(P))) or 1.0
    tol = rel_tol * ext
    T = np.array(list(itertools.combinations(range(n), 3)))
    A, B, C = P[T[:, 0]], P[T[:, 1]], P[T[:, 2]]
    N = np.cross(B - A, C - A)
    nn = np.sqrt(np.sum(N * N, axis=1))
    ok = nn > 1e-8 * ext * ext
    T, N, nn, A = T[ok], N[ok] / nn[ok, None], nn[ok], A[ok]
    off = np.sum(N * A, axis=1)
    faces = {}
    for k0 in range(0, len(T), 4000):
        V = N[k0:k0 + 4000] @ P.T - off[k0:k0 + 4000, None]
        mx, mn = V.max(axis=1), V.min(axis=1)
        for k in np.nonzero((mx <= tol) | (mn >= -tol))[0]:
            nrm, o = N[k0 + k], off[k0 + k]
            if mx[k] > tol: nrm, o = -nrm, -o
            on = np.nonzero(np.abs(P @ nrm - o) <= tol)[0]
            key = tuple(sorted(set(on.tolist())))
            if key not in faces:
                # refit the plane through the extreme points of the face: keep the best-separating
                faces[key] = (nrm, o)
    out = []
    for key, (nrm, o) in faces.items():
        out.append((nrm, o, list(key)))
    return out


def hull_sd(P, faces, x):
    """exact signed distance of x to the hull (faces from hull_faces, local frame)"""
    P = ld(P); x = ld(x)
    vals = [float(nrm @ x - o) for nrm, o, _ in faces]
    m = max(vals)
    if m <= 1e-12 * float(np.max(np.abs(P))):
        return m
    best = np.inf
    for nrm, o, idx in faces:
        Q = P[idx].astype(float)
        c = Q.mean(axis=0)
        nf = np.asarray(nrm, float)
        e1 = unit(np.cross(nf, [1, 0, 0] if abs(nf[0]) < 0.6 else [0, 1, 0]))
        e2 = np.cross(nf, e1)
        H = exact._hull2d(np.stack([(Q - c) @ e1, (Q - c) @ e2], axis=1))   # the face's polygon
        V = [c + h[0] * e1 + h[1] * e2 + float(np.mean((Q - c) @ nf)) * nf for h in H]
        if len(V) < 3:
            best = min(best, exact._seg_dist(np.asarray(x, float), V[0], V[-1])); continue
        for i in range(1, len(V) - 1):
            best = min(best, exact._tri_dist(np.asarray(x, float), V[0], V[i], V[i + 1]))
    return best


def polyhedral_points(s):
    """vertex candidates of a polyhedral shape (box, polytope, segment, triangle, point, sums)"""
    t = s["type"]
    if t == "box":
        h = s["half_extents"]
        return np.array([[sx * h[0], sy * h[1], sz * h[2]] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
    if t in ("polytope", "segment", "triangle", "point"):
        return np.array(s["points"], float)
    if t == "sum":
        P, Q = polyhedral_points(s["shapes"][0]), polyhedral_points(s["shapes"][1])
        if P is None or Q is None: return None
        return (P[:, None, :] + Q[None, :, :]).reshape(-1, 3)
    return None


_hull_cache = {}
def shape_hull(s):
    import json
    key = json.dumps(s, sort_keys=True)
    if key not in _hull_cache:
        P = polyhedral_points(s)
        _hull_cache[key] = (P, hull_faces(P))
    return _hull_cache[key]


# ---------------------------------------------------------------- signed distances
def signed_distance(s, pose, x, hint=None):
    """signed distance of world point x to shape s at pose (positive outside). Closed forms where
    they exist (exact.py, hulls); else (None) -- the caller falls back to a support search."""
    t, R = pose_of(pose, LD)
    xl = R.T @ (ld(x) - t)
    typ = s["type"]
    if typ == "ellipsoid":
        return ellipsoid_sd(ld(s["radii"]), xl)
    if typ == "rounded" and s["shape"]["type"] == "ellipsoid":
        return ellipsoid_sd(ld(s["shape"]["radii"]), xl) - s["radius"]
    if typ == "rounded" and polyhedral_points(s["shape"]) is not None and s["shape"]["type"] not in ("segment", "point"):
        P, F = shape_hull(s["shape"])
        if len(F) >= 4: return hull_sd(P, F, xl) - s["radius"]
    if polyhedral_points(s) is not None and typ not in ("segment", "triangle", "point", "box"):
        P, F = shape_hull(s)
        if len(F) >= 4: return hull_sd(P, F, xl)
    d = exact.sd_local(s, np.asarray(xl, float))
    return d


def ellipsoid_sd(r, x):
    """signed distance of local point x to the ellipsoid with radii r (long double Newton on the
    Lagrange multiplier; exact to rounding)"""
    x = ld(x); r = ld(r)
    g = np.sum((x / r) ** 2)
    if g == 0: return -float(r.min())
    # closest point p = x / (1 + t / r^2); solve sum (r x / (r^2 + t))^2 = 1
    outside = g > 1
    lo, hi = (LD(0), None) if outside else (-LD(r.min()) ** 2, LD(0))
    f = lambda t: np.sum((r * x / (r * r + t)) ** 2) - 1
    if outside:
        hi = LD(1)
        while f(hi) > 0: hi *= 2
    t = (lo + hi) / 2
    for _ in range(400):
        t = (lo + hi) / 2
        v = f(t)
        if v > 0: lo = t
        else: hi = t
        if hi - lo <= 1e-19 * max(abs(hi), abs(lo), LD(1e-300)): break
    p = r * r * x / (r * r + t)
    dist = float(np.sqrt(np.sum((x - p) ** 2)))
    return dist if outside else -dist


def support_search_sd(s, pose, x, hint, fine=False):
    """-(min over unit u of h(u) - u.x), long double, started at hint: an upper bound on the
    distance outside; inside, its magnitude may be too large where the search stalls."""
    F = member_fn(s, pose, ld(x), LD)
    starts = [np.asarray(hint, float)] if hint is not None else []
    if fine:
        v, u = minimize(F, ngrid=60000, nstarts=12, extra=starts, dt=LD, tol=1e-15)
    else:
        v, u = float(F(ld(unit(hint))[None, :])[0]), unit(hint)
    v, u = refine(F, u, v0=v, r0=1e-4)
    return -v


# ---------------------------------------------------------------- long-double pattern search
def _basis(u):
    a = ld([1, 0, 0]) if abs(u[0]) < 0.6 else ld([0, 1, 0])
    e1 = np.cross(u, a); e1 /= np.sqrt(np.sum(e1 * e1))
    return e1, np.cross(u, e1)


def refine(F, u0, v0=None, r0=1e-4, rmin=1e-15, M=16, maxit=4000, seed=0):
    """Pattern search on the unit sphere in long double, from u0: the step shrinks to rmin rad."""
    rng = np.random.default_rng(seed)
    u = ld(u0); u /= np.sqrt(np.sum(u * u))
    f = F(u[None, :])[0]
    if v0 is not None and v0 < f:  # v0 from elsewhere: keep the computed one
        pass
    r = LD(r0); fails = 0
    base = np.linspace(0, 2 * np.pi, M, endpoint=False)
    for it in range(maxit):
        if r < rmin: break
        e1, e2 = _basis(u)
        ph = ld(base + rng.uniform(0, 2 * np.pi))
        rr = np.concatenate([np.full(M, r), np.full(M, r / 3)])
        ph = np.concatenate([ph, ph + LD(np.pi / M)])
        C = (np.cos(rr)[:, None] * u[None, :] + np.sin(rr)[:, None] *
             (np.cos(ph)[:, None] * e1[None, :] + np.sin(ph)[:, None] * e2[None, :]))
        C /= np.sqrt(np.sum(C * C, axis=1))[:, None]
        fc = F(C)
        j = int(np.argmin(fc))
        if fc[j] < f:
            u, f = C[j], fc[j]
            r = min(r * 2, LD(1e-2)); fails = 0
        else:
            fails += 1
            if fails >= 2: r /= 4; fails = 0
    return f, u


# ---------------------------------------------------------------- structured minimum (confirmation)
_CONE_SLANTS = []   # (radius, half height) of cone slants met by the last span_dirs calls


def span_dirs(s, d, tol):
    """directions (local) spanning the support set of s along local direction d, where support
    values within tol (absolute) of the maximum count as on the set"""
    t = s["type"]
    d = ld(d); d = d / np.sqrt(np.sum(d * d))
    if t in ("sphere", "ellipsoid", "point"): return []
    if t in ("segment", "triangle", "polytope"):
        Q = ld(s["points"]); v = Q @ d
        on = Q[v >= v.max() - tol]
        return [q - on[0] for q in on[1:] if np.max(np.abs(q - on[0])) > 0]
    if t == "box":
        h = ld(s["half_extents"])
        return [ld(np.eye(3)[i]) for i in range(3) if 2 * h[i] * abs(d[i]) <= tol]
    if t in ("cylinder", "capsule", "cone"):
        r, h = LD(s["radius"]), LD(s["half_height"])
        rho = np.sqrt(d[0] ** 2 + d[1] ** 2)
        out = []
        if t == "cylinder":
            if r * rho <= tol: out += [ld([1, 0, 0]), ld([0, 1, 0])]
            if 2 * h * abs(d[2]) <= tol: out.append(ld([0, 0, 1]))
            return out
        if t == "capsule":
            return [ld([0, 0, 1])] if 2 * h * abs(d[2]) <= tol else []
        apex, rim = h * d[2], r * rho - h * d[2]
        if r * rho <= tol and d[2] < 0: out += [ld([1, 0, 0]), ld([0, 1, 0])]
        elif abs(apex - rim) <= tol and rho > 0:
            v = ld([r * d[0] / rho, r * d[1] / rho, -2 * h])
            _CONE_SLANTS.append((r, h))
            out.append(v)
        return out
    if t == "sum": return span_dirs(s["shapes"][0], d, tol) + span_dirs(s["shapes"][1], d, tol)
    if t == "rounded": return span_dirs(s["shape"], d, tol)
    raise ValueError(t)


def world_span(s, pose, u, tol, sign=1):
    """span directions (world) and the cone slants among them: (r, h, R, sign)"""
    t, R = pose_of(pose, LD)
    del _CONE_SLANTS[:]
    V = [R @ v for v in span_dirs(s, R.T @ ld(u), tol)]
    return V, [(r, h, R, sign) for r, h in _CONE_SLANTS]


def _rank_dirs(V):
    if not V: return 0, None
    M = np.array([np.asarray(v, float) / np.linalg.norm(np.asarray(v, float)) for v in V])
    _, sv, Vt = np.linalg.svd(M)
    rank = int(np.sum(sv > 1e-6 * sv[0]))
    return rank, Vt


def _bisect(slope, x0):
    lo, hi = x0 - LD(1e-3), x0 + LD(1e-3)
    slo, shi = slope(lo), slope(hi)
    k = 0
    while slo * shi > 0 and k < 6:
        lo, hi = x0 - (x0 - lo) * 4, x0 + (hi - x0) * 4; slo, shi = slope(lo), slope(hi); k += 1
    if slo * shi > 0: return None
    for _ in range(200):
        mid = (lo + hi) / 2
        sm = slope(mid)
        if (sm > 0) == (shi > 0): hi, shi = mid, sm
        else: lo, slo = mid, sm
        if hi - lo < 1e-19 * max(1, abs(float(mid))): break
    return (lo + hi) / 2


def structured_min(P, pa, C, pb, n0, size, tol_rel=1e-6):
    """The minimum of F(u) = h_P(u) + h_C(-u) near n0, found from the structure of the support
    sets there: both sets together span a plane (a face, or two crossing edges): the plane's
    normal; a line: the minimum on the circle of directions orthogonal to it (a root of the
    slope along the circle, by bisection in long double); nothing: a smooth minimum (2D Newton
    on the tangential part of the support point of P - C). Returns (value, u, kind)."""
    F = pair_fn(P, pa, C, pb, LD)
    u = ld(n0); u /= np.sqrt(np.sum(u * u))
    tol = tol_rel * size
    def w_of(u):
        a, _ = world_support(P, pa, u); b, _ = world_support(C, pb, -u)
        return a - b
    def spans(u):
        VP, kP = world_span(P, pa, u, tol, 1); VC, kC = world_span(C, pb, -u, tol, -1)
        V = [v - (v @ u) * u for v in VP + VC]
        V = [v for v in V if np.sqrt(np.sum(v * v)) > 1e-12 * size]
        return V, kP + kC
    V, cones = spans(u)
    rank, Vt = _rank_dirs(V)
    if rank >= 2:
        # the plane's normal; a cone's slant turns with the direction: iterate
        for _ in range(12):
            m = np.cross(ld(Vt[0]), ld(Vt[1])); m /= np.sqrt(np.sum(m * m))
            if m @ u < 0: m = -m
            moved = float(np.sqrt(np.sum(np.cross(m, u) ** 2)))
            u = m
            if not cones or moved < 1e-17: break
            V, cones = spans(u)
            rank, Vt = _rank_dirs(V)
            if rank < 2: return None
        return float(F(u[None, :])[0]), u, "plane"
    if rank == 1 and cones:
        # the kink of a cone's slant: the directions at its slant normal's polar angle (a small
        # circle), by azimuth psi; the slope along it is the azimuthal direction dotted with
        # any support point of P - C (the slant segment lies across it)
        r_, h_, R_, sg = cones[0]
        loc = R_.T @ (sg * u)
        psi0 = np.arctan2(loc[1], loc[0])
        k = LD(r_) / (2 * LD(h_))
        def u_of(psi):
            v = ld([np.cos(psi), np.sin(psi), k]); v /= np.sqrt(np.sum(v * v))
            return sg * (R_ @ v)
        def slope(psi):
            dv = ld([-np.sin(psi), np.cos(psi), 0])
            return (sg * (R_ @ dv)) @ w_of(u_of(psi))
        root = _bisect(slope, psi0)
        if root is None: return None
        uu = u_of(root)
        return float(F(uu[None, :])[0]), uu, "cone_circle"
    if rank == 1:
        # the circle orthogonal to the set's own direction (not to its part across u: the tool's
        # normal may lie off the kink)
        dd = ld(Vt[0]); dd /= np.sqrt(np.sum(dd * dd))
        a = u - (u @ dd) * dd; a /= np.sqrt(np.sum(a * a)); b = np.cross(dd, a)
        def slope(phi):
            uu = np.cos(phi) * a + np.sin(phi) * b
            du = -np.sin(phi) * a + np.cos(phi) * b
            return du @ w_of(uu)
        phi = _bisect(slope, LD(0))
        if phi is None: return None
        uu = np.cos(phi) * a + np.sin(phi) * b
        return float(F(uu[None, :])[0]), uu, "circle"
    # smooth: Newton on g(u) = tangential part of w(u); stops when |g| stops falling (its
    # rounding floor), keeping the best
    best_u, best_g = u, None
    for it in range(30):
        e1, e2 = _basis(u)
        w = w_of(u); g = ld([e1 @ w, e2 @ w])
        gn = np.sqrt(np.sum(g * g))
        if best_g is None or gn < best_g: best_u, best_g = u, gn
        elif gn > 0.5 * best_g and it > 2: break
        if gn == 0: break
        J = np.zeros((2, 2), dtype=LD); hstep = LD(1e-9)
        for j, e in enumerate((e1, e2)):
            up = u + hstep * e; up /= np.sqrt(np.sum(up * up))
            wp = w_of(up)
            J[:, j] = (ld([e1 @ wp, e2 @ wp]) - g) / hstep
        try:
            step = np.linalg.solve(J.astype(float), (-g).astype(float))
        except np.linalg.LinAlgError:
            return None
        step = ld(step)
        if np.max(np.abs(step)) > 1e-2: step *= LD(1e-2) / np.max(np.abs(step))
        u = u + step[0] * e1 + step[1] * e2; u /= np.sqrt(np.sum(u * u))
    u = best_u
    return float(F(u[None, :])[0]), u, "smooth"
