"""Runs mink on gen_exact.py's cases, and on probe 62's (../probe_stop62/curved/gen_curved.py),
contact and distance in both argument orders, and checks every answer against the construction,
refined in long double.
usage: MINK=path python3 check.py cases.jsonl results.jsonl
Errors are recorded as fractions of the size (sum of the bounding radii); an answer fails beyond
1e-9 of the size plus 16 eps times the largest translation (the rounding of world coordinates)."""
import json, os, subprocess, sys, time
import numpy as np
from common import (LD, ld, unit, TOOL, pose_of, support_point, structured_min, world_support, pair_fn, minimize, refine, bounding_radius, h_world, signed_distance,
                    support_search_sd, EPS)

WANTS = ("contact", "distance")

def qline(c, want, order):
    a, pa, b, pb = (c["a"], c["pa"], c["b"], c["pb"]) if order == "o" else (c["b"], c["pb"], c["a"], c["pa"])
    return {"id": f"{c['id']}:{want}:{order}", "a": a, "pa": pa, "b": b, "pb": pb, "want": want}

def run_tool(lines, chunk=2000, timing=False):
    out, problems, wall = {}, [], 0.0
    for k in range(0, len(lines), chunk):
        part = lines[k:k + chunk]
        inp = "\n".join(json.dumps(l) for l in part) + "\n"
        t0 = time.time()
        p = subprocess.run(["timeout", "600", TOOL, "query"] + (["--timing"] if timing else []), input=inp,
                           capture_output=True, text=True)
        wall += time.time() - t0
        if p.returncode != 0: problems.append(f"chunk {k}: rc={p.returncode} {p.stderr[:300]}")
        got = p.stdout.splitlines()
        if len(got) != len(part): problems.append(f"chunk {k}: {len(got)} answers for {len(part)} lines")
        for l in got:
            try:
                a = json.loads(l); out[str(a["id"])] = a
            except Exception:
                problems.append("unparseable: " + l[:200])
    return out, problems, wall

def point_sd(shape, pose, x, hint):
    """signed distance of x to the shape: closed form if there is one, else a long-double support
    search from hint (confirmed by a denser search when it claims the point is inside)"""
    d = signed_distance(shape, pose, x)
    if d is not None: return float(d), "closed"
    v = support_search_sd(shape, pose, x, hint)
    return float(v), "search"

