import json, math, sys
import numpy as np
import gen
from gen import *
seed = int(sys.argv[1]) if len(sys.argv) > 1 else 5
N = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
gen.rng = np.random.default_rng(seed)
rng = gen.rng

def rq():
    q = rng.normal(size=4); q /= np.linalg.norm(q)
    return [float(v) for v in q]

def qmul(a, b):
    w1, x1, y1, z1 = a; w2, x2, y2, z2 = b
    return [w1*w2-x1*x2-y1*y2-z1*z2, w1*x2+x1*w2+y1*z2-z1*y2, w1*y2-x1*z2+y1*w2+z1*x2, w1*z2+x1*y2-y1*x2+z1*w2]

def qsmall(ang):
    ax = rng.normal(size=3); ax /= np.linalg.norm(ax)
    return [math.cos(ang/2)] + [float(v) for v in math.sin(ang/2) * ax]

def qn(q):
    q = np.array(q, float); q /= np.linalg.norm(q); return [float(v) for v in q]

ANG = [0, 1e-15, 1e-12, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1]

def gen_boxbox(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        ha = rand_box_he(s); hb = rand_box_he(s * float(rng.choice([1, 1, 0.1, 1e-3])))
        k = rng.integers(4)
        qa = rq() if rng.random() < 0.7 else [1.0, 0, 0, 0]
        if k == 0:
            ang = float(rng.choice(ANG)); qb = qn(qmul(qa, qsmall(ang))); sub = 'near%g' % ang
        elif k == 1:
            ang = float(rng.choice(ANG)); qb = qn(qmul(qmul(qa, EXACTQ[rng.integers(len(EXACTQ))]), qsmall(ang))); sub = 'perm%g' % ang
        elif k == 2:
            qb = rq(); sub = 'rand'
        else:
            ang = float(rng.choice(ANG)); qb = qn(qmul(qmul(qa, [math.cos(math.pi/8), math.sin(math.pi/8), 0, 0]), qsmall(ang))); sub = 'x45_%g' % ang
        a = {'type': 'box', 'half_extents': ha}; b = {'type': 'box', 'half_extents': hb}
        if rng.random() < 0.15:
            a = {'type': 'rounded', 'shape': a, 'radius': 0.05 * s}
        ta = [float(v) for v in rng.normal(size=3) * s]
        if rng.random() < 0.6:
            tb = place(a, qa, ta, b, qb, gap_pick(s))
        else:
            tb = [float(v) for v in np.asarray(ta) + rng.normal(size=3) * s * float(rng.choice([1e-9, 1e-3, 0.1, 0.5]))]
        gid = len(cases)
        emit('boxbox', a, {'t': ta, 'q': qa}, b, {'t': tb, 'q': qb}, sub)
        if rng.random() < 0.3:
            emit('boxbox', a, {'t': ta, 'q': qa}, poly(cube_pts(np.array(hb))), {'t': tb, 'q': qb}, sub + '_aspoly#%d' % gid)

def perp(u):
    v = rng.normal(size=3); v -= v.dot(u) * u; return v / np.linalg.norm(v)

def gen_segseg(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        u = rng.normal(size=3); u /= np.linalg.norm(u)
        ang = float(rng.choice(ANG))
        w = perp(u)
        d2 = math.cos(ang) * u + math.sin(ang) * w
        la = rng.uniform(0.2, 1) * s; lb = rng.uniform(0.2, 1) * s
        if rng.random() < 0.1: lb = float(rng.choice([0, 1e-15, 1e-12])) * s
        c = rng.normal(size=3) * s
        v = perp(u)
        h = float(rng.choice([0, 1e-15, 1e-12, 1e-9, 1e-6, 1e-3, 0.1])) * s
        shift = rng.uniform(-1.5, 1.5) * s
        A = np.array([c - u * la, c + u * la]); cb = c + v * h + u * shift
        B = np.array([cb - d2 * lb, cb + d2 * lb])
        a = {'type': 'segment', 'points': A.tolist()}
        b = {'type': 'segment', 'points': B.tolist()}
        r = rng.random()
        if r < 0.3:
            a = {'type': 'rounded', 'shape': a, 'radius': float(rng.choice([0.1, 1e-3])) * s}
            b = {'type': 'rounded', 'shape': b, 'radius': float(rng.choice([0.1, 1e-3, 0])) * s}
        elif r < 0.4:
            b = poly(B)
        elif r < 0.5:
            b = poly(np.vstack([B, B + 1e-13 * s * rng.normal(size=(2, 3))]))
        emit('segseg', a, {}, b, {}, 'ang%g_h%g' % (ang, h / s))

def gen_capsule(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        ca = {'type': 'capsule', 'radius': float(rng.uniform(0.05, 0.5) * s), 'half_height': float(rng.uniform(0, 1) * s)}
        other = rng.random()
        if other < 0.4:
            cb = {'type': 'capsule', 'radius': float(rng.uniform(0.05, 0.5) * s), 'half_height': float(rng.uniform(0, 1) * s)}
        else:
            cb = other_shape(s)
        qa = rq() if rng.random() < 0.5 else qpick()
        ang = float(rng.choice(ANG))
        qb = qn(qmul(qa, qsmall(ang))) if rng.random() < 0.5 else rq()
        ta = [float(v) for v in rng.normal(size=3) * s]
        tb = place(ca, qa, ta, cb, qb, gap_pick(s)) if rng.random() < 0.7 else [float(v) for v in np.asarray(ta) + rng.normal(size=3) * 0.2 * s]
        emit('capsule', ca, {'t': ta, 'q': qa}, cb, {'t': tb, 'q': qb}, 'ang%g' % ang)

def gen_tritri(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        k = rng.integers(6)
        if k == 0:  # crossing at small angle
            T1 = np.array([[-1, -1, 0], [1, -0.5, 0], [0, 1, 0]], float)
            ang = float(rng.choice(ANG[1:]))
            R = rot_axis([1, rng.uniform(-1, 1), 0], ang)
            T2 = (np.array([[-0.8, -0.2, 0], [0.9, 0.1, 0], [0.1, 0.9, 0]]) + [rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), 0]) @ R.T
            sub = 'cross%g' % ang
        elif k == 1:  # share an edge exactly (dyadic)
            e = np.array([[-1, 0, 0], [1, 0, 0]], float)
            T1 = np.vstack([e, [[dy(rng.uniform(-1, 1)), dy(rng.uniform(0.2, 1)), 0]]])
            T2 = np.vstack([e, [[dy(rng.uniform(-1, 1)), dy(rng.uniform(-1, 1)), dy(rng.uniform(-1, 1))]]])
            sub = 'edge'
        elif k == 2:  # share a vertex
            T1 = np.vstack([[[0, 0, 0]], [[dy(v) for v in rng.uniform(-1, 1, 3)] for _ in range(2)]])
            T2 = np.vstack([[[0, 0, 0]], [[dy(v) for v in rng.uniform(-1, 1, 3)] for _ in range(2)]])
            sub = 'vertex'
        elif k == 3:  # coplanar overlapping
            T1 = np.array([[dy(v) for v in rng.uniform(-1, 1, 3)] for _ in range(3)]); T1[:, 2] = 0
            T2 = np.array([[dy(v) for v in rng.uniform(-1, 1, 3)] for _ in range(3)]); T2[:, 2] = float(rng.choice([0, 0, 1e-12, -1e-9]))
            sub = 'coplanar'
        elif k == 4:  # random crossing
            T1 = rng.uniform(-1, 1, (3, 3)); T2 = rng.uniform(-1, 1, (3, 3)) * 0.8
            sub = 'rand'
        else:  # triangle piercing / lying on a box
            T1 = None
            he = [dy(v) for v in rng.uniform(0.3, 1, 3)]
            T2 = np.array([[dy(v) for v in rng.uniform(-1.5, 1.5, 3)] for _ in range(3)])
            m = rng.integers(3)
            if m == 0: T2[:, 2] = he[2]; sub = 'onbox'
            elif m == 1: T2[:, 2] = he[2] - float(rng.choice([1e-12, 1e-9, 1e-6, 0.1])); sub = 'inbox'
            else: sub = 'boxrand'
        M = rot_random() if rng.random() < 0.5 else signed_perm()
        c = rng.normal(size=3) * s
        if T1 is None:
            a = {'type': 'box', 'half_extents': [v * s for v in he]}
            b = {'type': 'triangle', 'points': (T2 * s).tolist()}
            q = [1.0, 0, 0, 0] if rng.random() < 0.5 else EXACTQ[rng.integers(len(EXACTQ))]
            emit('tritri', a, {'t': c.tolist(), 'q': q}, b, {'t': c.tolist(), 'q': q}, sub)
            continue
        a = {'type': 'triangle', 'points': (T1 * s @ M.T).tolist()}
        b = {'type': 'triangle', 'points': (T2 * s @ M.T).tolist()}
        if rng.random() < 0.2:
            b = {'type': 'rounded', 'shape': b, 'radius': 0.01 * s}
        emit('tritri', a, {'t': c.tolist()}, b, {'t': c.tolist()}, sub)

def gen_lowdim(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        he = [dy(v) for v in rng.uniform(0.3, 1, 3)]
        if rng.random() < 0.3: he = [he[0]] * 3
        asbox = rng.random() < 0.5
        a = {'type': 'box', 'half_extents': [v * s for v in he]} if asbox else poly(cube_pts(np.array(he)) * s)
        k = rng.integers(5)
        H = np.array(he)
        if k == 0:   # point at centre / on a symmetry plane / exact feature
            p = np.zeros(3)
            m = rng.integers(4)
            if m == 1: p[0] = H[0]
            elif m == 2: p[:2] = H[:2]
            elif m == 3: p = H.copy()
            p *= rng.choice([-1, 1], 3)
            b = {'type': 'point', 'points': [(p * s).tolist()]}; sub = 'point%d' % m
        elif k == 1:
            p = rng.uniform(-1, 1, 3) * H; j = rng.integers(3); p[j] = H[j] * (1 - float(rng.choice([0, 1e-15, 1e-12, 1e-9, -1e-12, -1e-9])))
            b = {'type': 'point', 'points': [(p * s).tolist()]}; sub = 'pointnear'
        elif k == 2:  # segment inside along diagonal / through centre
            d = rng.normal(size=3); d /= np.linalg.norm(d)
            L = float(rng.choice([0.1, 0.5, 2.0]))
            b = {'type': 'segment', 'points': [(-d * L * s).tolist(), (d * L * s).tolist()]}; sub = 'segcentre'
        elif k == 3:  # triangle inside
            b = {'type': 'triangle', 'points': (rng.uniform(-1, 1, (3, 3)) * H * s * 0.9).tolist()}; sub = 'triinside'
        else:  # small polytope nearly at centre: ties
            b = poly(rand_poly(int(rng.integers(4, 10)), 0.01 * s)); sub = 'smallcentre'
        if rng.random() < 0.2:
            b = {'type': 'rounded', 'shape': b, 'radius': 0.1 * s}
        q = [1.0, 0, 0, 0] if rng.random() < 0.5 else (rq() if rng.random() < 0.5 else EXACTQ[rng.integers(len(EXACTQ))])
        c = [float(v) for v in rng.normal(size=3) * s]
        emit('lowdim', a, {'t': c, 'q': q}, b, {'t': c, 'q': q}, sub)

def gen_slab(n):
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        A = flat_set(1.0, eps=float(rng.choice([0, 1e-12, 1e-9])))
        B = flat_set(1.0, eps=float(rng.choice([0, 1e-12, 1e-9])))
        PA = np.array(A['points']); PB = np.array(B['points'])
        # align both to z=0 plane then tilt B
        def toz(P):
            c = P.mean(axis=0); U, S, Vt = np.linalg.svd(P - c); return (P - c) @ Vt.T
        PA = toz(PA); PB = toz(PB) * rng.uniform(0.3, 1)
        ang = float(rng.choice(ANG))
        PB = PB @ rot_axis(rng.normal(size=3) * [1, 1, 0] + [0, 0, 1e-30], ang).T
        PB += [rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), float(rng.choice([0, 1e-12, 1e-9, 1e-6]))]
        M = rot_random() if rng.random() < 0.5 else np.eye(3)
        PA = PA @ M.T * s; PB = PB @ M.T * s
        emit('slab', poly(PA), {}, poly(PB), {}, 'tilt%g' % ang)

def gen_rotgeneric(n):
    makers = [flat_set, needle_set, dup_set, sphere_set, boxface_set]
    for _ in range(n):
        s = float(10 ** rng.uniform(-1, 1))
        a = makers[rng.integers(len(makers))](s)
        b = other_shape(s) if rng.random() < 0.6 else makers[rng.integers(len(makers))](s)
        qa = rq(); qb = rq() if rng.random() < 0.6 else qn(qmul(qa, qsmall(float(rng.choice(ANG)))))
        T = float(rng.choice([0, 0, 1e3, 1e6]))
        ta = [float(v) for v in rng.normal(size=3) * s + T]
        tb = place(a, qa, ta, b, qb, gap_pick(s)) if rng.random() < 0.8 else [float(v) for v in np.asarray(ta) + rng.normal(size=3) * 0.1 * s]
        emit('rotgen', a, {'t': ta, 'q': qa}, b, {'t': tb, 'q': qb}, 'T%g' % T)

gen_boxbox(int(400 * N))
gen_segseg(int(300 * N))
gen_capsule(int(200 * N))
gen_tritri(int(300 * N))
gen_lowdim(int(250 * N))
gen_slab(int(150 * N))
gen_rotgeneric(int(300 * N))
for i, c in enumerate(cases):
    c['pid'] = i
    print(json.dumps(c))
