import json, math, sys
import numpy as np
rng = np.random.default_rng(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
SCALE_N = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0

def rot_random():
    q = rng.normal(size=4); q /= np.linalg.norm(q)
    w, x, y, z = q
    return np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],
                     [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],
                     [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])

def rot_axis(axis, ang):
    axis = np.asarray(axis, float); axis /= np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(ang)*K + (1-math.cos(ang))*K@K

# exact quaternions (binary tetrahedral group) -> exact rotations in double
EXACTQ = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] + \
    [[a*0.5, b*0.5, c*0.5, d*0.5] for a in (1,) for b in (1, -1) for c in (1, -1) for d in (1, -1)]

def qpick(p_ident=0.6):
    if rng.random() < p_ident:
        return [1, 0, 0, 0]
    return EXACTQ[rng.integers(len(EXACTQ))]

def poly(P):
    return {'type': 'polytope', 'points': [[float(v) for v in p] for p in P]}

def rand_poly(n, s=1.0):
    P = rng.normal(size=(n, 3))
    if rng.random() < 0.5:
        P /= np.linalg.norm(P, axis=1)[:, None]
    return P * s

def rand_box_he(s=1.0):
    return [float(v) for v in rng.uniform(0.2, 1.0, 3) * s]

def round_maybe(shape, s, p=0.2):
    u = rng.random()
    if u < p*0.7:
        return {'type': 'rounded', 'shape': shape, 'radius': float(rng.choice([0.5, 0.125, 0.01, 1e-6]) * s)}
    if u < p:
        return {'type': 'sum', 'shapes': [shape, {'type': 'sphere', 'radius': float(rng.choice([0.25, 0.03]) * s)}]}
    return shape

def local_pts(shape):
    t = shape['type']
    if t == 'box':
        h = shape['half_extents']
        return np.array([[sx*h[0], sy*h[1], sz*h[2]] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
    if t in ('polytope', 'triangle', 'segment', 'point'):
        return np.array(shape['points'], float)
    if t == 'capsule':
        return np.array([[0, 0, -shape['half_height']], [0, 0, shape['half_height']]])
    if t == 'rounded':
        return local_pts(shape['shape'])
    if t == 'sum':
        return local_pts(shape['shapes'][0])
def radius_of(shape):
    if shape['type'] == 'capsule':
        return shape['radius']
    if shape['type'] == 'rounded':
        return radius_of(shape['shape']) + shape['radius']
    if shape['type'] == 'sum':
        return radius_of(shape['shapes'][0]) + shape['shapes'][1]['radius']
    return 0.0

def qmat(q):
    w, x, y, z = q
    return np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)],
                     [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)],
                     [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])

def hsup(shape, q, u):
    P = local_pts(shape) @ qmat(q).T
    return (P @ u).max() + radius_of(shape)

def place(a, qa, ta, b, qb, gap, u=None):
    """translation of B so that the separation of A,B along u is gap (float approx)"""
    if u is None:
        u = rng.normal(size=3); u /= np.linalg.norm(u)
    d = hsup(a, qa, u) + hsup(b, qb, -u) + gap
    return [float(v) for v in np.asarray(ta) + d*u]

cases = []
def emit(cls, a, pa, b, pb, sub=''):
    cases.append({'cls': cls, 'sub': sub, 'a': a, 'pa': pa, 'b': b, 'pb': pb})

GAPS = [-0.5, -0.1, -1e-3, -1e-6, -1e-9, -1e-12, 0.0, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 0.5]
def gap_pick(s):
    return float(rng.choice(GAPS) * s)

def other_shape(s):
    u = rng.random()
    if u < 0.35:
        return round_maybe(poly(rand_poly(int(rng.integers(4, 16)), s)), s)
    if u < 0.55:
        return round_maybe({'type': 'box', 'half_extents': rand_box_he(s)}, s)
    if u < 0.7:
        return round_maybe({'type': 'triangle', 'points': rand_poly(3, s).tolist()}, s)
    if u < 0.8:
        return round_maybe({'type': 'segment', 'points': rand_poly(2, s).tolist()}, s)
    if u < 0.85:
        return round_maybe({'type': 'point', 'points': rand_poly(1, 0.3*s).tolist()}, s, p=0.5)
    return round_maybe(flat_set(s), s)

