# Independent second computation (no hull, no feature enumeration):
# distance between conv(A) and conv(B) = distance from origin to conv(A-B), found by brute force
# over all subsets of <= 3 points of A-B (Caratheodory on the boundary), exact Fractions.
# Also h_D(n) of the tool's normal from the raw points, and point-to-shape distances likewise.
import json, sys, itertools, math
from fractions import Fraction as F
sys.path.insert(0, __import__('os').path.dirname(__import__('os').path.abspath(__file__)))
from oracle import world_points, bounding_radius

def dot(a, b): return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]
def sub(a, b): return tuple(x - y for x, y in zip(a, b))

def proj_simplex(P):
    """closest point to origin of the affine hull of P (list of 1..3 points), with barycentric coords;
    None if degenerate"""
    if len(P) == 1:
        return P[0], [F(1)]
    p0 = P[0]; E = [sub(p, p0) for p in P[1:]]
    k = len(E)
    G = [[dot(E[i], E[j]) for j in range(k)] for i in range(k)]
    r = [-dot(E[i], p0) for i in range(k)]
    if k == 1:
        if G[0][0] == 0: return None
        l = [r[0] / G[0][0]]
    else:
        det = G[0][0]*G[1][1] - G[0][1]*G[1][0]
        if det == 0: return None
        l = [(r[0]*G[1][1] - G[0][1]*r[1]) / det, (G[0][0]*r[1] - G[1][0]*r[0]) / det]
    bary = [1 - sum(l)] + l
    x = tuple(p0[c] + sum(l[i]*E[i][c] for i in range(k)) for c in range(3))
    return x, bary

def dist2_origin_hull(D):
    best = None
    D = list(dict.fromkeys(D))
    for m in (1, 2, 3):
        for S in itertools.combinations(D, m):
            r = proj_simplex(list(S))
            if r is None: continue
            x, bary = r
            if min(bary) < 0: continue
            d2 = dot(x, x)
            if best is None or d2 < best:
                best = d2
                if d2 == 0: return F(0)
    return best

def det3(a, b, c):
    return a[0]*(b[1]*c[2]-b[2]*c[1]) - a[1]*(b[0]*c[2]-b[2]*c[0]) + a[2]*(b[0]*c[1]-b[1]*c[0])

def origin_in_some_tetra(D):
    for S in itertools.combinations(D, 4):
        p0, p1, p2, p3 = S
        e1, e2, e3 = sub(p1, p0), sub(p2, p0), sub(p3, p0)
        dt = det3(e1, e2, e3)
        if dt == 0: continue
        r = tuple(-x for x in p0)
        l1 = det3(r, e2, e3) / dt; l2 = det3(e1, r, e3) / dt; l3 = det3(e1, e2, r) / dt
        if l1 >= 0 and l2 >= 0 and l3 >= 0 and l1 + l2 + l3 <= 1:
            return True
    return False

def verify(q, a):
    wa, ra = world_points(q['a'], q.get('pa')); wb, rb = world_points(q['b'], q.get('pb'))
    size = bounding_radius(q['a']) + bounding_radius(q['b'])
    D = [sub(x, y) for x in wa for y in wb]
    d2 = dist2_origin_hull(D)
    inside = origin_in_some_tetra(list(dict.fromkeys(D))) if d2 > 0 else None
    dc = math.sqrt(d2)
    out = {'id': q['id'], 'size': size, 'core_dist_bruteforce': dc, 'dist_rounded': dc - float(ra + rb)}
    if inside:
        out['core_dist_bruteforce'] = 0.0; out['cores_overlap_tetra_certificate'] = True; out['dist_rounded'] = -float(ra + rb)
    n = a.get('normal')
    if n:
        nf = tuple(F(x) for x in n); nn = math.sqrt(float(dot(nf, nf)))
        h = max(dot(nf, x) for x in wa) + max(-dot(nf, y) for y in wb)
        out['hD_tool_normal'] = float(h) / nn + float(ra + rb)
        out['hD_over_size'] = out['hD_tool_normal'] / size
    for key, W, r in (('point_a', wa, ra), ('point_b', wb, rb)):
        p = a.get(key)
        if p:
            pf = tuple(F(x) for x in p)
            dd = dist2_origin_hull([sub(w, pf) for w in W])
            out[key + '_dist_to_core'] = math.sqrt(dd) - float(r)
    return out

if __name__ == '__main__':
    qs = [json.loads(l) for l in open(sys.argv[1])]
    ans = [json.loads(l) for l in open(sys.argv[2])]
    for q, a in zip(qs, ans):
        print(json.dumps(verify(q, a)))
