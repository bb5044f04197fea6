"""Runs mink on generated cases and checks answers against probe 50's support-function oracle.
usage: MINK=path python3 check.py cases.jsonl results.jsonl
Each case: a, pa, b, pb, wants (subset of contact/intersect/distance/manifold), optional margin,
variants (manifold also run with A and B swapped, and with both moved by one rigid motion),
expect_count (resting contact)."""
import json, os, sys, time, numpy as np
from multiprocessing import Pool
from oracle import bounding_radius, minimize, pair_fn, member_fn, support_local, pose_of, quat_to_R
from shapes import qmul

TOOL = os.environ.get("MINK", "../../../build/release/tools/mink/mink")
EPS = 2.2e-16

EXACT_MOTION = ("far", "scale_tiny", "scale_huge")
def motion_of(cid, cat=""):
    if cat in EXACT_MOTION:  # a permutation of the axes: exact, keeps far and tiny scenes exact
        return [0.5, 0.5, 0.5, 0.5], [0.0, 0.0, 0.0]
    r = np.random.default_rng(__import__("zlib").crc32(str(cid).encode()))
    q = r.normal(size=4); q /= np.linalg.norm(q)
    t = r.normal(size=3) * 3
    return [float(v) for v in q], [float(v) for v in t]

def move_pose(p, q, t):
    R = quat_to_R(q)
    pt = np.array(p.get("t", [0, 0, 0]), float)
    pq = p.get("q", [1, 0, 0, 0])
    return {"t": [float(v) for v in R @ pt + np.array(t)], "q": qmul(q, pq)}

def qline(c, want, variant=""):
    a, pa, b, pb = c["a"], c["pa"], c["b"], c["pb"]
    if variant == "swap":
        a, pa, b, pb = b, pb, a, pa
    elif variant == "move":
        q, t = motion_of(c["id"], c["cat"])
        pa, pb = move_pose(pa, q, t), move_pose(pb, q, t)
    d = {"id": f"{c['id']}:{want}{':' + variant if variant else ''}", "a": a, "pa": pa, "b": b, "pb": pb, "want": want}
    if want == "manifold" and c.get("margin") is not None:
        d["margin"] = c["margin"]
    return json.dumps(d)

def lines_of(c):
    out = []
    for w in c["wants"]:
        out.append(qline(c, w))
        if w == "manifold" and c.get("variants"):
            out.append(qline(c, w, "swap")); out.append(qline(c, w, "move"))
    return out

def run_tool(cases, chunk=1500):
    out, problems = {}, []
    lines = [l for c in cases for l in lines_of(c)]
    for k in range(0, len(lines), chunk):
        inp = "\n".join(lines[k:k + chunk]) + "\n"
        p = __import__("subprocess").run(["timeout", "300", TOOL, "query"], input=inp, capture_output=True, text=True)
        if p.returncode != 0:
            problems.append(f"chunk {k}: rc={p.returncode} stderr={p.stderr[:300]}")
        got = 0
        for l in p.stdout.splitlines():
            try:
                a = json.loads(l)
            except Exception:
                problems.append(f"unparseable: {l[:200]}"); continue
            out[a["id"]] = a; got += 1
        if got != len(lines[k:k + chunk]):
            problems.append(f"chunk {k}: {got} answers for {len(lines[k:k+chunk])} lines")
    return out, problems

def has_nan(a):
    s = json.dumps(a)
    return "NaN" in s or "Infinity" in s

def signed_depth_in(s, p, x, hint, tol=None):
    """min over unit u of h(u) - u.x: > 0 inside (distance to the boundary), < 0 outside (-distance).
    The sampled value is an upper bound; a point that seems inside by more than tol is confirmed by a
    closed form (exact.py), the hull's face planes (polytopes) or a denser search."""
    F = member_fn(s, p, x)
    v, u = minimize(F, ngrid=4000, nstarts=4, extra=[hint] if hint is not None else [])
    if tol is not None and v > tol:
        from exact import signed_distance, poly_sd_inside
        d = signed_distance(s, p, x)
        if d is not None: return -d
        if s["type"] == "polytope":
            d, viol = poly_sd_inside(s["points"], p, x)
            return -d
        v2, u2 = minimize(F, ngrid=100000, nstarts=16, extra=[hint] if hint is not None else [])
        v = min(v, v2)
    return v