def flat_set(s, eps=None):
    n = int(rng.integers(4, 30))
    eps = float(rng.choice([0, 1e-12, 1e-10, 1e-8, 1e-6])) if eps is None else eps
    P = rng.uniform(-1, 1, size=(n, 3)); P[:, 2] = eps * rng.uniform(-1, 1, n)
    if rng.random() < 0.5:
        ang = rng.uniform(0, 2*math.pi, n); P[:, 0] = np.cos(ang); P[:, 1] = np.sin(ang)
    return poly((P @ rot_random().T) * s)

def needle_set(s):
    n = int(rng.integers(3, 20))
    eps = float(rng.choice([0, 1e-15, 1e-12, 1e-9, 1e-6]))
    P = np.zeros((n, 3)); P[:, 0] = rng.uniform(-1, 1, n)
    P[:, 1:] = eps * rng.uniform(-1, 1, (n, 2))
    return poly((P @ rot_random().T) * s)

def dup_set(s):
    P = rand_poly(int(rng.integers(4, 14)), s)
    k = int(rng.integers(1, 8))
    idx = rng.integers(len(P), size=k)
    D = P[idx].copy()
    for i in range(k):
        e = float(rng.choice([0, 1e-15, 1e-13, 1e-11, 1e-9]))
        D[i] += e * s * rng.normal(size=3)
    return poly(np.vstack([P, D]))

def sphere_set(s, n=None):
    n = n or int(rng.integers(20, 50))
    P = rng.normal(size=(n, 3)); P /= np.linalg.norm(P, axis=1)[:, None]
    return poly(P * s)

def boxface_set(s):
    h = rng.uniform(0.3, 1, 3)
    pts = []
    for _ in range(int(rng.integers(10, 40))):
        p = rng.uniform(-1, 1, 3)
        k = rng.integers(3); p[k] = rng.choice([-1, 1])
        if rng.random() < 0.4:
            k2 = (k + 1 + rng.integers(2)) % 3; p[k2] = rng.choice([-1, 1])
        if rng.random() < 0.2:
            p = rng.choice([-1, 1], 3).astype(float)
        pts.append(p * h)
    P = np.array(pts) * s
    if rng.random() < 0.5:
        P = P @ rot_random().T
    return poly(P)

def gen_generic(cls, maker, npairs):
    for _ in range(npairs):
        s = float(10 ** rng.uniform(-1, 1)) if rng.random() < 0.7 else 1.0
        a = round_maybe(maker(s), s, p=0.15)
        b = other_shape(s * float(10 ** rng.uniform(-0.5, 0.5))) if rng.random() < 0.7 else round_maybe(maker(s), s, 0.15)
        qa = qpick(); qb = qpick()
        ta = [float(v) for v in rng.normal(size=3) * s]
        tb = place(a, qa, ta, b, qb, gap_pick(s))
        emit(cls, a, {'t': ta, 'q': qa}, b, {'t': tb, 'q': qb})

# ---- touching constructions (exact dyadic) ----
SP = [np.array(p) for p in
      [[[1, 0, 0], [0, 1, 0], [0, 0, 1]], [[0, 1, 0], [0, 0, 1], [1, 0, 0]], [[0, 0, 1], [1, 0, 0], [0, 1, 0]]]]
def signed_perm():
    M = SP[rng.integers(3)].copy().astype(float)
    if rng.random() < 0.5: M = M[[1, 0, 2]]
    M = M * rng.choice([-1, 1], 3)[:, None]
    return M

def dy(x, bits=10):
    return float(round(x * (1 << bits)) / (1 << bits))

