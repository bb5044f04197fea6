# Nearly parallel segments, capsules, slivers and needles. NEEDLES=rounded: only the sliver and
# needle kinds (3, 4), half of them rounded (kinds 13, 14).
import json, math, os, sys
import numpy as np
import gen
from gen import *
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 5
N = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
gen.rng = np.random.default_rng(seed)
rng = gen.rng
ROUNDED = os.environ.get('NEEDLES') == 'rounded'
def perp(u):
    v = rng.normal(size=3); v -= v.dot(u) * u; return v / np.linalg.norm(v)
def quat_from_z(d):
    # unit quaternion rotating +z to d
    z = np.array([0, 0, 1.0]); d = d / np.linalg.norm(d)
    c = z.dot(d); ax = np.cross(z, d); sn = np.linalg.norm(ax)
    if sn < 1e-300: return [1.0, 0, 0, 0]
    ax /= sn; ang = math.atan2(sn, c)
    return [math.cos(ang/2)] + [float(v) for v in math.sin(ang/2) * ax]
def gen_parallel(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        u = rng.normal(size=3); u /= np.linalg.norm(u)
        ang = float(rng.choice([1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7]))
        w = perp(u); d2 = math.cos(ang) * u + math.sin(ang) * w
        v = np.cross(u, w)
        la = rng.uniform(0.3, 1) * s; lb = rng.uniform(0.3, 1) * s
        c = rng.normal(size=3) * s
        h = float(rng.choice([0, 1e-14, 1e-12, 1e-10, 1e-8, 1e-6])) * s * rng.choice([-1, 1])
        shift = rng.uniform(-0.2, 0.2) * min(la, lb)
        cb = c + v * h + u * shift
        A = np.array([c - u * la, c + u * la]); B = np.array([cb - d2 * lb, cb + d2 * lb])
        k = int(rng.choice([3, 4])) if ROUNDED else rng.integers(6)
        if k == 0:
            a = {'type': 'segment', 'points': A.tolist()}; b = {'type': 'segment', 'points': B.tolist()}; pa = {}; pb = {}
        elif k == 1:
            r1 = float(rng.choice([0.1, 1e-3])) * s; r2 = float(rng.choice([0.1, 1e-3])) * s
            a = {'type': 'rounded', 'shape': {'type': 'segment', 'points': A.tolist()}, 'radius': r1}
            b = {'type': 'rounded', 'shape': {'type': 'segment', 'points': B.tolist()}, 'radius': r2}; pa = {}; pb = {}
        elif k == 2:
            r1 = float(rng.choice([0.1, 1e-3])) * s; r2 = float(rng.choice([0.1, 1e-3])) * s
            a = {'type': 'capsule', 'radius': r1, 'half_height': float(la)}; pa = {'t': c.tolist(), 'q': quat_from_z(u)}
            b = {'type': 'capsule', 'radius': r2, 'half_height': float(lb)}; pb = {'t': cb.tolist(), 'q': quat_from_z(d2)}
        elif k == 3:  # segment vs thin triangle (needle) containing direction d2
            a = {'type': 'segment', 'points': A.tolist()}
            th = float(rng.choice([1e-12, 1e-9, 1e-6, 1e-3])) * s
            b = {'type': 'triangle', 'points': B.tolist() + [(cb + w * th).tolist()]}; pa = {}; pb = {}
        elif k == 4:  # thin box-like needles as polytopes
            th = float(rng.choice([1e-12, 1e-9, 1e-6])) * s
            a = poly(np.vstack([A, A + perp(u) * th])); b = poly(np.vstack([B, B + perp(d2) * th])); pa = {}; pb = {}
        else:  # segment vs box edge nearly parallel
            he = rand_box_he(s)
            a = {'type': 'box', 'half_extents': he}
            # box edge along x at (y=he1, z=he2); segment near-parallel just above
            E = np.array([[-he[0], he[1], he[2]], [he[0], he[1], he[2]]])
            dd = np.array([math.cos(ang), 0, math.sin(ang)]) ; nrm = np.array([0, 1.0, 1.0]) / math.sqrt(2)
            m = np.array([rng.uniform(-0.2, 0.2) * he[0], he[1], he[2]]) + nrm * h
            L = rng.uniform(0.3, 1) * s
            b = {'type': 'segment', 'points': [(m - dd * L).tolist(), (m + dd * L).tolist()]}
            pa = {}; pb = {}
        if ROUNDED and rng.random() < 0.5:
            r = float(rng.choice([0.1, 1e-3])) * s
            a = {'type': 'rounded', 'shape': a, 'radius': r}; b = {'type': 'rounded', 'shape': b, 'radius': r}
            k = k + 10
        emit('parallel', a, pa, b, pb, 'k%d_ang%g_h%g' % (k, ang, abs(h) / s))
gen_parallel(int(600 * N))
for i, c in enumerate(cases):
    c['pid'] = i
    print(json.dumps(c))
