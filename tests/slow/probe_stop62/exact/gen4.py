# Box-segment pairs. BOXSEG=hair: only the first three kinds, the segment 3e-10 to 3e-7 rad from
# the face (log-uniform) instead of a tilt from ANG.
import json, math, os, sys
import numpy as np
import gen
from gen import *
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 5
N = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
gen.rng = np.random.default_rng(seed)
rng = gen.rng
HAIR = os.environ.get('BOXSEG') == 'hair'
def rq():
    q = rng.normal(size=4); q /= np.linalg.norm(q); return [float(v) for v in q]
ANG=[0,1e-12,1e-10,1e-8,1e-6,1e-4,1e-2]
def gen_boxseg(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        he = np.array(rand_box_he(s))
        k = rng.integers(3) if HAIR else rng.integers(6)
        ang = float(10 ** rng.uniform(-9.5, -6.5)) if HAIR else float(rng.choice(ANG))
        h = float(rng.choice([0, 0, 1e-14, 1e-12, 1e-10, 1e-8, -1e-12, -1e-8])) * s
        P = np.eye(3)[rng.permutation(3)] * rng.choice([-1, 1], 3)[:, None]   # signed permutation (exact)
        if k == 0:   # in face plane y=he1, crossing the edge (y=he1,z=he2) at tiny angle
            xc = rng.uniform(-1, 1) * he[0]
            d = np.array([math.cos(ang), 0, math.sin(ang)]); m = np.array([xc, he[1] + h, he[2]])
            L = rng.uniform(0.5, 2) * he[0] * float(rng.choice([1, 3]))
            seg = [m - d * L, m + d * L]
        elif k == 1:  # parallel to face at height h, tilted by ang
            d = np.array([math.cos(ang), math.sin(ang) * rng.uniform(-1, 1), math.sin(ang)]); d /= np.linalg.norm(d)
            m = np.array([rng.uniform(-1, 1) * he[0], rng.uniform(-1, 1) * he[1], he[2] + h])
            L = rng.uniform(0.1, 2) * s; seg = [m - d * L, m + d * L]
        elif k == 2:  # along an edge, collinear-ish
            d = np.array([math.cos(ang), math.sin(ang), 0.0]); m = np.array([rng.uniform(-1.5, 1.5) * he[0], he[1] + h, he[2]])
            L = rng.uniform(0.1, 2) * s; seg = [m - d * L, m + d * L]
        elif k == 3:  # through/near a corner
            c = he.copy(); d = rng.normal(size=3); d /= np.linalg.norm(d)
            off = np.cross(d, rng.normal(size=3)); off /= np.linalg.norm(off)
            m = c + off * h; L = rng.uniform(0.1, 2) * s; seg = [m - d * L, m + d * L]
        elif k == 4:  # endpoint exactly on face / inside by tiny
            e = np.array([rng.uniform(-1, 1) * he[0], rng.uniform(-1, 1) * he[1], he[2] - h])
            d = rng.normal(size=3); d[2] = abs(d[2]) + float(rng.choice([0, 1e-9, 1e-3])); d /= np.linalg.norm(d)
            seg = [e, e + d * rng.uniform(0.1, 2) * s]
        else:  # deep: segment through the box
            d = rng.normal(size=3); d /= np.linalg.norm(d)
            m = rng.uniform(-1, 1, 3) * he * float(rng.choice([0, 1e-9, 0.5, 0.99]))
            L = rng.uniform(0.1, 3) * s; seg = [m - d * L, m + d * L]
        seg = [P @ p for p in seg]; hep = np.abs(P @ he)
        box = {'type': 'box', 'half_extents': [float(v) for v in hep]}
        b = {'type': 'segment', 'points': [[float(v) for v in p] for p in seg]}
        u = rng.random()
        if u < 0.15: b = {'type': 'rounded', 'shape': b, 'radius': float(rng.choice([0.1, 1e-3])) * s}
        elif u < 0.25: b = {'type': 'point', 'points': [b['points'][0]]}
        elif u < 0.35: b = {'type': 'triangle', 'points': b['points'] + [[float(v) for v in np.asarray(b['points'][0]) + rng.normal(size=3) * s * float(rng.choice([1, 1e-6]))]]}
        elif u < 0.45: box = poly(cube_pts(hep))
        m = rng.random()
        if m < 0.5:
            pa = {}; pb = {}
        elif m < 0.8:
            q = EXACTQ[rng.integers(len(EXACTQ))]; t = [float(v) for v in rng.normal(size=3) * s]
            pa = {'t': t, 'q': q}; pb = {'t': t, 'q': q}
        else:
            q = rq(); t = [float(v) for v in rng.normal(size=3) * s]
            pa = {'t': t, 'q': q}; pb = {'t': t, 'q': q}
        label = ('k%d_ang%.1e_h%g_%s_%s' if HAIR else 'k%d_ang%g_h%g_%s_%s') % (k, ang, h / s, b['type'], box['type'])
        emit('boxseg', box, pa, b, pb, label)
gen_boxseg(int(1500 * N))
for i, c in enumerate(cases):
    c['pid'] = i
    print(json.dumps(c))
