# grade mink answers against the independent oracle.
# usage: grade.py in.jsonl out.jsonl report.jsonl [nproc]
import sys, json, math, traceback
import numpy as np
from multiprocessing import Pool
import oracle as O

def core_shape(s):
    c = O.core_points(s)
    if c is None: return None, 0.0
    return {'type': 'polytope', 'points': c[0].tolist()}, c[1]

def member_err(P, p, tol_abs):
    """certified lower bound on dist(p, shape) (minus radius for polyhedral cores)."""
    cs, r = core_shape(P.s)
    if cs is not None:
        C = O.Posed(cs, None, [0, 0, 0]); C.R = P.R; C.t = P.t
        g = O.point_dist(C, p, tol_abs * 1e-3)
        return max(g['lo'] - r, 0.0), g['hi'] - r
    g = O.point_dist(P, p, tol_abs * 1e-3)
    return g['lo'], g['hi']

def signed_oracle(A, B, size, seeds):
    """returns dict: m (estimate of min h_D; negative = -distance), lo/hi bracket where known, how."""
    ca, ra = core_shape(A.s); cb, rb = core_shape(B.s)
    tol_abs = 1e-14 * size
    if ca is not None and cb is not None:
        CA = O.Posed(ca, None, [0, 0, 0]); CA.R = A.R; CA.t = A.t
        CB = O.Posed(cb, None, [0, 0, 0]); CB.R = B.R; CB.t = B.t
        r = ra + rb
        g = O.gjk(O.make_supD(CA, CB), tol_abs)
        if g['lo'] > tol_abs * 10 or (not g['inside'] and g['hi'] > 1e-12 * size):
            return dict(m=r - 0.5 * (g['lo'] + g['hi']), lo=r - g['hi'], hi=r - g['lo'], how='poly_gjk', n=g['dir'])
        pe = O.poly_exact(CA, CB)
        if pe is not None:
            return dict(m=pe[0] + r, lo=None, hi=pe[0] + r, how='poly_hull', n=pe[1])
        # degenerate core hull: search
        f, n = O.min_hD(A, B, seeds=seeds)
        return dict(m=f, lo=None, hi=f, how='poly_search', n=n)
    g = O.gjk(O.make_supD(A, B), tol_abs)
    if g['lo'] > tol_abs * 10 or (not g['inside'] and g['hi'] > 1e-12 * size):
        return dict(m=-0.5 * (g['lo'] + g['hi']), lo=-g['hi'], hi=-g['lo'], how='gjk', n=g['dir'])
    f, n = O.min_hD(A, B, seeds=seeds)
    return dict(m=f, lo=None, hi=f, how='search', n=n)

def ulp_allow(*vs):
    m = max(max(abs(float(x)) for x in v) for v in vs)
    return 8 * np.spacing(m) if m > 0 else 0.0

def grade_one(args):
    q, ans = args
    r = dict(id=q.get('id'), fam=str(q.get('id')).split(':')[0], want=q.get('want', 'contact'), fails=[])
    try:
        if ans.get('status') not in ('ok',):
            r['fails'].append('status=' + str(ans.get('status')) + ' ' + str(ans.get('error', '')))
            if ans.get('status') == 'error':
                return r
        for k, v in ans.items():
            if isinstance(v, float) and not math.isfinite(v): r['fails'].append('nan')
        a, b = q['a'], q['b']
        size = O.brad(a) + O.brad(b)
        r['size'] = size
        tol = 1e-9 * size
        origin = (q.get('pa') or {}).get('t', [0, 0, 0])
        A = O.Posed(a, q.get('pa'), origin); B = O.Posed(b, q.get('pb'), origin)
        allow = ulp_allow(origin, (q.get('pb') or {}).get('t', [0, 0, 0]))
        r['allow'] = allow
        seeds = []
        if 'normal' in ans: seeds.append(np.array(ans['normal'], float))
        orc = signed_oracle(A, B, size, seeds)
        m = orc['m']; r['oracle_m'] = m; r['how'] = orc['how']
        I = ans.get('intersect')
        # verdict
        if orc['lo'] is not None:
            if orc['hi'] < -tol - allow and I: r['fails'].append('verdict_true_but_sep')
        if m > tol + allow and I is False: r['fails'].append('verdict_false_but_pen')
        r['e_val'] = 0.0; r['e_norm'] = 0.0; r['e_wit'] = 0.0
        want = r['want']
        if want == 'intersect':
            return r
        if I is False:
            d = ans['distance']
            r['e_val'] = abs(d + m) / size
            if orc['lo'] is not None:
                ev = max(0.0, d - (-orc['lo']), (-orc['hi']) - d) / size
                r['e_val'] = ev
        else:
            if 'depth' in ans:
                p = ans['depth']
                r['e_val'] = abs(p - max(m, 0.0)) / size if m > -tol else abs(p) / size
        if 'normal' in ans and ('point_a' in ans):
            n = np.array(ans['normal'], float)
            if abs(np.linalg.norm(n) - 1) > 1e-12: r['fails'].append('normal_not_unit')
            n = n / np.linalg.norm(n)
            hv = O.hD(A, B, n)[0]
            pa = np.array([float(O.Fraction(ans['point_a'][i]) - O.Fraction(origin[i])) for i in range(3)])
            pb = np.array([float(O.Fraction(ans['point_b'][i]) - O.Fraction(origin[i])) for i in range(3)])
            if I is False:
                d = ans['distance']
                r['e_norm'] = abs(-hv - d) / size
                rel = np.linalg.norm(pb - pa - d * n)
                supa = abs(n @ pa - A.h(n)[0]); supb = abs(n @ pb + B.h(-n)[0])
            else:
                p = ans.get('depth', 0.0)
                r['e_norm'] = abs(hv - p) / size if m > -tol else max(0.0, hv - 0) / size
                rel = np.linalg.norm(pb - pa + p * n)
                supa = abs(n @ pa - A.h(n)[0]); supb = abs(n @ pb + B.h(-n)[0])
            ma = member_err(A, pa, tol); mb = member_err(B, pb, tol)
            r['e_wit'] = max(rel, supa, supb, ma[0], mb[0]) / size
            r['wit_parts'] = [rel / size, supa / size, supb / size, ma[0] / size, mb[0] / size]
            r['hv'] = hv
        thr = 1e-9 + allow / size
        if r['e_val'] > thr: r['fails'].append('value')
        if r['e_norm'] > thr: r['fails'].append('normal')
        if r['e_wit'] > thr: r['fails'].append('witness')
    except Exception as e:
        r['fails'].append('grader_exc ' + repr(e) + traceback.format_exc()[-300:])
    return r

import time
def timed(x):
    t0 = time.time(); r = grade_one(x); r['sec'] = time.time() - t0; return r

def main():
    qs = [json.loads(l) for l in open(sys.argv[1])]
    ans = [json.loads(l) for l in open(sys.argv[2])]
    np_ = int(sys.argv[4]) if len(sys.argv) > 4 else 2
    res = []
    with Pool(np_) as pool, open(sys.argv[3], 'w') as f:
        for r in pool.imap_unordered(timed, list(zip(qs, ans)), chunksize=1):
            res.append(r)
            f.write(json.dumps(r, default=float) + '\n'); f.flush()
    nf = sum(1 for r in res if r['fails'])
    print('graded', len(res), 'failing', nf)

if __name__ == '__main__':
    main()