def supp(s, p, n):
    t, R = pose_of(p)
    return float(n @ t + support_local(s, (n @ R)[None, :])[0])

def check_one(args):
    c, ans = args
    a, pa, b, pb = c["a"], c["pa"], c["b"], c["pb"]
    size = bounding_radius(a) + bounding_radius(b)
    T = max(np.max(np.abs(pa.get("t", [0]))), np.max(np.abs(pb.get("t", [0]))))
    tol = 1e-9 * size
    tol_far = tol + 16 * EPS * T
    F = pair_fn(a, pa, b, pb)
    extra = [x["normal"] for x in ans.values() if x and "normal" in x and x.get("status") != "error"]
    s_or, u_or = minimize(F, extra=extra[:3])
    r = {"id": c["id"], "cat": c["cat"], "size": size, "T": float(T), "tol": tol, "tol_far": tol_far,
         "s_oracle": s_or, "issues": [], "errs": {}}
    def issue(kind, want, err, extra=None):
        r["issues"].append({"kind": kind, "want": want, "err": err, "rel": err / size, "far_ok": bool(err <= tol_far), **(extra or {})})
    def err(name, e):
        r["errs"][name] = max(r["errs"].get(name, 0.0), float(e) / size)
    for want in ("contact", "intersect", "distance", "manifold"):
        if want not in c["wants"]: continue
        x = ans.get(want)
        if x is None: issue("missing", want, float("inf")); continue
        if has_nan(x): issue("nan", want, float("inf"))
        if x.get("status") != "ok":
            issue("status:" + str(x.get("status")), want, 0.0, {"error": x.get("error")})
            if x.get("status") == "error": continue
        it = x.get("intersect")
        if it is True and s_or < -tol: issue("verdict_true_but_separated", want, -s_or)
        if it is False and s_or > tol: issue("verdict_false_but_overlap", want, s_or)
        if want == "intersect": continue
        if want == "distance" and it: continue
        st = x["depth"] if it else -x["distance"]
        if want != "distance" and it and x.get("distance") != 0: issue("distance_nonzero_when_intersecting", want, abs(x["distance"]))
        if st - s_or > tol_far: issue("value_too_high", want, st - s_or, {"s_tool": st})
        if "normal" not in x: issue("no_normal", want, 0.0); continue
        n = np.array(x["normal"], float)
        if abs(np.linalg.norm(n) - 1) > 1e-12: issue("normal_not_unit", want, abs(np.linalg.norm(n) - 1) * size)
        n = n / np.linalg.norm(n)
        hn = float(F(n[None, :])[0])
        err("normal_value_" + want, abs(hn - st))
        if abs(hn - st) > tol_far: issue("normal_value_mismatch", want, abs(hn - st), {"h_at_normal": hn, "s_tool": st})
        if hn < s_or: r["s_oracle"] = s_or = hn
        err("value_" + want, abs(st - s_or))
        if st - s_or < -tol_far: issue("value_too_low", want, s_or - st, {"s_tool": st})
        if want == "manifold": continue
        if "point_a" in x and "point_b" in x:
            P, Q = np.array(x["point_a"]), np.array(x["point_b"])
            va = -signed_depth_in(a, pa, P, n); vb = -signed_depth_in(b, pb, Q, -n)
            err("witness_outside_" + want, max(va, vb, 0))
            if va > tol_far: issue("point_a_outside_A", want, va)
            if vb > tol_far: issue("point_b_outside_B", want, vb)
            expect = -x["depth"] * n if (want == "contact" and it) else x["distance"] * n
            rel = float(np.linalg.norm((Q - P) - expect))
            if rel > tol_far: issue("points_relation", want, rel)
        else:
            issue("no_points", want, 0.0)
    m = ans.get("manifold")
    if m is not None and m.get("status") != "error":
        check_manifold(c, m, ans, size, tol, tol_far, issue, err)
        for var in ("swap", "move"):
            v = ans.get("manifold:" + var)
            if v is None or v.get("status") == "error": continue
            cv = dict(c)
            if var == "swap":
                cv["a"], cv["pa"], cv["b"], cv["pb"] = c["b"], c["pb"], c["a"], c["pa"]
            else:
                q, t = motion_of(c["id"], c["cat"]); cv["pa"], cv["pb"] = move_pose(c["pa"], q, t), move_pose(c["pb"], q, t)
            Tv = max(np.max(np.abs(cv["pa"]["t"])), np.max(np.abs(cv["pb"]["t"])))
            def issue_v(kind, want, e, extra=None, var=var):
                if kind.startswith("manifold_value_differs") or kind.startswith("manifold_verdict_differs"): return
                issue(kind, want + ":" + var, e, extra)
            check_manifold(cv, v, {}, size, tol, tol + 16 * EPS * Tv, issue_v, lambda name, e: err(name + ":var", e), variants=False)
    return r

