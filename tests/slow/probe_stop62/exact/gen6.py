import json, math, sys
import numpy as np
import gen
from gen import *
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 5
N = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
gen.rng = np.random.default_rng(seed)
rng = gen.rng
def qmul(a, b):
    w1, x1, y1, z1 = a; w2, x2, y2, z2 = b
    return [w1*w2-x1*x2-y1*y2-z1*z2, w1*x2+x1*w2+y1*z2-z1*y2, w1*y2-x1*z2+y1*w2+z1*x2, w1*z2+x1*y2-y1*x2+z1*w2]
def qn(q):
    q = np.array(q, float); q /= np.linalg.norm(q); return [float(v) for v in q]
def qaxis(ax, ang):
    ax = np.asarray(ax, float); ax /= np.linalg.norm(ax)
    return [math.cos(ang/2)] + [float(v) for v in math.sin(ang/2) * ax]
def rq():
    q = rng.normal(size=4); q /= np.linalg.norm(q); return [float(v) for v in q]
for _ in range(int(1500 * N)):
    s = float(10 ** rng.uniform(-1, 1))
    ha = np.array(rand_box_he(s)); hb = np.array(rand_box_he(s))
    for h in (ha, hb):
        if rng.random() < 0.4:
            h[rng.integers(3)] *= float(10 ** rng.uniform(-9, -3))
    ang = float(10 ** rng.uniform(-10, -4)) if rng.random() < 0.85 else 0.0
    k = rng.integers(3)
    qa = rq() if rng.random() < 0.5 else [1.0, 0, 0, 0]
    if k == 0:    # faces nearly parallel: B above A's +z face
        qrel = qaxis(rng.normal(size=3), ang)
        gap = float(rng.choice([0, 1e-14, 1e-12, 1e-10, 1e-8, -1e-12, -1e-10, -1e-8, -1e-6])) * s
        off = np.array([rng.uniform(-1, 1) * (ha[0] + hb[0]), rng.uniform(-1, 1) * (ha[1] + hb[1]), ha[2] + hb[2] + gap])
    elif k == 1:  # B edge-on: rotated 45 deg about x, plus tiny tilt
        qrel = qmul(qaxis([1, 0, 0], math.pi / 4), qaxis(rng.normal(size=3), ang))
        gap = float(rng.choice([0, 1e-12, 1e-10, 1e-8, -1e-12, -1e-10, -1e-8])) * s
        off = np.array([rng.uniform(-1, 1) * (ha[0] + hb[0]), rng.uniform(-1, 1) * ha[1], ha[2] + (hb[1] + hb[2]) / math.sqrt(2) + gap])
    else:         # edge-edge crossing, both edge-on, tiny tilt
        qrel = qmul(qaxis([0, 1, 0], math.pi / 4), qmul(qaxis([1, 0, 0], math.pi / 4), qaxis(rng.normal(size=3), ang)))
        off = np.array([rng.uniform(-0.3, 0.3) * ha[0], rng.uniform(-0.3, 0.3) * ha[1], ha[2] + rng.uniform(0, 1) * hb.max()])
    qa_ = qa
    qb = qn(qmul(qa_, qrel))
    Ra = qmat(qa_)
    ta = rng.normal(size=3) * s
    tb = ta + Ra @ off
    a = {'type': 'box', 'half_extents': [float(v) for v in ha]}
    b = {'type': 'box', 'half_extents': [float(v) for v in hb]}
    u = rng.random()
    if u < 0.2: b = poly(cube_pts(hb))
    elif u < 0.3: b = {'type': 'rounded', 'shape': b, 'radius': float(rng.choice([1e-3, 0.1])) * s}
    emit('boxbox2', a, {'t': [float(v) for v in ta], 'q': qa_}, b, {'t': [float(v) for v in tb], 'q': qb}, 'k%d_ang%.1e_%s' % (k, ang, b['type']))
for i, c in enumerate(cases):
    c['pid'] = i
    print(json.dumps(c))
