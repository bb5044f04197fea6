"""Independent support-function oracle for mink probe 50."""
import numpy as np

def quat_to_R(q, dt=np.float64):
    w, x, y, z = [dt(v) for v in q]
    return np.array([
        [1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
        [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
        [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]], dtype=dt)

def _norm(U):
    return np.sqrt(np.sum(U*U, axis=1))

def support_local(s, U):
    """h(u) for rows of U (N,3), shape s in its own frame (JSON dict)."""
    t = s["type"]
    dt = U.dtype
    if t == "sphere":
        return dt.type(s["radius"]) * _norm(U)
    if t == "box":
        h = np.array(s["half_extents"], dtype=dt)
        return np.abs(U) @ h
    if t == "capsule":
        return dt.type(s["half_height"]) * np.abs(U[:, 2]) + dt.type(s["radius"]) * _norm(U)
    if t == "cylinder":
        return dt.type(s["half_height"]) * np.abs(U[:, 2]) + dt.type(s["radius"]) * np.sqrt(U[:, 0]**2 + U[:, 1]**2)
    if t == "cone":
        h = dt.type(s["half_height"]); r = dt.type(s["radius"])
        rho = np.sqrt(U[:, 0]**2 + U[:, 1]**2)
        return np.maximum(h*U[:, 2], r*rho - h*U[:, 2])
    if t == "ellipsoid":
        r = np.array(s["radii"], dtype=dt)
        return _norm(U * r)
    if t in ("polytope", "point", "segment", "triangle"):
        P = np.array(s["points"], dtype=dt)
        return np.max(U @ P.T, axis=1)
    if t == "sum":
        return support_local(s["shapes"][0], U) + support_local(s["shapes"][1], U)
    if t == "rounded":
        return support_local(s["shape"], U) + dt.type(s["radius"]) * _norm(U)
    raise ValueError(t)

def bounding_radius(s):
    t = s["type"]
    if t == "sphere": return s["radius"]
    if t == "box": return float(np.linalg.norm(s["half_extents"]))
    if t == "capsule": return s["radius"] + s["half_height"]
    if t in ("cylinder", "cone"): return float(np.hypot(s["radius"], s["half_height"]))
    if t == "ellipsoid": return max(s["radii"])
    if t in ("polytope", "point", "segment", "triangle"):
        return float(max(np.linalg.norm(p) for p in s["points"]))
    if t == "sum": return bounding_radius(s["shapes"][0]) + bounding_radius(s["shapes"][1])
    if t == "rounded": return bounding_radius(s["shape"]) + s["radius"]
    raise ValueError(t)

def pose_of(p, dt=np.float64):
    p = p or {}
    t = np.array(p.get("t", [0, 0, 0]), dtype=dt)
    R = quat_to_R(p.get("q", [1, 0, 0, 0]), dt)
    return t, R

_fib_cache = {}
def fib(n, dt=np.float64):
    key = (n, dt)
    if key not in _fib_cache:
        i = np.arange(n, dtype=np.float64) + 0.5
        phi = np.arccos(1 - 2*i/n)
        th = np.pi * (1 + 5**0.5) * i
        U = np.stack([np.cos(th)*np.sin(phi), np.sin(th)*np.sin(phi), np.cos(phi)], axis=1)
        _fib_cache[key] = U.astype(dt)
    return _fib_cache[key]

def pair_fn(a, pa, b, pb, dt=np.float64):
    """F(U) = h_A(u) + h_B(-u), computed relative to B's origin."""
    tA, RA = pose_of(pa, dt); tB, RB = pose_of(pb, dt)
    d = tA - tB
    def F(U):
        U = U.astype(dt, copy=False)
        return U @ d + support_local(a, U @ RA) + support_local(b, -(U @ RB))
    return F

def member_fn(s, p, x, dt=np.float64):
    """F(U) = h_K(u) - u.x; min over unit u = -(signed distance of x to K)."""
    t, R = pose_of(p, dt)
    d = t - np.array(x, dtype=dt)
    def F(U):
        U = U.astype(dt, copy=False)
        return U @ d + support_local(s, U @ R)
    return F

def _basis(u):
    a = np.where(np.abs(u[:, [0]]) < 0.6, np.array([[1.0, 0, 0]]), np.array([[0, 1.0, 0]])).astype(u.dtype)
    e1 = np.cross(u, a); e1 /= _norm(e1)[:, None]
    e2 = np.cross(u, e1)
    return e1, e2

def minimize(F, ngrid=30000, nstarts=8, extra=(), rng=None, dt=np.float64, tol=1e-13, M=24):
    """Minimise F over the unit sphere. Returns (value, direction)."""
    rng = rng or np.random.default_rng(0)
    G = fib(ngrid, dt)
    v = F(G)
    idx = np.argsort(v)[:nstarts * 6]
    # keep distinct starts
    starts = []
    for i in idx:
        if all(np.dot(G[i], G[j]) < 0.999 for j in starts):
            starts.append(i)
        if len(starts) >= nstarts: break
    S = [G[i] for i in starts]
    for e in extra:
        e = np.asarray(e, dtype=dt)
        n = np.linalg.norm(e)
        if n > 0 and np.all(np.isfinite(e)): S.append(e / n)
    S = np.array(S, dtype=dt)
    S /= _norm(S)[:, None]
    fv = F(S)
    k = len(S)
    r = np.full(k, 2.0 * np.sqrt(4*np.pi/ngrid))
    r[len(starts):] = 1e-3  # extra starts are probably already good
    fails = np.zeros(k, int)
    for it in range(400):
        active = r > tol
        if not active.any(): break
        ia = np.nonzero(active)[0]
        u = S[ia]
        e1, e2 = _basis(u)
        ph = rng.uniform(0, 2*np.pi, size=(len(ia), 1)) + np.linspace(0, 2*np.pi, M, endpoint=False)[None, :]
        rr = r[ia][:, None] * np.concatenate([np.ones(M//2), 0.5*np.ones(M - M//2)])[None, :]
        C = (np.cos(rr)[..., None] * u[:, None, :] +
             np.sin(rr)[..., None] * (np.cos(ph)[..., None] * e1[:, None, :] + np.sin(ph)[..., None] * e2[:, None, :]))
        C = C.reshape(-1, 3)
        C /= _norm(C)[:, None]
        fc = F(C).reshape(len(ia), M)
        j = np.argmin(fc, axis=1)
        best = fc[np.arange(len(ia)), j]
        better = best < fv[ia]
        for q, i in enumerate(ia):
            if better[q]:
                S[i] = C.reshape(len(ia), M, 3)[q, j[q]]
                fv[i] = best[q]
                fails[i] = 0
                r[i] = min(r[i] * 1.5, 0.3)
            else:
                fails[i] += 1
                if fails[i] >= 2:
                    r[i] *= 0.35; fails[i] = 0
    i = int(np.argmin(fv))
    return float(fv[i]), S[i].astype(np.float64)
