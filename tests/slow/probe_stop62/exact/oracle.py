# Exact oracle for polyhedral pairs (integer arithmetic on a common dyadic grid).
from fractions import Fraction as F
import math, random
import mpmath
mpmath.mp.prec = 300

# ---------- exact shape -> world points ----------
def quat_R(q):
    w, x, y, z = [F(v) for v in q]
    n = w*w + x*x + y*y + z*z
    R = [[w*w+x*x-y*y-z*z, 2*(x*y-w*z), 2*(x*z+w*y)],
         [2*(x*y+w*z), w*w-x*x+y*y-z*z, 2*(y*z-w*x)],
         [2*(x*z-w*y), 2*(y*z+w*x), w*w-x*x-y*y+z*z]]
    return [[v / n for v in row] for row in R]

def core_and_radius(s):
    """returns (list of local points as Fractions, radius Fraction, bounding radius float)"""
    t = s['type']
    if t == 'box':
        hx, hy, hz = [F(v) for v in s['half_extents']]
        pts = [(sx*hx, sy*hy, sz*hz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
        return pts, F(0)
    if t in ('polytope', 'point', 'segment', 'triangle'):
        return [tuple(F(v) for v in p) for p in s['points']], F(0)
    if t == 'sphere':
        return [(F(0), F(0), F(0))], F(s['radius'])
    if t == 'capsule':
        h = F(s['half_height'])
        return [(F(0), F(0), -h), (F(0), F(0), h)], F(s['radius'])
    if t == 'rounded':
        p, r = core_and_radius(s['shape'])
        return p, r + F(s['radius'])
    if t == 'sum':
        p1, r1 = core_and_radius(s['shapes'][0])
        p2, r2 = core_and_radius(s['shapes'][1])
        return [tuple(a[i]+b[i] for i in range(3)) for a in p1 for b in p2], r1 + r2
    raise ValueError(t)

def bounding_radius(s):
    t = s['type']
    if t == 'box':
        return math.sqrt(sum(v*v for v in s['half_extents']))
    if t in ('polytope', 'point', 'segment', 'triangle'):
        return max(math.sqrt(sum(v*v for v in p)) for p in s['points'])
    if t == 'sphere':
        return s['radius']
    if t == 'capsule':
        return s['radius'] + s['half_height']
    if t == 'rounded':
        return bounding_radius(s['shape']) + s['radius']
    if t == 'sum':
        return bounding_radius(s['shapes'][0]) + bounding_radius(s['shapes'][1])

def world_points(s, pose):
    pts, r = core_and_radius(s)
    pose = pose or {}
    t = [F(v) for v in pose.get('t', [0, 0, 0])]
    q = pose.get('q', [1, 0, 0, 0])
    R = quat_R(q)
    out = []
    for p in pts:
        out.append(tuple(R[i][0]*p[0] + R[i][1]*p[1] + R[i][2]*p[2] + t[i] for i in range(3)))
    return out, r

# ---------- integer vector helpers ----------
def sub(a, b): return (a[0]-b[0], a[1]-b[1], a[2]-b[2])
def add(a, b): return (a[0]+b[0], a[1]+b[1], a[2]+b[2])
def dot(a, b): return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def neg(a): return (-a[0], -a[1], -a[2])
def iszero(a): return a[0] == 0 and a[1] == 0 and a[2] == 0

def prim(v):
    g = math.gcd(math.gcd(abs(v[0]), abs(v[1])), abs(v[2]))
    return (v[0]//g, v[1]//g, v[2]//g) if g else v

def canon_dir(v):
    v = prim(v)
    for c in v:
        if c != 0:
            return v if c > 0 else neg(v)
    return v

# ---------- exact hull ----------
class Hull:
    # dim, verts (list of int tuples), tris (index triples, CCW from outside for dim 3;
    # for dim 2 a fan with normal +n), planes (list of (n, d) with n.x <= d), edges (index pairs),
    # edge_dirs (canonical primitive directions of real edges)
    pass

def affine_dim(pts):
    p0 = pts[0]
    basis = []
    for p in pts[1:]:
        v = sub(p, p0)
        if iszero(v):
            continue
        if not basis:
            basis.append(v); continue
        if len(basis) == 1:
            if not iszero(cross(basis[0], v)):
                basis.append(v)
            continue
        if len(basis) == 2:
            if dot(cross(basis[0], basis[1]), v) != 0:
                basis.append(v)
                break
    return len(basis), basis

def hull2d(pts2):
    pts2 = sorted(set(pts2))
    if len(pts2) <= 2:
        return pts2
    def cr(o, a, b): return (a[0]-o[0])*(b[1]-o[1]) - (a[1]-o[1])*(b[0]-o[0])
    lo = []
    for p in pts2:
        while len(lo) >= 2 and cr(lo[-2], lo[-1], p) <= 0:
            lo.pop()
        lo.append(p)
    up = []
    for p in reversed(pts2):
        while len(up) >= 2 and cr(up[-2], up[-1], p) <= 0:
            up.pop()
        up.append(p)
    return lo[:-1] + up[:-1]

def make_hull(pts):
    pts = list(dict.fromkeys(pts))  # dedupe exact
    h = Hull()
    d, basis = affine_dim(pts)
    h.dim = d
    if d == 0:
        h.verts = [pts[0]]; h.tris = []; h.planes = []; h.edges = []; h.edge_dirs = []
        return h
    if d == 1:
        u = basis[0]
        lo = min(pts, key=lambda p: dot(p, u)); hi = max(pts, key=lambda p: dot(p, u))
        h.verts = [lo, hi]; h.tris = []; h.planes = []; h.edges = [(0, 1)]
        h.edge_dirs = [canon_dir(u)]
        return h
    if d == 2:
        n = cross(basis[0], basis[1])
        ax = max(range(3), key=lambda i: abs(n[i]))
        keep = [i for i in range(3) if i != ax]
        m = {}
        for p in pts:
            m[(p[keep[0]], p[keep[1]])] = p
        poly = hull2d(list(m.keys()))
        verts = [m[q] for q in poly]
        # orient poly so that its normal is +n
        nn = cross(sub(verts[1], verts[0]), sub(verts[2], verts[0]))
        if dot(nn, n) < 0:
            verts = verts[::-1]
        k = len(verts)
        h.verts = verts
        h.tris = [(0, i, i+1) for i in range(1, k-1)]
        d0 = dot(n, verts[0])
        h.planes = [(n, d0), (neg(n), -d0)]
        h.edges = [(i, (i+1) % k) for i in range(k)]
        h.edge_dirs = list({canon_dir(sub(verts[j], verts[i])) for i, j in h.edges})
        h.normal = n
        return h
    # dim 3: incremental
    p0 = pts[0]
    i1 = next(i for i, p in enumerate(pts) if not iszero(sub(p, p0)))
    i2 = next(i for i, p in enumerate(pts) if not iszero(cross(sub(pts[i1], p0), sub(p, p0))))
    nrm = cross(sub(pts[i1], p0), sub(pts[i2], p0))
    i3 = next(i for i, p in enumerate(pts) if dot(nrm, sub(p, p0)) != 0)
    V = pts
    def orient(f, p):  # >0: p strictly above face f (outside)
        a, b, c = V[f[0]], V[f[1]], V[f[2]]
        return dot(cross(sub(b, a), sub(c, a)), sub(p, a))
    idx = [0, i1, i2, i3]
    if dot(nrm, sub(V[i3], p0)) > 0:
        faces = {(0, i2, i1), (0, i1, i3), (i1, i2, i3), (i2, 0, i3)}
    else:
        faces = {(0, i1, i2), (0, i3, i1), (i1, i3, i2), (i2, i3, 0)}
    for f in faces:
        for j in idx:
            assert orient(f, V[j]) <= 0
    order = [i for i in range(len(V)) if i not in idx]
    random.Random(1).shuffle(order)
    for pi in order:
        p = V[pi]
        vis = [f for f in faces if orient(f, p) > 0]
        if not vis:
            continue
        visset = set(vis)
        edge_face = {}
        for f in faces:
            for k in range(3):
                edge_face[(f[k], f[(k+1) % 3])] = f
        newf = []
        for f in vis:
            for k in range(3):
                e = (f[k], f[(k+1) % 3])
                g = edge_face[(e[1], e[0])]
                if g not in visset:
                    newf.append((e[0], e[1], pi))
        faces -= visset
        faces |= set(newf)
    used = sorted({i for f in faces for i in f})
    remap = {o: k for k, o in enumerate(used)}
    h.verts = [V[i] for i in used]
    h.tris = [tuple(remap[i] for i in f) for f in faces]
    planes = {}
    tri_plane = []
    for f in h.tris:
        a, b, c = h.verts[f[0]], h.verts[f[1]], h.verts[f[2]]
        n = cross(sub(b, a), sub(c, a))
        g = math.gcd(math.gcd(abs(n[0]), abs(n[1])), abs(n[2]))
        n = (n[0]//g, n[1]//g, n[2]//g)
        key = (n, dot(n, a))
        planes[key] = 1
        tri_plane.append(key)
    h.planes = list(planes.keys())
    edge_face = {}
    for ti, f in enumerate(h.tris):
        for k in range(3):
            edge_face[(f[k], f[(k+1) % 3])] = ti
    edges = []
    dirs = set()
    for (i, j), ti in edge_face.items():
        if i < j:
            edges.append((i, j))
            tj = edge_face[(j, i)]
            if tri_plane[ti] != tri_plane[tj]:
                dirs.add(canon_dir(sub(h.verts[j], h.verts[i])))
    h.edges = edges
    h.edge_dirs = list(dirs)
    # sanity: all points inside
    for p in pts:
        for (n, dd) in h.planes:
            assert dot(n, p) <= dd
    return h

def support(h, c):
    return max(dot(c, v) for v in h.verts)

# ---------- exact distance between hulls ----------
def less(a, b):  # compare (num, den) with den > 0
    return a[0]*b[1] < b[0]*a[1]

def closest_pair(A, B):
    """min over feature pairs; returns (num, den), recipe"""
    best = None; rec = None
    VA, VB = A.verts, B.verts
    def consider(val, r):
        nonlocal best, rec
        if best is None or less(val, best):
            best, rec = val, r
    for i, a in enumerate(VA):
        for j, b in enumerate(VB):
            w = sub(b, a)
            consider((dot(w, w), 1), ('vv', i, j))
    def ve(P, H, swap):
        for i, p in enumerate(P):
            for (e0, e1) in H.edges:
                a = H.verts[e0]; d = sub(H.verts[e1], a); w = sub(p, a)
                tn = dot(w, d); td = dot(d, d)
                if 0 < tn < td:
                    consider((dot(w, w)*td - tn*tn, td), ('ve', swap, i, e0, e1))
    ve(VA, B, False); ve(VB, A, True)
    for (a0i, a1i) in A.edges:
        a0 = VA[a0i]; d1 = sub(VA[a1i], a0)
        for (b0i, b1i) in B.edges:
            b0 = VB[b0i]; d2 = sub(VB[b1i], b0)
            cx = cross(d1, d2)
            den = dot(cx, cx)
            if den == 0:
                continue
            r = sub(a0, b0)
            aa = dot(d1, d1); bb = dot(d1, d2); cc = dot(d2, d2); dd = dot(d1, r); ee = dot(d2, r)
            dn = aa*cc - bb*bb
            sn = bb*ee - cc*dd; tn = aa*ee - bb*dd
            if 0 < sn < dn and 0 < tn < dn:
                x = dot(r, cx)
                consider((x*x, den), ('ee', a0i, a1i, b0i, b1i))
    def vf(P, H, swap):
        for (t0, t1, t2) in H.tris:
            v0, v1, v2 = H.verts[t0], H.verts[t1], H.verts[t2]
            n = cross(sub(v1, v0), sub(v2, v0))
            nn = dot(n, n)
            e01 = sub(v1, v0); e12 = sub(v2, v1); e20 = sub(v0, v2)
            for i, p in enumerate(P):
                if dot(n, cross(e01, sub(p, v0))) >= 0 and dot(n, cross(e12, sub(p, v1))) >= 0 \
                        and dot(n, cross(e20, sub(p, v2))) >= 0:
                    x = dot(n, sub(p, v0))
                    consider((x*x, nn), ('vf', swap, i, t0, t1, t2))
    vf(VA, B, False); vf(VB, A, True)
    return best, rec

def witness(A, B, rec):
    kind = rec[0]
    Fr = lambda v: tuple(F(c) for c in v)
    if kind == 'vv':
        return Fr(A.verts[rec[1]]), Fr(B.verts[rec[2]])
    if kind == 've':
        swap, i, e0, e1 = rec[1:]
        P, H = (B, A) if swap else (A, B)
        p = P.verts[i]; a = H.verts[e0]; d = sub(H.verts[e1], a)
        t = F(dot(sub(p, a), d), dot(d, d))
        q = tuple(a[k] + t*d[k] for k in range(3))
        return (Fr(q), Fr(p)) if swap else (Fr(p), Fr(q))
    if kind == 'ee':
        a0i, a1i, b0i, b1i = rec[1:]
        a0 = A.verts[a0i]; d1 = sub(A.verts[a1i], a0); b0 = B.verts[b0i]; d2 = sub(B.verts[b1i], b0)
        r = sub(a0, b0)
        aa = dot(d1, d1); bb = dot(d1, d2); cc = dot(d2, d2); dd = dot(d1, r); ee = dot(d2, r)
        dn = aa*cc - bb*bb
        s = F(bb*ee - cc*dd, dn); t = F(aa*ee - bb*dd, dn)
        return tuple(a0[k] + s*d1[k] for k in range(3)), tuple(b0[k] + t*d2[k] for k in range(3))
    if kind == 'vf':
        swap, i, t0, t1, t2 = rec[1:]
        P, H = (B, A) if swap else (A, B)
        p = P.verts[i]; v0, v1, v2 = H.verts[t0], H.verts[t1], H.verts[t2]
        n = cross(sub(v1, v0), sub(v2, v0))
        x = F(dot(n, sub(p, v0)), dot(n, n))
        q = tuple(p[k] - x*n[k] for k in range(3))
        return (q, Fr(p)) if swap else (Fr(p), q)

def hD(A, B, c):
    return support(A, c) + support(B, neg(c))

def depth_candidates(A, B):
    cands = set()
    for H in (A, B):
        if H.dim == 3:
            for (n, d) in H.planes:
                cands.add(canon_dir(n))
        elif H.dim == 2:
            cands.add(canon_dir(H.normal))
    for da in A.edge_dirs:
        for db in B.edge_dirs:
            c = cross(da, db)
            if not iszero(c):
                cands.add(canon_dir(c))
    return list(cands)

def isqrt_float(num, den):
    return float(mpmath.sqrt(mpmath.mpf(num) / mpmath.mpf(den)))

def mp_sqrt(num, den):
    return mpmath.sqrt(mpmath.mpf(num) / mpmath.mpf(den))

def float_support_all(H, ref):
    return [[float(x - r) for x, r in zip(v, ref)] for v in H.verts]

def solve_depth(A, B, scale_bits, extent_int):
    """min over candidate directions of hD(c)/|c|. returns (num_sq, den, c, val_sign) exact:
    depth^2 = num/den, with hD(c) >= 0.  Uses float prefilter with a wide margin, then exact."""
    import numpy as np
    cands = depth_candidates(A, B)
    ref = A.verts[0]
    # float prefilter in coordinates relative to ref, scaled by 2^-scale_bits
    sh = scale_bits
    def tofl(v):
        return [math.ldexp(float(x - r), 0) if abs(x - r) < (1 << 1000) else float('inf') for x, r in zip(v, ref)]
    Av = np.array([[float(F(x - r, sh)) for x, r in zip(v, ref)] for v in A.verts])
    Bv = np.array([[float(F(x - r, sh)) for x, r in zip(v, ref)] for v in B.verts])
    allc = cands + [neg(c) for c in cands]
    C = []
    for c in allc:
        m = max(abs(x) for x in c)
        bl = m.bit_length()
        s = max(bl - 60, 0)
        C.append([float(F(x, 1 << s)) / float(F(m, 1 << s)) for x in c])
    C = np.array(C)
    Cn = C / np.linalg.norm(C, axis=1)[:, None]
    vals = (Av @ Cn.T).max(axis=0) + (-(Bv @ Cn.T)).max(axis=0)
    ext = float(F(extent_int, sh))
    vmin = vals.min()
    sel = [i for i in range(len(allc)) if vals[i] <= vmin + 1e-9 * ext + 1e-300]
    best = None; bc = None
    neg_found = None
    for i in sel:
        c = allc[i]
        v = hD(A, B, c)
        if v < 0:
            neg_found = c
        cc = dot(c, c)
        val = (v*v if v >= 0 else -v*v, cc)
        if best is None or less(val, best):
            best, bc = val, c
    return best, bc, neg_found, len(allc), len(sel)

# ---------- full case ----------
def to_int_grid(ptsA, ptsB):
    allp = ptsA + ptsB
    L = 1
    for p in allp:
        for c in p:
            d = c.denominator
            if L % d:
                L = L * d // math.gcd(L, d)
    conv = lambda p: tuple(int(c * L) for c in p)
    return [conv(p) for p in ptsA], [conv(p) for p in ptsB], L

def solve(q):
    """exact answer for a query dict. returns dict with exact Fractions/mpf"""
    wa, ra = world_points(q['a'], q.get('pa'))
    wb, rb = world_points(q['b'], q.get('pb'))
    ia, ib, sh = to_int_grid(wa, wb)
    A = make_hull(ia); B = make_hull(ib)
    res = {'A': A, 'B': B, 'sh': sh, 'ra': ra, 'rb': rb}
    dist2, rec = closest_pair(A, B)
    scale = F(1, sh)
    inter = None
    if dist2[0] > 0:
        pa, pb = witness(A, B, rec)
        c = tuple(pb[k] - pa[k] for k in range(3))
        okA = max(dot(c, v) for v in A.verts) <= dot(c, pa)
        okB = min(dot(c, v) for v in B.verts) >= dot(c, pb)
        assert dot(c, c) == F(dist2[0], dist2[1])
        if okA and okB:
            inter = False
            res['core_d2'] = F(dist2[0], dist2[1]) * scale * scale
            res['pa'] = tuple(x*scale for x in pa); res['pb'] = tuple(x*scale for x in pb)
            res['sep_dir'] = c
        else:
            inter = True
    else:
        inter = True
    res['core_inter'] = inter
    dimD = affine_dim([sub(a, A.verts[0]) for a in A.verts] + [sub(b, B.verts[0]) for b in B.verts] + [(0, 0, 0)])[0]
    # rank of dirA + dirB
    dirs = [sub(a, A.verts[0]) for a in A.verts] + [sub(b, B.verts[0]) for b in B.verts]
    res['dimD'] = affine_dim([(0, 0, 0)] + dirs)[0]
    if inter:
        res['core_d2'] = F(0)
        if res['dimD'] == 3:
            ext = max(max(abs(x) for x in sub(v, A.verts[0])) for v in A.verts + B.verts) + 1
            best, bc, negc, nc, ns = solve_depth(A, B, sh, ext)
            res['ncand'] = (nc, ns)
            if negc is not None or best[0] < 0:
                res['oracle_error'] = 'negative support on intersecting pair'
            res['core_depth2'] = F(best[0], best[1]) * scale * scale
            res['depth_dir'] = bc
        else:
            res['core_depth2'] = F(0)
            res['depth_dir'] = None
    return res

def signed_dist_to_hull(H, p_int_frac):
    """exact signed distance (mpf) of a Fraction point (in grid units) to hull H (grid units).
    outside: exact Euclidean distance; inside (dim 3): -min plane distance."""
    p = p_int_frac
    den = 1
    for c in p: den = max(den, c.denominator)
    # bring to integer grid by scaling everything by den (power of 2 or general)
    L = 1
    for c in p: L = L * c.denominator // math.gcd(L, c.denominator)
    P = Hull(); P.dim = 0; P.verts = [tuple(int(c*L) for c in p)]; P.tris = []; P.planes = []; P.edges = []; P.edge_dirs = []
    Hs = Hull(); Hs.dim = H.dim; Hs.verts = [tuple(x*L for x in v) for v in H.verts]; Hs.tris = H.tris; Hs.edges = H.edges
    d2, rec = closest_pair(Hs, P)
    # inside test for dim 3
    if H.dim == 3:
        inside = all(dot(n, P.verts[0]) <= dd*L for (n, dd) in H.planes)
        if inside:
            m = None
            for (n, dd) in H.planes:
                x = dd*L - dot(n, P.verts[0])
                v = (x*x, dot(n, n))
                if m is None or less(v, m): m = v
            return -mp_sqrt(m[0], m[1]) / L
    # outside (or lower-dim): exact distance via feature candidates (valid since point is outside)
    return mp_sqrt(d2[0], d2[1]) / L