def gen_touch(npairs):
    kinds = ['ff', 'vf', 'ee', 'ef', 'boxff', 'vv', 've']
    for _ in range(npairs):
        kind = kinds[rng.integers(len(kinds))]
        # A below z=0 with top feature; B above z=0 with bottom feature
        def below(n, top):
            P = np.column_stack([rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), -rng.uniform(0.05, 1, n)])
            P = np.array([[dy(v) for v in p] for p in P])
            return np.vstack([P, top])
        def topface():
            n = int(rng.integers(3, 7)); ang = np.sort(rng.uniform(0, 2*math.pi, n))
            return np.array([[dy(0.8*math.cos(t)), dy(0.8*math.sin(t)), 0.0] for t in ang])
        if kind == 'ff':
            A = below(int(rng.integers(4, 12)), topface()); B = -below(int(rng.integers(4, 12)), topface())
            B[:, :2] = np.array([[dy(v) for v in p] for p in B[:, :2] + rng.uniform(-0.5, 0.5, 2)])
        elif kind == 'vf':
            A = below(int(rng.integers(4, 12)), topface())
            B = -below(int(rng.integers(4, 12)), np.array([[dy(rng.uniform(-0.3, 0.3)), dy(rng.uniform(-0.3, 0.3)), 0.0]]))
            B[:, 2] = np.abs(B[:, 2]); B[-1, 2] = 0
            B[:-1, 2] = np.maximum(B[:-1, 2], 1/1024)
        elif kind == 'ee':
            A = np.array([[-1, 0, 0], [1, 0, 0], [-1, -1, -1], [-1, 1, -1], [1, -1, -1], [1, 1, -1]], float)
            B = np.array([[0, -1, 0], [0, 1, 0], [-1, -1, 1], [1, -1, 1], [-1, 1, 1], [1, 1, 1]], float)
            c = rng.uniform(0.2, 0.9); B[:, 0] = B[:, 0] * c + dy(rng.uniform(-0.5, 0.5)); B = np.round(B * 1024) / 1024
            # skew edge direction in xy
            sk = dy(rng.uniform(-0.9, 0.9))
            B[:, 0] += sk * B[:, 1]
        elif kind == 'ef':
            A = below(int(rng.integers(4, 12)), topface())
            e = np.array([[dy(rng.uniform(-0.3, 0)), dy(rng.uniform(-0.3, 0.3)), 0], [dy(rng.uniform(0, 0.3)), dy(rng.uniform(-0.3, 0.3)), 0]])
            B = np.vstack([e, np.array([[dy(v) for v in p] for p in rng.uniform(-1, 1, (5, 3))])])
            B[2:, 2] = np.abs(B[2:, 2]) + 1/64
        elif kind == 'vv':
            A = below(int(rng.integers(4, 12)), np.array([[0.0, 0.0, 0.0]]))
            A[:-1, 2] -= 1/64
            A[:-1, :2] *= 0.5
            B = -A.copy() @ signed_perm().T if False else -A.copy()
            B[:, :2] = B[:, :2] @ np.array([[0, 1], [-1, 0]])
        elif kind == 've':
            A = np.array([[-1, 0, 0], [1, 0, 0], [-1, -1, -1], [-1, 1, -1], [1, -1, -1], [1, 1, -1]], float)
            B = np.vstack([[[dy(rng.uniform(-0.9, 0.9)), 0.0, 0.0]], np.array([[dy(v) for v in p] for p in rng.uniform(-1, 1, (5, 3))])])
            B[1:, 2] = np.abs(B[1:, 2]) + 1/64
            B[1:, :2] = B[1:, :2] * 0.3 + B[0, :2]
        else:  # boxff
            ha = [dy(v) for v in rng.uniform(0.2, 1, 3)]; hb = [dy(v) for v in rng.uniform(0.2, 1, 3)]
            A = np.array([[sx*ha[0], sy*ha[1], sz*ha[2]] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) - [0, 0, ha[2]]
            B = np.array([[sx*hb[0], sy*hb[1], sz*hb[2]] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) + [dy(rng.uniform(-1, 1)), dy(rng.uniform(-1, 1)), hb[2]]
        M = signed_perm()
        s = float(2.0 ** int(rng.integers(-8, 8)))
        A = (A @ M.T) * s; B = (B @ M.T) * s
        zdir = M @ np.array([0, 0, 1.0])
        delta = float(rng.choice([0, 0, 0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6])) * s
        off = np.array([dy(v, 6) for v in rng.normal(size=3)]) * s
        # split off into local center & pose t
        ta = [float(v) for v in off]
        tb = [float(v) for v in off + zdir * delta]
        sub = kind + ('' if delta == 0 else ('+' if delta > 0 else '-') + '%g' % abs(delta / s))
        a = poly(A); b = poly(B)
        if kind == 'boxff' and rng.random() < 0.5:
            # as real boxes with pose: centers
            ca = A.mean(axis=0); cb = B.mean(axis=0)
            hea = list(np.abs(M @ np.array(ha)) * s); heb = list(np.abs(M @ np.array(hb)) * s)
            a = {'type': 'box', 'half_extents': [float(v) for v in hea]}
            b = {'type': 'box', 'half_extents': [float(v) for v in heb]}
            ta = [float(v) for v in off + ca]; tb = [float(v) for v in off + cb + zdir * delta]
        emit('touch', a, {'t': ta}, b, {'t': tb}, sub)

def gen_scale(npairs):
    for _ in range(npairs):
        big = float(rng.choice([1.0, 1e6])); small = big * float(rng.choice([1e-6, 1e-5, 1e-3]))
        a = rng.choice(['box', 'poly', 'sph'])
        if a == 'box':
            A = {'type': 'box', 'half_extents': rand_box_he(big)}
        elif a == 'poly':
            A = poly(rand_poly(int(rng.integers(4, 20)), big))
        else:
            A = sphere_set(big, 30)
        B = other_shape(small)
        qa = qpick(); qb = qpick()
        ta = [0.0, 0.0, 0.0] if rng.random() < 0.5 else [float(v) for v in rng.normal(size=3) * big]
        mode = rng.random()
        if mode < 0.7:
            tb = place(A, qa, ta, B, qb, gap_pick(small))
        else:
            tb = [float(v) for v in np.asarray(ta) + rng.normal(size=3) * 0.1 * big]
        emit('scale', A, {'t': ta, 'q': qa}, B, {'t': tb, 'q': qb}, 'big%g_small%g' % (big, small / big))

def gen_far(npairs):
    for _ in range(npairs):
        T = float(rng.choice([1e6, 1e7, 1e8])); s = float(rng.choice([1e-3, 1e-2, 1e-1, 1.0]))
        u = rng.random()
        A = other_shape(s) if u < 0.5 else (dup_set(s) if u < 0.7 else flat_set(s))
        B = other_shape(s)
        qa = qpick(); qb = qpick()
        ta = [float(v) for v in T * rng.uniform(-1, 1, 3)]
        tb = place(A, qa, ta, B, qb, gap_pick(s))
        emit('far', A, {'t': ta, 'q': qa}, B, {'t': tb, 'q': qb}, 'T%g_s%g' % (T, s))

def gen_nested(npairs):
    for _ in range(npairs):
        s = float(10 ** rng.uniform(-1, 1))
        k = rng.integers(4)
        if k == 0:  # identical
            A = rng.choice([lambda: poly(rand_poly(int(rng.integers(4, 20)), s)), lambda: sphere_set(s), lambda: boxface_set(s)])()
            B = json.loads(json.dumps(A)); t = [float(v) for v in rng.normal(size=3) * s]
            emit('nested', A, {'t': t}, B, {'t': t}, 'identical')
        elif k == 1:  # deep inside
            A = rng.choice([lambda: poly(rand_poly(int(rng.integers(6, 20)), s)), lambda: sphere_set(s), lambda: {'type': 'box', 'half_extents': rand_box_he(s)}])()
            B = other_shape(s * float(rng.choice([1e-3, 0.05, 0.2])))
            t = [float(v) for v in rng.normal(size=3) * s]
            tb = [float(v) for v in np.asarray(t) + rng.normal(size=3) * 0.05 * s]
            emit('nested', A, {'t': t}, B, {'t': tb}, 'inside')
        elif k == 2:  # coincident, scaled copy (shared centre)
            P = rand_poly(int(rng.integers(4, 20)), s)
            f = float(rng.choice([1 - 1e-12, 1 - 1e-9, 1 - 1e-6, 0.9, 0.5]))
            t = [float(v) for v in rng.normal(size=3) * s]
            emit('nested', poly(P), {'t': t}, poly(P * f), {'t': t}, 'scaled%g' % f)
        else:  # same shape shifted slightly
            P = rand_poly(int(rng.integers(4, 20)), s)
            d = rng.normal(size=3); d /= np.linalg.norm(d)
            e = float(rng.choice([1e-12, 1e-9, 1e-6, 1e-3]))
            t = [float(v) for v in rng.normal(size=3) * s]
            emit('nested', poly(P), {'t': t}, poly(P), {'t': [float(v) for v in np.asarray(t) + d * e * s]}, 'shift%g' % e)

def cube_pts(h):
    return np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float) * h

def gen_deeptie(npairs):
    for _ in range(npairs):
        s = float(10 ** rng.uniform(-1, 1))
        k = rng.integers(3)
        if k == 0:  # cube in cube rotated slightly
            ang = float(10 ** rng.uniform(-9, -1))
            R = rot_axis(rng.normal(size=3), ang)
            f = float(rng.choice([1.0, 0.99, 0.7]))
            A = cube_pts(np.ones(3)) * s
            B = (cube_pts(np.ones(3)) * f @ R.T) * s
            off = rng.normal(size=3) * s * float(rng.choice([0, 1e-9, 1e-3, 0.1]))
            asbox = rng.random() < 0.3
            a = {'type': 'box', 'half_extents': [s, s, s]} if asbox else poly(A)
            emit('deeptie', a, {}, poly(B), {'t': [float(v) for v in off]}, 'cuberot%.0e' % ang)
        elif k == 1:  # edge-edge crossing deep
            A = cube_pts(np.ones(3)) @ rot_axis([1, 0, 0], math.pi/4 + rng.uniform(-0.01, 0.01)).T
            B = cube_pts(np.ones(3)) @ rot_axis([0, 1, 0], math.pi/4 + rng.uniform(-0.01, 0.01)).T
            R = rot_random()
            A = A @ R.T * s; B = B @ R.T * s
            dz = float(rng.uniform(2.2, 2.8))
            tb = (R @ np.array([rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05), dz])) * s
            emit('deeptie', poly(A), {}, poly(B), {'t': [float(v) for v in tb]}, 'edgeedge')
        else:  # random polytopes deep overlapping, many near-ties: regular-ish shapes
            A = sphere_set(s, int(rng.integers(12, 30)))
            B = sphere_set(s * float(rng.uniform(0.5, 1)), int(rng.integers(12, 30)))
            tb = rng.normal(size=3) * s * 0.3
            emit('deeptie', A, {}, B, {'t': [float(v) for v in tb]}, 'spheres')

