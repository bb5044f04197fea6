# Probe queries for `mink query`: usage gen.py SEED N_PER_FAMILY > in.jsonl
# Environment: PEN=1 draws penetrating and touching pairs only; BIG=1 draws the large-polytope
# families (13 to 129 points: general, flat, needle, duplicated, ball and lattice sets) instead of
# the mixed ones.
import sys, json, math, os
import numpy as np
import oracle as O

rng = np.random.default_rng(int(sys.argv[1]))
NPER = int(sys.argv[2])

def rquat():
    c = rng.random()
    if c < 0.4:
        q = rng.normal(size=4)
    elif c < 0.7:
        base = [[1, 0, 0, 0], [0.5**0.5, 0.5**0.5, 0, 0], [0.5**0.5, 0, 0.5**0.5, 0], [0.5**0.5, 0, 0, 0.5**0.5],
                [0.5, 0.5, 0.5, 0.5], [0, 1, 0, 0]]
        q = np.array(base[rng.integers(len(base))], float)
    else:
        q = np.array([1, 0, 0, 0], float) + 10 ** rng.uniform(-9, -4) * rng.normal(size=4)
    q = q / np.linalg.norm(q)
    return [float(x) for x in q]

def pts(n, s, kind):
    if kind == 'ball':
        P = rng.normal(size=(n, 3)); P *= (rng.random((n, 1)) ** (1/3)) / np.linalg.norm(P, axis=1, keepdims=True)
    elif kind == 'flat':
        P = rng.uniform(-1, 1, size=(n, 3)); P[:, 2] = 0
    elif kind == 'needle':
        P = rng.uniform(-1, 1, size=(n, 3)); P[:, 1:] *= 10 ** rng.uniform(-8, -4)
    elif kind == 'dup':
        P = rng.uniform(-1, 1, size=(max(2, n // 2), 3)); P = np.vstack([P, P[: n - len(P)]])
    elif kind == 'cube':
        P = np.array([[i, j, k] for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)], float) * rng.uniform(0.2, 1, 3)
    elif kind == 'lattice':
        # A grid on a box's surface: many coplanar and collinear points.
        k = int(rng.integers(2, 6))
        g = np.linspace(-1, 1, k)
        P = np.array([[x, y, z] for x in g for y in g for z in g
                      if max(abs(x), abs(y), abs(z)) == 1.0], float) * rng.uniform(0.2, 1, 3)
    elif kind == 'tet':
        P = rng.uniform(-1, 1, size=(4, 3))
    else:
        P = rng.uniform(-1, 1, size=(n, 3))
    P = P * s
    return [[float(x) for x in p] for p in P]

def shape(t, s=1.0):
    u = lambda lo=0.2, hi=1.0: float(s * rng.uniform(lo, hi))
    if t == 'sphere': return {'type': 'sphere', 'radius': u()}
    if t == 'box': return {'type': 'box', 'half_extents': [u(), u(), u()]}
    if t == 'flatbox': return {'type': 'box', 'half_extents': [u(), u(), float(s * 10 ** rng.uniform(-6, -2))]}
    if t == 'capsule': return {'type': 'capsule', 'radius': u(), 'half_height': u()}
    if t == 'cylinder': return {'type': 'cylinder', 'radius': u(), 'half_height': u()}
    if t == 'cone': return {'type': 'cone', 'radius': u(), 'half_height': u()}
    if t == 'ellipsoid': return {'type': 'ellipsoid', 'radii': [u(), u(), u()]}
    if t == 'ellx':
        r = [u(0.5, 1), u(0.5, 1), u(0.5, 1)]
        k = rng.integers(3); r[k] = float(r[k] * 10 ** rng.uniform(-3.3, -2.5))
        if rng.random() < 0.4:
            k2 = (k + 1) % 3; r[k2] = float(r[k2] * 10 ** rng.uniform(-3.3, -2.5))
        return {'type': 'ellipsoid', 'radii': r}
    if t == 'point': return {'type': 'point', 'points': pts(1, s, 'u')}
    if t == 'segment': return {'type': 'segment', 'points': pts(2, s, 'u')}
    if t == 'triangle': return {'type': 'triangle', 'points': pts(3, s, 'u')}
    if t.startswith('poly'):
        kind = t[5:] if len(t) > 4 else 'u'
        kind = kind or 'u'
        n = int(rng.integers(13, 130)) if BIG else int(rng.integers(4, 13))
        return {'type': 'polytope', 'points': pts(n, s, kind)}
    if t == 'rbox': return {'type': 'rounded', 'shape': shape('box', s), 'radius': u(0.01, 0.3)}
    if t == 'rpoly': return {'type': 'rounded', 'shape': shape('poly', s), 'radius': u(0.01, 0.3)}
    if t == 'rtri': return {'type': 'rounded', 'shape': shape('triangle', s), 'radius': u(0.01, 0.3)}
    if t == 'rseg': return {'type': 'rounded', 'shape': shape('segment', s), 'radius': u(0.01, 0.3)}
    if t == 'rcyl': return {'type': 'rounded', 'shape': shape('cylinder', s), 'radius': u(0.01, 0.3)}
    if t == 'rcone': return {'type': 'rounded', 'shape': shape('cone', s), 'radius': u(0.01, 0.3)}
    if t == 'rflat': return {'type': 'rounded', 'shape': shape('poly_flat', s), 'radius': float(s * 10 ** rng.uniform(-6, -1))}
    if t == 'sweep':
        first = ['box', 'poly', 'triangle', 'sphere', 'ellipsoid', 'cone', 'cylinder', 'capsule', 'segment', 'poly_flat', 'ellx', 'rbox']
        second = ['segment', 'segment', 'sphere', 'triangle', 'point', 'box', 'poly']
        a = shape(str(rng.choice(first)), s * 0.7)
        b = shape(str(rng.choice(second)), s * float(rng.choice([1e-6, 1e-3, 0.3, 0.7, 2.0])))
        return {'type': 'sum', 'shapes': [a, b]}
    raise ValueError(t)

SOLIDS = ['sphere', 'box', 'capsule', 'cylinder', 'cone', 'ellipsoid', 'poly', 'sweep', 'rbox']
FAMILIES = {
    'sweep_vs_boxpoly': (['sweep'], ['box', 'poly', 'sphere', 'flatbox', 'poly_tet', 'poly_cube']),
    'sweep_vs_sweep': (['sweep'], ['sweep']),
    'rounded_pair': (['rbox', 'rpoly', 'rtri', 'rseg', 'rflat'], ['rbox', 'rpoly', 'rtri', 'rflat', 'rcyl', 'rcone']),
    'lowdim_vs_solid': (['triangle', 'segment', 'point'], SOLIDS + ['rpoly', 'ellx', 'poly_flat']),
    'ellx_vs_poly': (['ellx'], ['poly', 'box', 'flatbox', 'poly_flat', 'poly_needle', 'triangle', 'rbox', 'ellx']),
    'smallpoly': (['poly', 'poly_flat', 'poly_needle', 'poly_dup', 'poly_tet'], ['poly', 'poly_flat', 'poly_needle', 'poly_dup', 'box', 'sphere', 'capsule', 'ellipsoid']),
    'cone_vs_poly': (['cone', 'rcone'], ['poly', 'box', 'flatbox', 'poly_flat', 'poly_cube', 'triangle']),
    'far': (SOLIDS + ['triangle', 'segment', 'rpoly'], SOLIDS + ['triangle', 'poly_flat']),
    'scale': (SOLIDS + ['triangle', 'segment', 'poly_flat'], SOLIDS + ['triangle', 'poly_flat']),
}
BIG_FAMILIES = {
    'bigpoly': (['poly', 'poly_flat', 'poly_needle', 'poly_dup', 'poly_lattice', 'poly_ball'],
                ['poly', 'poly_flat', 'poly_lattice', 'poly_ball', 'poly_needle']),
    'bigpoly_prim': (['poly', 'poly_lattice', 'poly_ball', 'poly_flat'],
                     ['box', 'sphere', 'capsule', 'cylinder', 'cone', 'ellipsoid', 'rbox', 'flatbox',
                      'segment', 'triangle']),
    'rbigpoly': (['rpoly'], ['poly_lattice', 'rpoly', 'box', 'cylinder']),
}
BIG = os.environ.get('BIG') == '1'
if BIG:
    FAMILIES = BIG_FAMILIES

PEN = os.environ.get('PEN') == '1'
def gap_class():
    c = rng.integers(9) if not PEN else rng.integers(4, 9)
    return ['sep_1e-6', 'sep_1e-4', 'sep_1e-2', 'sep_big', 'touch', 'touch_eps', 'pen_small', 'pen_mid', 'pen_deep'][c]

def gap_value(c, size):
    if c == 'sep_1e-6': return size * 10 ** rng.uniform(-7, -5.5)
    if c == 'sep_1e-4': return size * 10 ** rng.uniform(-5, -3.5)
    if c == 'sep_1e-2': return size * 10 ** rng.uniform(-3, -1.5)
    if c == 'sep_big': return size * rng.uniform(0.05, 0.5)
    if c == 'touch': return 0.0
    if c == 'touch_eps': return size * rng.choice([-1, 1]) * 10 ** rng.uniform(-12, -10)
    if c == 'pen_small': return -size * 10 ** rng.uniform(-7, -3)
    if c == 'pen_mid': return -size * 10 ** rng.uniform(-3, -1.3)
    return -size * rng.uniform(0.05, 0.6)

lines = []
for fam, (LA, LB) in FAMILIES.items():
    for i in range(NPER):
        sa = 1.0; sb = 1.0
        if fam == 'scale':
            r = 10 ** rng.uniform(-4, 4) if rng.random() < 0.5 else rng.choice([1e-4, 1e4, 1e-3, 1e3])
            sb = float(r)
        ta, tb = str(rng.choice(LA)), str(rng.choice(LB))
        if rng.random() < 0.5: ta, tb, sa, sb = tb, ta, sb, sa
        a = shape(ta, sa); b = shape(tb, sb)
        qa, qb = rquat(), rquat()
        u = rng.normal(size=3); u /= np.linalg.norm(u)
        if rng.random() < 0.3:
            u = np.zeros(3); u[rng.integers(3)] = rng.choice([-1, 1])
        A = O.Posed(a, {'q': qa}, [0, 0, 0]); B = O.Posed(b, {'q': qb}, [0, 0, 0])
        size = O.brad(a) + O.brad(b)
        lat = rng.normal(size=3) * 0.2 * size * rng.random() * (0.02 if PEN else 1)
        lat -= lat.dot(u) * u
        B.t = lat
        gc = gap_class()
        g = gap_value(gc, size)
        lam = A.h(u)[0] + B.h(-u)[0] + g
        tB = lat + lam * u
        tA = np.zeros(3)
        if fam == 'far':
            off = rng.normal(size=3); off *= 10 ** rng.uniform(5, 6) / np.linalg.norm(off)
            tA = tA + off; tB = tB + off
        elif rng.random() < 0.3:
            off = rng.normal(size=3) * 10
            tA = tA + off; tB = tB + off
        pa = {'t': [float(x) for x in tA], 'q': qa}
        pb = {'t': [float(x) for x in tB], 'q': qb}
        base = {'a': a, 'pa': pa, 'b': b, 'pb': pb}
        idb = f'{fam}:{ta}-{tb}:{gc}:{i}'
        lines.append(dict(id=idb, **base, want='contact'))
        if rng.random() < 0.35:
            lines.append(dict(id=idb + ':D', **base, want='distance'))
            lines.append(dict(id=idb + ':I', **base, want='intersect'))
for l in lines:
    print(json.dumps(l))
