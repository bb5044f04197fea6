import json, os, sys, subprocess, math, time, numpy as np
from multiprocessing import Pool
from oracle import bounding_radius, minimize, pair_fn, member_fn

TOOL = os.environ.get("MINK", "build/release/tools/mink/mink")
EPS = 2.2e-16

def qline(c, want):
    return json.dumps({"id": f"{c['id']}:{want}", "a": c["a"], "pa": c["pa"], "b": c["b"], "pb": c["pb"], "want": want})

def run_tool(cases, chunk=2000):
    out = {}
    problems = []
    lines = [qline(c, w) for c in cases for w in ("contact", "intersect", "distance") + (("manifold",) if c.get("manifold") else ())]
    for k in range(0, len(lines), chunk):
        inp = "\n".join(lines[k:k+chunk]) + "\n"
        t0 = time.time()
        try:
            p = subprocess.run(["timeout", "120", TOOL, "query"], input=inp, capture_output=True, text=True)
        except Exception as e:
            problems.append(f"chunk {k}: {e}"); continue
        if p.returncode != 0:
            problems.append(f"chunk {k}: rc={p.returncode} stderr={p.stderr[:300]}")
        for l in p.stdout.splitlines():
            try:
                a = json.loads(l)
            except Exception:
                problems.append(f"unparseable: {l[:200]}"); continue
            out[a["id"]] = a
        print(f"chunk {k}: {time.time()-t0:.2f}s", file=sys.stderr)
    return out, problems

def has_nan(a):
    s = json.dumps(a)
    return "NaN" in s or "Infinity" in s

def member_viol(s, p, x, hint, size):
    F = member_fn(s, p, x)
    v, u = minimize(F, ngrid=6000, nstarts=4, extra=[hint] if hint is not None else [])
    return max(0.0, -v)

