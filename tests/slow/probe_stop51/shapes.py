"""Random shapes and poses for probe 51 (own generators; the oracle is probe 50's oracle.py)."""
import numpy as np

class Gen:
    def __init__(self, seed):
        self.rng = np.random.default_rng(seed)

    def U(self, a, b): return float(self.rng.uniform(a, b))
    def LU(self, a, b): return float(10 ** self.rng.uniform(np.log10(a), np.log10(b)))

    def rquat(self):
        q = self.rng.normal(size=4); q /= np.linalg.norm(q)
        return [float(v) for v in q]

    def axis_quat(self, ang, ax=None):
        if ax is None:
            ax = self.rng.normal(size=3)
        ax = np.asarray(ax, float); ax = ax / np.linalg.norm(ax)
        return [float(np.cos(ang / 2))] + [float(v) for v in np.sin(ang / 2) * ax]

    def tilt_quat(self, ang):  # small rotation about a random horizontal axis
        th = self.U(0, 2 * np.pi)
        return self.axis_quat(ang, [np.cos(th), np.sin(th), 0.0])

    def pts(self, n, L):
        P = self.rng.normal(size=(n, 3)) * L * np.array([self.U(0.3, 1) for _ in range(3)])
        return [[float(c) for c in p] for p in P]

    # ---------- polytopes ----------
    def poly_random(self, L, n=None):
        n = n or int(self.rng.integers(4, 201))
        if self.rng.uniform() < 0.5:   # points on a sphere-ish surface: many hull vertices
            P = self.rng.normal(size=(n, 3)); P /= np.linalg.norm(P, axis=1)[:, None]
            P *= L * np.array([self.U(0.3, 1) for _ in range(3)])
            P = [[float(c) for c in p] for p in P]
        else:
            P = self.pts(n, L)
        return {"type": "polytope", "points": P}

    def poly_flat(self, L, thick=None):
        """Points in a plane (through the origin, random orientation) plus thickness."""
        n = int(self.rng.integers(4, 60))
        P = self.rng.normal(size=(n, 3)) * L * np.array([self.U(0.3, 1), self.U(0.3, 1), 0.0])
        if thick is not None:
            P[:, 2] = self.rng.uniform(-1, 1, size=n) * thick
            P[0, 2] = thick; P[1, 2] = -thick
        R = quat_to_R(self.rquat())
        P = P @ R.T
        return {"type": "polytope", "points": [[float(c) for c in p] for p in P]}

    def poly_needle(self, L, spread=None):
        """Two clusters of points at the ends of a segment; cluster spread tiny."""
        n = int(self.rng.integers(2, 12))
        spread = spread if spread is not None else self.LU(1e-12, 1e-4) * L
        d = self.rng.normal(size=3); d /= np.linalg.norm(d)
        P = []
        for c in (d * L, -d * L * self.U(0.3, 1)):
            Q = c + self.rng.normal(size=(n, 3)) * spread
            P += [[float(x) for x in q] for q in Q]
        return {"type": "polytope", "points": P}

    def poly_dups(self, L):
        base = self.pts(int(self.rng.integers(4, 9)), L)
        k = int(self.rng.integers(20, 200))
        P = [base[int(i)] for i in self.rng.integers(len(base), size=k)] + base
        return {"type": "polytope", "points": P}

    def prism(self, k, r, hz, even=False):
        ang = np.sort(self.rng.uniform(0, 2 * np.pi, size=k))
        if even: ang = (np.arange(k) + self.rng.uniform(-0.3, 0.3, size=k)) * 2 * np.pi / k
        if k <= 4: ang = np.arange(k) * 2 * np.pi / k + self.U(0, 1)
        rad = r * self.rng.uniform(0.7, 1.0, size=k)
        P = []
        for z in (-hz, hz):
            P += [[float(rad[i] * np.cos(ang[i])), float(rad[i] * np.sin(ang[i])), float(z)] for i in range(k)]
        return {"type": "polytope", "points": P}

    # ---------- basics ----------
    KINDS = ["sphere", "box", "capsule", "cylinder", "cone", "ellipsoid", "polytope", "poly_flat", "poly_needle",
             "segment", "triangle", "point"]

    def basic(self, L, kinds=None):
        kinds = kinds or self.KINDS
        k = kinds[int(self.rng.integers(len(kinds)))]
        U = self.U
        if k == "sphere": return {"type": "sphere", "radius": L * U(0.3, 1)}
        if k == "box": return {"type": "box", "half_extents": [L * U(0.1, 1) for _ in range(3)]}
        if k in ("capsule", "cylinder", "cone"):
            return {"type": k, "radius": L * U(0.1, 1), "half_height": L * U(0.1, 1)}
        if k == "ellipsoid": return {"type": "ellipsoid", "radii": [L * U(0.2, 1) for _ in range(3)]}
        if k == "polytope": return self.poly_random(L)
        if k == "poly_flat": return self.poly_flat(L, None if self.rng.uniform() < 0.5 else L * self.LU(1e-12, 1e-7))
        if k == "poly_needle": return self.poly_needle(L)
        if k == "segment": return {"type": "segment", "points": self.pts(2, L)}
        if k == "triangle": return {"type": "triangle", "points": self.pts(3, L)}
        if k == "point": return {"type": "point", "points": self.pts(1, 0.3 * L)}
        raise ValueError(k)

    def any_shape(self, L, kinds=None):
        r = self.rng.uniform()
        if r < 0.55: return self.basic(L, kinds)
        if r < 0.78: return {"type": "sum", "shapes": [self.basic(0.6 * L, kinds), self.basic(0.6 * L, kinds)]}
        return {"type": "rounded", "shape": self.basic(L, kinds), "radius": L * self.LU(1e-3, 0.5)}


def quat_to_R(q):
    w, x, y, z = q
    return np.array([
        [1 - 2*(y*y + z*z), 2*(x*y - w*z), 2*(x*z + w*y)],
        [2*(x*y + w*z), 1 - 2*(x*x + z*z), 2*(y*z - w*x)],
        [2*(x*z - w*y), 2*(y*z + w*x), 1 - 2*(x*x + y*y)]])

def qmul(a, b):
    w1, x1, y1, z1 = a; w2, x2, y2, z2 = b
    q = np.array([w1*w2 - x1*x2 - y1*y2 - z1*z2, w1*x2 + x1*w2 + y1*z2 - z1*y2,
                  w1*y2 - x1*z2 + y1*w2 + z1*x2, w1*z2 + x1*y2 - y1*x2 + z1*w2])
    q /= np.linalg.norm(q)
    return [float(v) for v in q]

def scale_shape(s, k):
    s = dict(s); t = s["type"]
    if "radius" in s: s["radius"] = s["radius"] * k
    if "half_height" in s: s["half_height"] = s["half_height"] * k
    if "half_extents" in s: s["half_extents"] = [v * k for v in s["half_extents"]]
    if "radii" in s: s["radii"] = [v * k for v in s["radii"]]
    if "points" in s: s["points"] = [[v * k for v in p] for p in s["points"]]
    if t == "sum": s["shapes"] = [scale_shape(x, k) for x in s["shapes"]]
    if t == "rounded": s["shape"] = scale_shape(s["shape"], k)
    return s
