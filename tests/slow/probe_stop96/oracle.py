# Independent oracle for mink queries: support functions, GJK with certified bracket,
# exact hull-based depth for polyhedral cores, multi-start search of min h_D for curved shapes.
import numpy as np
from fractions import Fraction
from itertools import combinations
from scipy.spatial import ConvexHull
from scipy.optimize import minimize

def qmat(q):
    w, x, y, z = q
    return np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],
                     [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],
                     [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])

def _unit(N):
    nn = np.linalg.norm(N, axis=1, keepdims=True)
    nn[nn == 0] = 1
    return N / nn

def sup_local(s, N):
    """support points of shape s (local frame) for rows of N (k,3)."""
    t = s['type']
    k = N.shape[0]
    if t == 'sphere':
        return s['radius'] * _unit(N)
    if t == 'box':
        h = np.array(s['half_extents'], float)
        return np.where(N >= 0, 1.0, -1.0) * h
    if t in ('polytope', 'point', 'segment', 'triangle'):
        P = np.array(s['points'], float)
        idx = np.argmax(N @ P.T, axis=1)
        return P[idx]
    if t == 'capsule':
        r, h = s['radius'], s['half_height']
        out = r * _unit(N)
        out[:, 2] += np.where(N[:, 2] >= 0, h, -h)
        return out
    if t == 'cylinder':
        r, h = s['radius'], s['half_height']
        xy = N[:, :2]
        nxy = np.linalg.norm(xy, axis=1, keepdims=True)
        rad = np.where(nxy > 0, r * xy / np.where(nxy > 0, nxy, 1), 0.0)
        z = np.where(N[:, 2] >= 0, h, -h)[:, None]
        return np.hstack([rad, z])
    if t == 'cone':
        r, h = s['radius'], s['half_height']
        xy = N[:, :2]
        nxy = np.linalg.norm(xy, axis=1, keepdims=True)
        rad = np.where(nxy > 0, r * xy / np.where(nxy > 0, nxy, 1), 0.0)
        base = np.hstack([rad, -h * np.ones((k, 1))])
        apex = np.tile([0.0, 0.0, h], (k, 1))
        hb = np.sum(base * N, axis=1)
        ha = N[:, 2] * h
        return np.where((ha >= hb)[:, None], apex, base)
    if t == 'ellipsoid':
        D = np.array(s['radii'], float)
        DN = N * D
        nn = np.linalg.norm(DN, axis=1, keepdims=True)
        nn[nn == 0] = 1
        return DN * D / nn
    if t == 'sum':
        return sup_local(s['shapes'][0], N) + sup_local(s['shapes'][1], N)
    if t == 'rounded':
        return sup_local(s['shape'], N) + s['radius'] * _unit(N)
    raise ValueError(t)

def brad(s):
    t = s['type']
    if t == 'sphere': return s['radius']
    if t == 'box': return float(np.linalg.norm(s['half_extents']))
    if t in ('polytope', 'point', 'segment', 'triangle'):
        return float(np.max(np.linalg.norm(np.array(s['points'], float), axis=1)))
    if t == 'capsule': return s['radius'] + s['half_height']
    if t in ('cylinder', 'cone'): return float(np.hypot(s['radius'], s['half_height']))
    if t == 'ellipsoid': return float(max(s['radii']))
    if t == 'sum': return brad(s['shapes'][0]) + brad(s['shapes'][1])
    if t == 'rounded': return brad(s['shape']) + s['radius']
    raise ValueError(t)

def core_points(s):
    """(points, radius) if the shape is a polyhedral core plus a ball, else None."""
    t = s['type']
    if t == 'sphere': return np.zeros((1, 3)), s['radius']
    if t == 'box':
        h = np.array(s['half_extents'], float)
        sg = np.array([[i, j, k] for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)], float)
        return sg * h, 0.0
    if t in ('polytope', 'point', 'segment', 'triangle'):
        return np.array(s['points'], float), 0.0
    if t == 'capsule':
        return np.array([[0, 0, -s['half_height']], [0, 0, s['half_height']]], float), s['radius']
    if t == 'sum':
        a = core_points(s['shapes'][0]); b = core_points(s['shapes'][1])
        if a is None or b is None: return None
        P = (a[0][:, None, :] + b[0][None, :, :]).reshape(-1, 3)
        return P, a[1] + b[1]
    if t == 'rounded':
        a = core_points(s['shape'])
        if a is None: return None
        return a[0], a[1] + s['radius']
    return None