def check_one(args):
    c, ans = args
    a, pa, b, pb = c["a"], c["pa"], c["b"], c["pb"]
    size = bounding_radius(a) + bounding_radius(b)
    T = max(np.max(np.abs(pa["t"])), np.max(np.abs(pb["t"])))
    tol = 1e-9 * size
    tol_far = tol + 8 * EPS * T
    F = pair_fn(a, pa, b, pb)
    con, inter, dist = ans.get("contact"), ans.get("intersect"), ans.get("distance")
    extra = []
    for x in (con, dist):
        if x and "normal" in x: extra.append(x["normal"])
    s_or, u_or = minimize(F, extra=extra)
    r = {"id": c["id"], "cat": c["cat"], "size": size, "T": float(T), "tol": tol, "tol_far": tol_far,
         "s_oracle": s_or, "u_oracle": u_or.tolist(), "issues": []}
    def issue(kind, want, err, extra=None):
        r["issues"].append({"kind": kind, "want": want, "err": err, "rel": err / (size if size > 0 else 1.0), "far_ok": bool(err <= tol_far),
                            **(extra or {})})
    for want, x in (("contact", con), ("intersect", inter), ("distance", dist)):
        if x is None:
            issue("missing", want, float("inf")); continue
        if has_nan(x): issue("nan", want, float("inf"))
        if x.get("status") != "ok":
            issue("status:" + str(x.get("status")), want, 0.0, {"error": x.get("error"), "err_s": None})
            if x.get("status") == "error": continue
        it = x.get("intersect")
        # verdict
        if it is True and s_or < -tol:
            issue("verdict_true_but_separated", want, -s_or)
        if it is False and s_or > tol:
            issue("verdict_false_but_overlap", want, s_or)
        if want == "intersect": continue
        if want == "contact":
            st = x["depth"] if it else -x["distance"]
        else:
            if it: continue  # distance query: nothing more when intersecting
            st = -x["distance"]
        r[want + "_s"] = st
        # value: tool higher than the oracle's min is certified wrong
        if st - s_or > tol:
            issue("value_too_high", want, st - s_or, {"s_tool": st})
        if "normal" not in x:
            issue("no_normal", want, 0.0); continue
        n = np.array(x["normal"], float)
        if abs(np.linalg.norm(n) - 1) > 1e-12:
            issue("normal_not_unit", want, abs(np.linalg.norm(n) - 1) * size)
        hn = float(F(n[None, :] / np.linalg.norm(n))[0])
        if abs(hn - st) > tol:
            issue("normal_value_mismatch", want, abs(hn - st), {"h_at_normal": hn, "s_tool": st})
        if hn < s_or: r["s_oracle"] = s_or = hn  # (extra start already includes it)
        if st - s_or < -tol:
            issue("value_too_low", want, s_or - st, {"s_tool": st})
        # witness points
        if "point_a" in x and "point_b" in x:
            P, Q = np.array(x["point_a"]), np.array(x["point_b"])
            va = member_viol(a, pa, P, n, size)
            vb = member_viol(b, pb, Q, -n, size)
            if va > tol: issue("point_a_outside_A", want, va)
            if vb > tol: issue("point_b_outside_B", want, vb)
            expect = -x["depth"] * n if (want == "contact" and it) else x["distance"] * n
            rel = float(np.linalg.norm((Q - P) - expect))
            if rel > tol: issue("points_relation", want, rel)
        else:
            issue("no_points", want, 0.0)
    m = ans.get("manifold")
    if m is not None:
        if has_nan(m): issue("nan", "manifold", float("inf"))
        if m.get("status") != "ok": issue("status:" + str(m.get("status")), "manifold", 0.0)
        if m.get("intersect") != (con or {}).get("intersect"): issue("manifold_verdict_differs", "manifold", abs(s_or))
        mf = m.get("manifold")
        if m.get("intersect") and m.get("status") == "ok":
            if not mf or not mf.get("points"): issue("manifold_empty", "manifold", 0.0)
            else:
                mn = np.array(mf["normal"])
                if con and "normal" in con and np.linalg.norm(mn - np.array(con["normal"])) > 1e-9:
                    issue("manifold_normal_differs_from_contact", "manifold", float(np.linalg.norm(mn - np.array(con["normal"]))) * size)
                d0 = mf["points"][0]["depth"]
                if abs(d0 - m["depth"]) > tol: issue("manifold_first_depth_ne_depth", "manifold", abs(d0 - m["depth"]), {"d0": d0, "depth": m["depth"]})
                for k, pt in enumerate(mf["points"]):
                    if pt["depth"] > m["depth"] + tol: issue("manifold_point_deeper_than_depth", "manifold", pt["depth"] - m["depth"], {"k": k})
                    P, Q = np.array(pt["point_a"]), np.array(pt["point_b"])
                    rel = float(np.linalg.norm((Q - P) + pt["depth"] * mn))
                    if rel > tol: issue("manifold_points_relation", "manifold", rel, {"k": k})
                    va = member_viol(a, pa, P, mn, size); vb = member_viol(b, pb, Q, -mn, size)
                    if va > tol: issue("manifold_point_a_outside_A", "manifold", va, {"k": k})
                    if vb > tol: issue("manifold_point_b_outside_B", "manifold", vb, {"k": k})
                    # point_a should be on A's surface: its support value along mn equals h_A(mn)
                    from oracle import pose_of, support_local
                    tA_, RA_ = pose_of(pa); hA = float(mn @ tA_ + support_local(a, (mn @ RA_)[None, :])[0])
                    tB_, RB_ = pose_of(pb); hB = float(-mn @ tB_ + support_local(b, (-mn @ RB_)[None, :])[0])
                    # depth of a manifold point never exceeds the penetration along mn
                    if pt["depth"] > hA + hB + tol: issue("manifold_depth_exceeds_support_gap", "manifold", pt["depth"] - hA - hB, {"k": k})
    # consistency of verdicts across wants
    vs = {w: ans[w].get("intersect") for w in ("contact", "intersect", "distance") if ans.get(w) and "intersect" in ans[w]}
    if len(set(vs.values())) > 1 and abs(s_or) > tol:
        issue("verdict_inconsistent", "all", abs(s_or), {"verdicts": vs})
    return r

def main():
    cases = [json.loads(l) for l in open(sys.argv[1])]
    outname = sys.argv[2]
    t0 = time.time()
    answers, problems = run_tool(cases)
    print(f"tool: {time.time()-t0:.1f}s, {len(answers)} answers, problems {problems}", file=sys.stderr)
    work = []
    for c in cases:
        work.append((c, {w: answers.get(f"{c['id']}:{w}") for w in ("contact", "intersect", "distance", "manifold")}))
    t0 = time.time()
    with Pool(2) as pool, open(outname, "w") as fo:
        for k, r in enumerate(pool.imap(check_one, work, chunksize=4)):
            fo.write(json.dumps(r) + "\n")
            if k % 200 == 0: print(f"checked {k} in {time.time()-t0:.0f}s", file=sys.stderr)
    json.dump({"problems": problems}, open(outname + ".meta", "w"))

if __name__ == "__main__":
    main()
