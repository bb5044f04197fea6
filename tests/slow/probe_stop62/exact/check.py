import json, sys, math, time, traceback
from fractions import Fraction as F
import mpmath
from oracle import *

def strip(c, order, want):
    a, pa, b, pb = (c['a'], c['pa'], c['b'], c['pb']) if order == 0 else (c['b'], c['pb'], c['a'], c['pa'])
    q = {'id': '%d:%d:%s' % (c['pid'], order, want[0]), 'a': a, 'pa': pa, 'b': b, 'pb': pb, 'want': want}
    return q

def vec_int(v):
    fs = [F(x) for x in v]
    den = max(x.denominator for x in fs)
    m = den.bit_length() - 1
    return tuple(int(x * den) for x in fs), m

def exact_values(res):
    r = res['ra'] + res['rb']
    rm = mpmath.mpf(r.numerator) / r.denominator
    if not res['core_inter']:
        dc = mp_sqrt(res['core_d2'].numerator, res['core_d2'].denominator)
        gap = dc - rm
        return -gap  # signed: >0 penetrating depth, <0 -distance
    dep = mp_sqrt(res['core_depth2'].numerator, res['core_depth2'].denominator)
    return dep + rm

def gsep(HA, HB, rA, rB, sh, n):
    nI, m = vec_int(n)
    if iszero(nI):
        return None
    h = max(dot(nI, a) for a in HA.verts) - min(dot(nI, b) for b in HB.verts)
    nn = mp_sqrt(dot(nI, nI), 1)
    return mpmath.mpf(h) / nn / mpmath.mpf(sh) + mpmath.mpf(rA.numerator) / rA.denominator + mpmath.mpf(rB.numerator) / rB.denominator

def surf_err(H, r, sh, p):
    pg = tuple(F(x) * sh for x in p)
    sd = signed_dist_to_hull(H, pg) / mpmath.mpf(sh)
    return abs(sd - mpmath.mpf(r.numerator) / r.denominator)

def evaluate(c, res, ans, order, want, size):
    HA, HB, rA, rB = (res['A'], res['B'], res['ra'], res['rb']) if order == 0 else (res['B'], res['A'], res['rb'], res['ra'])
    sh = res['sh']
    s_ex = exact_values(res)
    out = {'id': ans.get('id'), 'status': ans.get('status'), 's_exact': float(s_ex), 'size': size}
    if ans.get('status') == 'error':
        out['fail'] = ['error:' + ans.get('error', '')]
        return out
    fails = []
    inter_ex = s_ex >= 0
    tolv = 1e-9 * size
    if want == 'intersect':
        if ans['intersect'] != bool(inter_ex) and abs(s_ex) > 1e-12 * size:
            out['flag_err'] = float(abs(s_ex)) / size
            if abs(s_ex) > tolv: fails.append('intersect_flag')
        out['fail'] = fails
        return out
    if want == 'distance':
        dex = max(-s_ex, 0)
        out['val_err'] = float(abs(mpmath.mpf(ans['distance']) - dex)) / size
        if ans['intersect'] != bool(inter_ex) and abs(s_ex) > 1e-12 * size:
            out['flag_err'] = float(abs(s_ex)) / size
            if abs(s_ex) > tolv: fails.append('intersect_flag')
        if out['val_err'] > 1e-9: fails.append('distance_value')
        if not ans['intersect'] and 'normal' in ans:
            s_tool = -mpmath.mpf(ans['distance'])
        else:
            out['fail'] = fails
            return out
    else:
        s_tool = mpmath.mpf(ans['depth']) - mpmath.mpf(ans['distance'])
        out['val_err'] = float(abs(s_tool - s_ex)) / size
        if out['val_err'] > 1e-9: fails.append('value')
        if ans['intersect'] != bool(inter_ex) and abs(s_ex) > 1e-12 * size:
            out['flag_err'] = float(abs(s_ex)) / size
            if abs(s_ex) > tolv: fails.append('intersect_flag')
    n = ans.get('normal')
    if n is not None:
        g = gsep(HA, HB, rA, rB, sh, n)
        if g is None:
            fails.append('zero_normal')
        else:
            out['nrm_sub'] = float(g - s_ex) / size
            if out['nrm_sub'] > 1e-9 or out['nrm_sub'] < -1e-9: fails.append('normal')
            nl = math.sqrt(sum(x*x for x in n))
            out['nrm_len_err'] = abs(nl - 1)
            if abs(nl - 1) > 1e-9: fails.append('normal_not_unit')
    else:
        fails.append('no_normal')
    pa, pb = ans.get('point_a'), ans.get('point_b')
    if pa is not None and pb is not None:
        ea = surf_err(HA, rA, sh, pa); eb = surf_err(HB, rB, sh, pb)
        out['wit_a'] = float(ea) / size; out['wit_b'] = float(eb) / size
        if n is not None:
            rel = [mpmath.mpf(pb[k]) - mpmath.mpf(pa[k]) + s_tool * mpmath.mpf(n[k]) for k in range(3)]
            out['wit_rel'] = float(mpmath.sqrt(sum(x*x for x in rel))) / size
        w = max(out['wit_a'], out['wit_b'], out.get('wit_rel', 0))
        out['wit'] = w
        if w > 1e-9: fails.append('witness')
    else:
        fails.append('no_points')
    out['fail'] = fails
    return out

def main():
    cases = [json.loads(l) for l in open(sys.argv[1])]
    answers = {}
    for l in open(sys.argv[2]):
        a = json.loads(l); answers[a['id']] = a
    out = open(sys.argv[3], 'w')
    t0 = time.time()
    for c in cases:
        size = bounding_radius(c['a']) + bounding_radius(c['b'])
        T = max(math.sqrt(sum(x*x for x in c[p].get('t', [0, 0, 0]))) for p in ('pa', 'pb'))
        try:
            res = solve({'a': c['a'], 'pa': c['pa'], 'b': c['b'], 'pb': c['pb']})
        except Exception as e:
            out.write(json.dumps({'pid': c['pid'], 'cls': c['cls'], 'oracle_exc': traceback.format_exc()}) + '\n'); out.flush()
            continue
        rec = {'pid': c['pid'], 'cls': c['cls'], 'sub': c['sub'], 'size': size, 'T': T,
               's_exact': float(exact_values(res)), 'dimD': res['dimD'], 'oracle_error': res.get('oracle_error'),
               'dimA': res['A'].dim, 'dimB': res['B'].dim, 'ev': []}
        for order in (0, 1):
            for want in ('contact', 'distance', 'intersect'):
                q = strip(c, order, want)
                ans = answers.get(q['id'])
                if ans is None:
                    continue
                try:
                    ev = evaluate(c, res, ans, order, want, size)
                except Exception:
                    ev = {'id': q['id'], 'eval_exc': traceback.format_exc(), 'fail': ['eval_exc']}
                ev['ans'] = ans
                rec['ev'].append(ev)
        out.write(json.dumps(rec) + '\n'); out.flush()
    print('done', time.time() - t0, file=sys.stderr)

if __name__ == '__main__':
    main()