def gen_boxpoly(npairs):
    for _ in range(npairs):
        s = float(10 ** rng.uniform(-1, 1))
        he = rand_box_he(s)
        if rng.random() < 0.3:
            he = [dy(v, 8) for v in he]
        qa = qpick(0.3)
        ta = [float(v) for v in rng.normal(size=3) * s]
        B = other_shape(s)
        qb = qpick()
        box = {'type': 'box', 'half_extents': he}
        tb = place(box, qa, ta, B, qb, gap_pick(s))
        P = poly(cube_pts(np.array(he)))
        r = float(rng.choice([0, 0, 0.1 * s]))
        if r:
            box = {'type': 'rounded', 'shape': box, 'radius': r}; P = {'type': 'rounded', 'shape': P, 'radius': r}
        gid = len(cases)
        emit('boxpoly', box, {'t': ta, 'q': qa}, B, {'t': tb, 'q': qb}, 'box#%d' % gid)
        emit('boxpoly', P, {'t': ta, 'q': qa}, B, {'t': tb, 'q': qb}, 'poly#%d' % gid)

if __name__ == '__main__':
    N = SCALE_N
    gen_generic('flat', flat_set, int(250*N))
    gen_generic('needle', needle_set, int(200*N))
    gen_generic('dup', dup_set, int(200*N))
    gen_generic('sphere', sphere_set, int(120*N))
    gen_generic('boxface', boxface_set, int(150*N))
    gen_touch(int(300*N))
    gen_scale(int(150*N))
    gen_far(int(200*N))
    gen_nested(int(150*N))
    gen_deeptie(int(150*N))
    gen_boxpoly(int(150*N))
    for i, c in enumerate(cases):
        c['pid'] = i
        print(json.dumps(c))