def check_case(c, ans):
    P, pa, C, pb, exp = c["a"], c["pa"], c["b"], c["pb"], c["exp"]
    size = bounding_radius(P) + bounding_radius(C)
    T = max(np.max(np.abs(pa["t"])), np.max(np.abs(pb["t"])))
    tol = 1e-9 * size; allow = tol + 16 * EPS * T
    F = pair_fn(P, pa, C, pb, LD)
    if exp["n"] is None:   # no construction: a search, refined in long double
        # exp.hint (probe 62's gen_curved.py, tilt_search): the direction the case was built on,
        # one more start for the search and its own refinement.
        hint = exp.get("hint")
        v, u = minimize(pair_fn(P, pa, C, pb), ngrid=20000, nstarts=6, extra=[hint] if hint else [])
        s_n, n = refine(F, u, r0=1e-4); s_n = float(s_n)
        if hint:
            s_h, n_h = refine(F, ld(hint), r0=1e-6)
            if float(s_h) < s_n: s_n, n = float(s_h), n_h
            rs = structured_min(P, pa, C, pb, ld(hint), size)
            if rs is not None and rs[0] < s_n: s_n, n = rs[0], rs[1]
        exp = dict(exp, n=[float(x) for x in n], gap=-s_n)
    n = ld(exp["n"]); n /= np.sqrt(np.sum(n * n))
    s_n = float(F(n[None, :])[0])
    s_ref, u_ref = refine(F, n, r0=1e-6)
    s_ref = float(min(s_ref, s_n))
    ref = "exact" if c["exp"]["n"] is not None else "oracle"
    if ref == "exact" and s_ref < s_n - 1e-9 * size:
        ref = "oracle_beat"   # n is not a minimum (an overlap where another direction separates sooner)
    r = {"id": c["id"], "cat": c["cat"], "size": size, "T": float(T), "allow_rel": allow / size, "gap": exp["gap"],
         "s_n": s_n, "errs": {}, "issues": [], "status": []}
    # tool normals (A -> B, in the P -> C orientation)
    tn = []
    for w in WANTS:
        for o in "os":
            x = ans.get(f"{c['id']}:{w}:{o}")
            if x and "normal" in x:
                v = np.array(x["normal"], float); tn.append(v if o == "o" else -v)
    overlapping = exp["gap"] <= 0 and ref != "oracle"
    if ref == "oracle":
        for t in tn:
            v3, u3 = refine(F, unit(t), r0=1e-6)
            s_ref = min(s_ref, float(v3))
    if overlapping or any(float(F(ld(unit(v))[None, :])[0]) < s_ref - 1e-3 * tol for v in tn):
        Fd = pair_fn(P, pa, C, pb)
        v, u = minimize(Fd, ngrid=20000, nstarts=6, extra=[np.asarray(exp["n"])] + tn[:2])
        v2, u2 = refine(F, u, r0=1e-4)
        for t in tn:
            v3, u3 = refine(F, unit(t), r0=1e-6)
            if v3 < v2: v2, u2 = v3, u3
        if float(v2) < s_ref - 1e-3 * tol:
            ref = "oracle_beat"; r["construction_beaten_by"] = (s_ref - float(v2)) / size
        if float(v2) < s_ref: s_ref = float(v2)
    r["s_ref"] = s_ref; r["ref"] = ref
    unique = exp["unique"] and ref == "exact"
    e, cc = (np.array(exp["e"]), np.array(exp["c"])) if unique else (None, None)

    def err(name, val):
        r["errs"][name] = max(r["errs"].get(name, 0.0), float(val) / size)
        return float(val)

    def issue(kind, line, val, **kw):
        r["issues"].append({"kind": kind, "line": line, "rel": float(val) / size, **kw})

    vals, pts = {}, {}
    for w in WANTS:
        for o in "os":
            lid = f"{c['id']}:{w}:{o}"
            x = ans.get(lid)
            if x is None: issue("missing", lid, np.inf); continue
            if x.get("status") != "ok":
                r["status"].append([lid, x.get("status"), x.get("error")]); issue("status", lid, 0.0, status=x.get("status"))
                if x.get("status") == "error": continue
            it = x.get("intersect")
            if it and s_ref < -allow: issue("verdict_intersect_but_apart", lid, -s_ref)
            if it is False and s_ref > allow: issue("verdict_apart_but_overlap", lid, s_ref)
            if w == "distance" and it:
                if x.get("distance", 0) != 0: issue("distance_nonzero", lid, abs(x["distance"]))
                continue
            st = x["depth"] if it else -x["distance"]
            vals[(w, o)] = st
            if err("value", abs(st - s_ref)) > allow: issue("value", lid, abs(st - s_ref), tool=st, ref=s_ref)
            if "normal" not in x: issue("no_normal", lid, 0.0); continue
            nt = np.array(x["normal"], float)
            if abs(np.linalg.norm(nt) - 1) > 1e-12: issue("normal_not_unit", lid, abs(np.linalg.norm(nt) - 1) * size)
            nP = unit(nt) if o == "o" else -unit(nt)          # in the P -> C orientation
            fn = float(F(ld(nP)[None, :])[0])
            if err("normal", fn - s_ref) > allow: issue("normal", lid, fn - s_ref, F_normal=fn, ref=s_ref,
                                                         angle=float(np.arccos(min(1.0, abs(nP @ np.asarray(exp['n']))))))
            if fn < s_ref - allow: issue("ref_beaten", lid, s_ref - fn)
            if ref == "exact":
                r["errs"]["angle_rad"] = max(r["errs"].get("angle_rad", 0.0), float(np.linalg.norm(np.cross(nP, np.asarray(exp["n"])))))
            if "point_a" not in x or "point_b" not in x: issue("no_points", lid, 0.0); continue
            A, B = np.array(x["point_a"]), np.array(x["point_b"])
            expect = (-x["depth"] * nt) if it else (x["distance"] * nt)
            if err("relation", np.linalg.norm((B - A) - expect)) > allow: issue("relation", lid, np.linalg.norm((B - A) - expect))
            onP, onC = (A, B) if o == "o" else (B, A)
            pts[(w, o)] = (onP, onC)
            # independent of the construction: the minimum from the structure of the support
            # sets along the tool's normal (common.structured_min), and the witness pair there
            # where one shape has a single support point (closed form, with a margin)
            rs = structured_min(P, pa, C, pb, nP, size)
            if rs is not None and rs[0] <= fn + 1e-3 * tol:
                vs, us, kind = rs
                if vs < s_ref - allow: issue("struct_beats_ref", lid, s_ref - vs, structure=kind)
                r["errs"]["struct_angle_rad"] = max(r["errs"].get("struct_angle_rad", 0.0), float(np.linalg.norm(np.cross(nP, np.array(us, float)))))
                sP_, uqP = world_support(P, pa, us, thr=1e-4); sC_, uqC = world_support(C, pb, -us, thr=1e-4)
                eP_ = eC_ = None
                if uqC: sC_ = np.array(sC_, float); eC_ = np.linalg.norm(onC - sC_); eP_ = np.linalg.norm(onP - (sC_ + vs * np.array(us, float)))
                elif uqP: sP_ = np.array(sP_, float); eP_ = np.linalg.norm(onP - sP_); eC_ = np.linalg.norm(onC - (sP_ - vs * np.array(us, float)))
                if eP_ is not None and err("struct_witness", max(eP_, eC_)) > allow:
                    issue("struct_witness", lid, max(eP_, eC_), structure=kind, off_P=eP_ / size, off_C=eC_ / size,
                          angle=float(np.linalg.norm(np.cross(nP, np.array(us, float)))))
            else:
                r["errs"]["struct_none"] = r["errs"].get("struct_none", 0) + 1
            if unique:
                eP, eC = np.linalg.norm(onP - e), np.linalg.norm(onC - cc)
                if err("witness", max(eP, eC)) > allow: issue("witness", lid, max(eP, eC), off_P=eP / size, off_C=eC / size)
            else:
                # on the surfaces, and on the support planes along the reference normal
                nref = np.asarray(exp["n"]) if ref == "exact" else unit(nP)
                sp = abs(float(nref @ onP) - h_world(P, pa, nref))
                sc = abs(float(-nref @ onC) - h_world(C, pb, -nref))
                if err("support_plane", max(sp, sc)) > allow: issue("support_plane", lid, max(sp, sc), P=sp / size, C=sc / size)
                dP, kP = point_sd(P, pa, onP, nref)
                dC, kC = point_sd(C, pb, onC, -nref)
                worst = max(abs(dP), abs(dC))
                if worst > allow and (kP == "search" and abs(dP) == worst or kC == "search" and abs(dC) == worst):
                    # a search claims it: confirm by a denser one
                    if kP == "search": dP = support_search_sd(P, pa, onP, nref, fine=True)
                    if kC == "search": dC = support_search_sd(C, pb, onC, -nref, fine=True)
                    worst = max(abs(dP), abs(dC))
                if err("surface", worst) > allow: issue("surface", lid, worst, P=dP / size, C=dC / size, how=[kP, kC])
    # swap consistency (values and points)
    for w in WANTS:
        if (w, "o") in vals and (w, "s") in vals:
            if err("swap_value", abs(vals[(w, "o")] - vals[(w, "s")])) > allow:
                issue("swap_value", f"{c['id']}:{w}", abs(vals[(w, "o")] - vals[(w, "s")]))
        if (w, "o") in pts and (w, "s") in pts:
            d = max(np.linalg.norm(pts[(w, "o")][0] - pts[(w, "s")][0]), np.linalg.norm(pts[(w, "o")][1] - pts[(w, "s")][1]))
            if unique:   # a single witness pair: both orders must give it
                if err("swap_points", d) > allow: issue("swap_points", f"{c['id']}:{w}", d)
    return r

def main():
    cases = [json.loads(l) for l in open(sys.argv[1])]
    lines = [qline(c, w, o) for c in cases for w in WANTS for o in "os"]
    ans, problems, wall = run_tool(lines)
    print(f"tool: {len(lines)} lines, {wall:.2f}s wall, {1e6 * wall / len(lines):.1f} us/line; problems {problems[:5]}", file=sys.stderr)
    t0 = time.time()
    with open(sys.argv[2], "w") as fo:
        for k, c in enumerate(cases):
            a = {l["id"]: ans.get(l["id"]) for l in lines[4 * k:4 * k + 4]}
            try:
                r = check_case(c, a)
            except Exception as ex:
                r = {"id": c["id"], "cat": c["cat"], "errs": {}, "issues": [{"kind": "checker_exception", "line": c["id"], "rel": 0, "msg": repr(ex)}], "status": []}
            fo.write(json.dumps(r) + "\n"); fo.flush()
            if k % 200 == 0: print(f"checked {k} in {time.time() - t0:.0f}s", file=sys.stderr)
    json.dump({"problems": problems, "wall": wall, "lines": len(lines)}, open(sys.argv[2] + ".meta", "w"))

if __name__ == "__main__":
    main()
