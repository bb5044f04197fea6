"""Closed-form signed distance of a point to a shape (positive outside, negative inside), used to
confirm what the sampled oracle suspects. Shapes: sphere, box, capsule, cylinder, cone, point, segment,
triangle, rounded of these, sum of one of these with a point/sphere, sum of a cone/cylinder with a
z-axis capsule/segment (solids of revolution). Returns None when it has no closed form."""
import numpy as np
from oracle import pose_of

def _seg_dist(p, a, b):
    ab = b - a; t = np.clip(np.dot(p - a, ab) / max(np.dot(ab, ab), 1e-300), 0, 1)
    return float(np.linalg.norm(p - (a + t * ab)))

def _poly2d_sd(P, V):
    """signed distance of 2D point P to convex polygon V (ccw or cw)"""
    d = min(_seg_dist(P, V[i], V[(i + 1) % len(V)]) for i in range(len(V)))
    inside = True
    sgn = None
    for i in range(len(V)):
        e = V[(i + 1) % len(V)] - V[i]; w = P - V[i]
        c = e[0] * w[1] - e[1] * w[0]
        if c != 0:
            if sgn is None: sgn = np.sign(c)
            elif np.sign(c) != sgn: inside = False
    return -d if inside else d

def _tri_dist(p, A, B, C):
    n = np.cross(B - A, C - A); nn = np.linalg.norm(n)
    if nn == 0: return min(_seg_dist(p, A, B), _seg_dist(p, B, C), _seg_dist(p, A, C))
    n /= nn
    q = p - np.dot(p - A, n) * n
    # inside test by barycentric signs
    s = [np.dot(np.cross(Y - X, q - X), n) for X, Y in ((A, B), (B, C), (C, A))]
    if all(v >= 0 for v in s) or all(v <= 0 for v in s): return abs(float(np.dot(p - A, n)))
    return min(_seg_dist(p, A, B), _seg_dist(p, B, C), _seg_dist(p, A, C))

def rev_profile(s):
    """2D (rho, z) polygon of a solid of revolution about z, and extra radius; or None"""
    t = s["type"]
    if t == "cylinder":
        r, h = s["radius"], s["half_height"]; return np.array([(0, -h), (r, -h), (r, h), (0, h)], float), 0.0
    if t == "cone":
        r, h = s["radius"], s["half_height"]; return np.array([(0, -h), (r, -h), (0, h)], float), 0.0
    if t == "capsule":
        h = s["half_height"]; return np.array([(0, -h), (0, h)], float), s["radius"]
    if t == "sphere": return np.array([(0, 0.0)]), s["radius"]
    return None

def sd_local(s, x):
    t = s["type"]
    if t == "sphere": return float(np.linalg.norm(x) - s["radius"])
    if t == "box":
        h = np.array(s["half_extents"]); q = np.abs(x) - h
        return float(np.linalg.norm(np.maximum(q, 0)) + min(max(q[0], q[1], q[2]), 0))
    if t == "capsule":
        h = s["half_height"]; return _seg_dist(x, np.array([0, 0, -h]), np.array([0, 0, h])) - s["radius"]
    if t in ("cylinder", "cone"):
        V, _ = rev_profile(s)
        P = np.array([np.hypot(x[0], x[1]), x[2]])
        V2 = np.concatenate([V, (V * [-1, 1])[::-1][1:-1]]) if len(V) > 2 else V
        # mirror to a full convex polygon in (rho, z) with rho of either sign
        W = np.concatenate([V, (V[::-1] * [-1, 1])])
        W = np.unique(W.round(300), axis=0) if False else W
        return _poly2d_sd(P, _hull2d(W))
    if t == "point": return float(np.linalg.norm(x - np.array(s["points"][0])))
    if t == "segment": return _seg_dist(x, np.array(s["points"][0]), np.array(s["points"][1]))
    if t == "triangle":
        A, B, C = (np.array(p) for p in s["points"]); return _tri_dist(x, A, B, C)
    if t == "rounded":
        d = sd_local(s["shape"], x)
        return None if d is None else d - s["radius"]
    if t == "sum":
        p, q = s["shapes"]
        for u, v in ((p, q), (q, p)):
            if v["type"] == "point": return sd_local(u, x - np.array(v["points"][0]))
            if v["type"] == "sphere":
                d = sd_local(u, x); return None if d is None else d - v["radius"]
        for u, v in ((p, q), (q, p)):
            if u["type"] in ("cylinder", "cone", "capsule", "sphere") and v["type"] in ("capsule", "sphere", "cylinder", "cone"):
                Pu, ru = rev_profile(u); Pv, rv = rev_profile(v)
                W = np.array([a + b for a in np.concatenate([Pu, Pu * [-1, 1]]) for b in np.concatenate([Pv, Pv * [-1, 1]])])
                H = _hull2d(W)
                P = np.array([np.hypot(x[0], x[1]), x[2]])
                d = _poly2d_sd(P, H) if len(H) >= 3 else min(_seg_dist(P, H[i], H[(i + 1) % len(H)]) for i in range(len(H)))
                return d - ru - rv
    return None

def _hull2d(P):
    P = sorted(set(map(tuple, np.asarray(P, float))))
    if len(P) <= 2: return np.array(P)
    def cross(o, a, b): return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lo, hi = [], []
    for p in P:
        while len(lo) >= 2 and cross(lo[-2], lo[-1], p) <= 0: lo.pop()
        lo.append(p)
    for p in reversed(P):
        while len(hi) >= 2 and cross(hi[-2], hi[-1], p) <= 0: hi.pop()
        hi.append(p)
    return np.array(lo[:-1] + hi[:-1])

def signed_distance(s, pose, x):
    t, R = pose_of(pose)
    return sd_local(s, R.T @ (np.asarray(x, float) - t))

def hull_planes(points, tool="../../../build/release/tools/mink/mink"):
    """face planes of a point set from `mink hull`, each verified here: every point on or below it"""
    import json, subprocess
    out = subprocess.run([tool, "hull"], input=json.dumps({"id": 0, "points": points}) + "\n", capture_output=True, text=True).stdout
    h = json.loads(out)
    N = np.array(h["normals"]); d = np.array(h["offsets"]); P = np.array(points)
    viol = float(np.max(P @ N.T - d[None, :]))
    return N, d, viol, h

def poly_sd_inside(points, pose, x):
    """max over face planes of n.x - d: exact signed distance for points inside the hull (<= 0)"""
    t, R = pose_of(pose)
    N, d, viol, h = hull_planes(points)
    xl = R.T @ (np.asarray(x, float) - t)
    return float(np.max(N @ xl - d)), viol
