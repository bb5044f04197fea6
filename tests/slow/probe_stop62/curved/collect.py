"""failing lines -> failures.jsonl (tool faults, confirmed by the exact construction) and
unconfirmed.jsonl (only the structured oracle objects: oracle doubts). usage: collect.py cases res [cases res ...]"""
import json, os, sys, subprocess, collections
import numpy as np
sys.path.insert(0, "../../probe_stop52"); sys.path.insert(0, ".")
from check import qline  # ../../probe_stop52/check.py
args = sys.argv[1:]
fo, fu = open("failures.jsonl", "w"), open("unconfirmed.jsonl", "w")
summary = collections.defaultdict(lambda: {"lines": 0, "cases": set(), "worst": 0.0, "wid": ""})
todo = []
for cf, rf in zip(args[0::2], args[1::2]):
    cases = {json.loads(l)["id"]: json.loads(l) for l in open(cf)}
    for l in open(rf):
        r = json.loads(l)
        if not r["issues"]: continue
        c = cases[r["id"]]
        by = collections.defaultdict(list)
        for i in r["issues"]:
            lid = i["line"]
            if lid.count(":") == 1:  # swap issue: attach to both orders
                by[lid + ":o"].append(i); by[lid + ":s"].append(i)
            else: by[lid].append(i)
        for lid, iss in by.items():
            _, w, o = lid.split(":")
            todo.append((c, r, w, o, iss))
lines = [qline(c, w, o) for c, r, w, o, iss in todo]
p = subprocess.run([os.environ.get("MINK", "../../../../build/release/tools/mink/mink"), "query"], input="".join(json.dumps(x) + "\n" for x in lines), capture_output=True, text=True)
answers = [json.loads(x) for x in p.stdout.splitlines()]
for (c, r, w, o, iss), q, a in zip(todo, lines, answers):
    kinds = {i["kind"] for i in iss}
    exp = c["exp"]
    ang = None
    if exp["n"] and "normal" in a:
        nt = np.array(a["normal"]) * (1 if o == "o" else -1)
        ang = float(np.linalg.norm(np.cross(nt, np.array(exp["n"]))))
    confirmed = bool(kinds - {"struct_witness", "swap_points"}) or (kinds == {"swap_points"} and exp["unique"])
    if c["mode"] == "tilt_search" or not exp["n"]: confirmed = confirmed and bool(kinds & {"value", "normal", "status", "ref_beaten"})
    if not confirmed: cls = "unconfirmed(struct oracle only)"
    elif kinds & {"value", "normal", "status", "missing", "verdict_intersect_but_apart", "verdict_apart_but_overlap"}: cls = "V:" + "+".join(sorted(kinds))
    elif c["mode"] == "tilt_exact": cls = "W-tilted-flat"
    elif ang is not None and ang < 1e-8: cls = "W-flat (normal exact)"
    else: cls = "W-kink (normal off)"
    worst = max(i["rel"] for i in iss if i["kind"] != "struct_witness") if confirmed else max(i["rel"] for i in iss)
    why = (f"{cls}: [{c['cls']} {c['mode']} {c['cat']}, size {r['size']:.4g}, gap/size {r['gap'] / r['size']:.2g}, "
           f"tilt {c['tilt']}, line angle {c['angle']}, reference {r['ref']}] tool normal vs n: "
           + (f"{ang:.2e} rad; " if ang is not None else "n/a; ")
           + "; ".join(f"{i['kind']} {i['rel']:.2e} of size" + "".join(
               f", {k}={v:.3g}" if isinstance(v, float) else f", {k}={v}" for k, v in i.items() if k not in ("kind", "line", "rel")) for i in iss)
           + f"; value and F(normal) within {max(r['errs'].get('value', 0), r['errs'].get('normal', 0)):.1e} of size")
    q = dict(q); q["why"] = why
    (fo if confirmed else fu).write(json.dumps(q) + "\n")
    s = summary[cls]; s["lines"] += 1; s["cases"].add(c["id"])
    if worst > s["worst"]: s["worst"], s["wid"] = worst, q["id"]
for k, s in sorted(summary.items()):
    print(f"{k}: {s['lines']} lines in {len(s['cases'])} cases, worst {s['worst']:.2e} of size ({s['wid']})")