def mpoints(m):
    mf = m.get("manifold") or {}
    return mf.get("normal"), mf.get("points") or []

def check_manifold(c, m, ans, size, tol, tol_far, issue, err, variants=True):
    a, pa, b, pb = c["a"], c["pa"], c["b"], c["pb"]
    margin = c.get("margin") or 0.0
    nrm, pts = mpoints(m)
    it = m.get("intersect")
    dist = m.get("distance", 0.0)
    if it and not pts: issue("manifold_empty", "manifold", 0.0)
    if not it:
        if dist <= margin and not pts: issue("manifold_no_speculative_points", "manifold", dist, {"margin": margin})
        if dist > margin * (1 + 1e-12) and pts: issue("manifold_points_beyond_margin", "manifold", dist, {"margin": margin})
    if len(pts) > 4: issue("manifold_more_than_4", "manifold", float(len(pts)))
    con = ans.get("contact")
    if con and con.get("status") == "ok" and m.get("status") == "ok":
        if con.get("intersect") != it: issue("manifold_verdict_differs_from_contact", "manifold", 0.0)
        d1 = (con["depth"] if con.get("intersect") else -con["distance"]); d2 = (m["depth"] if it else -m["distance"])
        err("manifold_vs_contact_value", abs(d1 - d2))
        if abs(d1 - d2) > tol_far: issue("manifold_value_differs_from_contact", "manifold", abs(d1 - d2), {"contact": d1, "manifold": d2})
    if "expect_count" in c and m.get("status") == "ok":
        if len(pts) != c["expect_count"]:
            issue("manifold_count", "manifold", 0.0, {"got": len(pts), "expected": c["expect_count"], "rest": c.get("rest"), "tilt": c.get("tilt")})
    if not pts: return
    n = np.array(nrm, float)
    if "normal" in m and np.linalg.norm(n - np.array(m["normal"])) > 0: issue("manifold_normal_ne_answer_normal", "manifold", float(np.linalg.norm(n - np.array(m["normal"]))) * size)
    if abs(np.linalg.norm(n) - 1) > 1e-12: issue("manifold_normal_not_unit", "manifold", abs(np.linalg.norm(n) - 1) * size)
    n = n / np.linalg.norm(n)
    d0 = pts[0]["depth"]
    ref = m["depth"] if it else -dist
    err("manifold_first_depth", abs(d0 - ref))
    if abs(d0 - ref) > tol_far: issue("manifold_first_depth_ne_contact", "manifold", abs(d0 - ref), {"d0": d0, "ref": ref})
    if "point_a" in m and (m["point_a"] != pts[0]["point_a"] or m["point_b"] != pts[0]["point_b"]):
        issue("answer_points_ne_first_manifold_point", "manifold", float(np.linalg.norm(np.array(m["point_a"]) - pts[0]["point_a"])))
    hA = supp(a, pa, n); hB = supp(b, pb, -n)
    lo = -max(margin, 1e-12 * size)
    for k, p in enumerate(pts):
        P, Q, X = np.array(p["point_a"]), np.array(p["point_b"]), np.array(p["position"])
        dk = p["depth"]
        if dk > d0 + tol_far: issue("manifold_point_deeper_than_first", "manifold", dk - d0, {"k": k})
        if dk < lo - tol_far: issue("manifold_point_below_margin", "manifold", lo - dk, {"k": k, "depth": dk})
        if it and dk < 0 and False: pass
        rel = float(np.linalg.norm((Q - P) + dk * n)); err("manifold_pair_relation", rel)
        if rel > tol_far: issue("manifold_pair_relation", "manifold", rel, {"k": k})
        mid = float(np.linalg.norm(X - 0.5 * (P + Q)))
        if mid > tol_far: issue("manifold_position_not_midpoint", "manifold", mid, {"k": k})
        # on the surfaces: signed distance to the boundary ~ 0
        sa = signed_depth_in(a, pa, P, n, tol_far); sb = signed_depth_in(b, pb, Q, -n, tol_far)
        err("manifold_point_off_surface", max(abs(sa), abs(sb)))
        for nm, sv in (("a", sa), ("b", sb)):
            if sv < -tol_far: issue(f"manifold_point_{nm}_outside", "manifold", -sv, {"k": k})
            if sv > tol_far: issue(f"manifold_point_{nm}_inside", "manifold", sv, {"k": k})
        # along the normal: no point of A beyond its support plane
        ea = float(n @ P - hA); eb = float(-n @ Q - hB)
        if ea > tol_far: issue("manifold_point_a_beyond_support", "manifold", ea, {"k": k})
        if eb > tol_far: issue("manifold_point_b_beyond_support", "manifold", eb, {"k": k})
        if k == 0 and it:
            err("manifold_first_support", max(abs(ea), abs(eb)))
            if abs(ea) > tol_far or abs(eb) > tol_far: issue("manifold_first_not_at_support", "manifold", max(abs(ea), abs(eb)), {"ea": ea, "eb": eb})
    # variants
    for var in (("swap", "move") if variants else ()):
        v = ans.get("manifold:" + var)
        if v is None: continue
        if v.get("status") != m.get("status"): issue("variant_status_" + var, "manifold", 0.0, {"got": v.get("status")}); continue
        vn, vp = mpoints(v)
        if len(vp) != len(pts): issue("variant_count_" + var, "manifold", 0.0, {"orig": len(pts), "var": len(vp)}); continue
        if not vp: continue
        R = np.eye(3)
        if var == "swap":
            exp_n = -n; exp_pos = [np.array(p["position"]) for p in pts]
        else:
            q, t = motion_of(c["id"], c["cat"]); R = quat_to_R(q)
            exp_n = R @ n; exp_pos = [R @ np.array(p["position"]) + t for p in pts]
        dn = float(np.linalg.norm(np.array(vn) - exp_n)); err("variant_normal_angle_" + var, dn * size)
        # the variant's normal, mapped back, must be as good as the original's (a support-value test;
        # near touching the normal itself is ill-conditioned)
        nb = -np.array(vn) if var == "swap" else R.T @ np.array(vn)
        Fv = float(pair_fn(a, pa, b, pb)(nb[None, :] / np.linalg.norm(nb))[0])
        sv = v["depth"] if v.get("intersect") else -v["distance"]
        so = m["depth"] if m.get("intersect") else -m["distance"]
        err("variant_normal_value_" + var, abs(Fv - so))
        if abs(Fv - so) > tol_far or abs(sv - so) > tol_far: issue("variant_normal_value_" + var, "manifold", max(abs(Fv - so), abs(sv - so)), {"dn": dn})
        got = [np.array(p["position"]) for p in vp]
        worst = 0.0
        for k, e in enumerate(exp_pos):
            j = int(np.argmin([np.linalg.norm(gp - e) for gp in got]))
            dd = float(np.linalg.norm(got[j] - e)) + abs(vp[j]["depth"] - pts[k]["depth"])
            worst = max(worst, dd)
        err("variant_points_" + var, worst)
        if worst > tol_far + 32 * EPS * 10: issue("variant_points_" + var, "manifold", worst)

def main():
    cases = [json.loads(l) for l in open(sys.argv[1])]
    t0 = time.time()
    answers, problems = run_tool(cases)
    print(f"tool: {time.time()-t0:.1f}s, {len(answers)} answers, problems {problems[:5]}", file=sys.stderr)
    work = []
    for c in cases:
        keys = [w for w in c["wants"]] + (["manifold:swap", "manifold:move"] if c.get("variants") else [])
        work.append((c, {k: answers.get(f"{c['id']}:{k}") for k in keys}))
    t0 = time.time()
    with Pool(2) as pool, open(sys.argv[2], "w") as fo:
        for k, r in enumerate(pool.imap(check_one, work, chunksize=4)):
            fo.write(json.dumps(r) + "\n")
            if k % 500 == 0: print(f"checked {k} in {time.time()-t0:.0f}s", file=sys.stderr)
    json.dump({"problems": problems}, open(sys.argv[2] + ".meta", "w"))

if __name__ == "__main__":
    main()