def flat_normals(s):
    """candidate face normals (local frame) of polyhedral parts, for seeding."""
    t = s['type']
    if t == 'box' or t == 'cylinder' or t == 'cone' or t == 'capsule':
        return [np.eye(3)]
    if t in ('polytope', 'triangle', 'segment'):
        P = np.array(s['points'], float)
        out = [np.eye(3)]
        if len(P) >= 3:
            try:
                H = ConvexHull(P)
                out.append(H.equations[:, :3])
            except Exception:
                pass
            c = P - P.mean(0)
            u, sv, vt = np.linalg.svd(c)
            out.append(vt)
        return out
    if t == 'sum': return flat_normals(s['shapes'][0]) + flat_normals(s['shapes'][1])
    if t == 'rounded': return flat_normals(s['shape'])
    return []

class Posed:
    def __init__(self, s, pose, origin):
        self.s = s
        q = pose.get('q', [1, 0, 0, 0]) if pose else [1, 0, 0, 0]
        t = pose.get('t', [0, 0, 0]) if pose else [0, 0, 0]
        self.R = qmat(np.array(q, float))
        # translation relative to a common origin, computed exactly then rounded
        self.t = np.array([float(Fraction(t[i]) - Fraction(origin[i])) for i in range(3)])
    def sup(self, N):
        N = np.atleast_2d(N)
        return sup_local(self.s, N @ self.R) @ self.R.T + self.t
    def h(self, N):
        N = np.atleast_2d(N)
        return np.sum(sup_local(self.s, N @ self.R) @ self.R.T * N, axis=1) + N @ self.t

def fib(n):
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    th = np.pi * (1 + 5 ** 0.5) * i
    return np.stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)], 1)

# ---------------- GJK on D = A - B (distance from origin to D) -------------
def _closest_simplex(W):
    best = None
    k = len(W)
    for m in range(min(k, 4), 0, -1):
        for sub in combinations(range(k), m):
            P = W[list(sub)]
            if m == 1:
                lam = np.array([1.0]); v = P[0]
            else:
                E = (P[1:] - P[0]).T
                mu, *_ = np.linalg.lstsq(E, -P[0], rcond=None)
                lam = np.concatenate([[1 - mu.sum()], mu])
                if np.any(lam < -1e-13):
                    continue
                lam = np.clip(lam, 0, None); lam /= lam.sum()
                v = lam @ P
            nv = np.dot(v, v)
            if best is None or nv < best[0] - 1e-30:
                best = (nv, sub, lam, v)
    return best

def gjk(supD, tol_abs, maxit=300, init=None):
    """supD(n) -> (d, a, b) with d = a - b minimising n.d.  Returns dict with
    lo (certified lower bound of dist), hi (upper bound), a, b witness (convex combos), v."""
    n0 = init if init is not None else np.array([1.0, 0.3, 0.1])
    d, a, b = supD(n0)  # some point
    W = [d]; As = [a]; Bs = [b]
    v = d.copy(); lam = np.array([1.0])
    lo = -np.inf
    best_hi = np.linalg.norm(v); best_ab = (a, b); best_dir = None
    for it in range(maxit):
        nv = np.linalg.norm(v)
        if nv <= 1e-300:
            return dict(lo=max(lo, 0.0), hi=0.0, a=best_ab[0], b=best_ab[1], inside=True, it=it, dir=best_dir)
        u = v / nv
        w, wa, wb = supD(u)       # minimises u.d
        low = float(np.dot(u, w))
        if low > lo:
            lo = low; best_dir = u
        if nv - lo <= tol_abs:
            break
        if any(np.array_equal(w, x) for x in W):
            break
        W.append(w); As.append(wa); Bs.append(wb)
        Wa = np.array(W)
        nvv, sub, lam, v = _closest_simplex(Wa)
        W = [W[i] for i in sub]; As = [As[i] for i in sub]; Bs = [Bs[i] for i in sub]
        av = lam @ np.array(As); bv = lam @ np.array(Bs)
        hi = np.linalg.norm(av - bv)
        if hi < best_hi:
            best_hi = hi; best_ab = (av, bv)
        if len(W) == 4 and np.sqrt(nvv) < 1e-14 * tol_abs * 1e3:
            return dict(lo=max(lo, 0.0), hi=0.0, a=av, b=bv, inside=True, it=it, dir=best_dir)
    return dict(lo=max(lo, 0.0) if lo > -np.inf else 0.0, hi=best_hi, a=best_ab[0], b=best_ab[1],
                inside=(best_hi <= tol_abs), it=it, dir=best_dir)

def make_supD(A, B):
    def supD(n):
        n = np.asarray(n, float)
        a = A.sup(-n)[0]; b = B.sup(n)[0]
        return a - b, a, b
    return supD

def point_dist(S, p, tol_abs):
    """certified bracket of distance from point p to posed shape S."""
    def supD(n):
        a = S.sup(-np.asarray(n, float))[0]
        return a - p, a, p
    return gjk(supD, tol_abs)

# ---------------- depth search ----------------
def hD(A, B, N):
    N = np.atleast_2d(N)
    return A.h(N) + B.h(-N)

def tangent_basis(n):
    a = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    e1 = np.cross(n, a); e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    return e1, e2

def refine(A, B, n0, step=0.05, iters=3):
    n = n0 / np.linalg.norm(n0)
    fbest = hD(A, B, n)[0]
    for k in range(iters):
        e1, e2 = tangent_basis(n)
        def f(x):
            m = n + x[0] * e1 + x[1] * e2
            m = m / np.linalg.norm(m)
            return hD(A, B, m)[0]
        st = step * (10.0 ** (-2 * k))
        res = minimize(f, np.zeros(2), method='Nelder-Mead',
                       options=dict(initial_simplex=np.array([[0, 0], [st, 0], [0, st]]),
                                    xatol=1e-15, fatol=0.0, maxiter=600, maxfev=900))
        if res.fun <= fbest:
            m = n + res.x[0] * e1 + res.x[1] * e2
            n = m / np.linalg.norm(m); fbest = hD(A, B, n)[0]
    return fbest, n

def min_hD(A, B, seeds=(), ngrid=3000, nref=4, size=1.0):
    """estimate min over unit n of h_D(n) (an upper bound, certified by the direction)."""
    G = fib(ngrid)
    S = [G]
    for s in seeds:
        s = np.atleast_2d(np.asarray(s, float))
        S.append(s); S.append(-s)
    for P, fl in ((A, flat_normals(A.s)), (B, flat_normals(B.s))):
        for M in fl:
            M = np.atleast_2d(M) @ P.R.T
            S.append(M); S.append(-M)
    C = _unit(np.vstack(S))
    vals = hD(A, B, C)
    order = np.argsort(vals)
    picked = []
    for i in order:
        if len(picked) >= nref: break
        if all(np.dot(C[i], C[j]) < 0.999 for j in picked) or len(picked) == 0:
            picked.append(i)
    best = (vals[order[0]], C[order[0]])
    seedset = [C[i] for i in picked] + [np.asarray(s, float) for s in seeds]
    for n0 in seedset:
        f, n = refine(A, B, np.asarray(n0, float).ravel())
        if f < best[0]:
            best = (f, n)
    return best

def poly_exact(A, B):
    """exact signed value min h_D for polyhedral cores (+ radius): returns (m, n) or None."""
    ca = core_points(A.s); cb = core_points(B.s)
    if ca is None or cb is None: return None
    PA = ca[0] @ A.R.T + A.t; PB = cb[0] @ B.R.T + B.t
    r = ca[1] + cb[1]
    D = (PA[:, None, :] - PB[None, :, :]).reshape(-1, 3)
    try:
        H = ConvexHull(D)
    except Exception:
        return None
    eq = H.equations  # n.x + c <= 0 inside
    # check full-dimensionality: thickness
    ext = D.max(0) - D.min(0)
    offs = -eq[:, 3]
    i = np.argmin(offs)
    # use exact evaluation of h on the facet normal
    n = eq[i, :3] / np.linalg.norm(eq[i, :3])
    hv = np.max(D @ n)
    if hv > 0:   # origin strictly inside core hull: depth = min facet offset (recomputed)
        hs = np.max(D @ (eq[:, :3] / np.linalg.norm(eq[:, :3], axis=1, keepdims=True)).T, axis=0)
        j = np.argmin(hs)
        n = eq[j, :3] / np.linalg.norm(eq[j, :3])
        return hs[j] + r, n, 'core_in'
    return None  # outside: use GJK
