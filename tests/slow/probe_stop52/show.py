"""Prints one case's four answers against the construction.  usage: python3 show.py CASES ID..."""
import json, subprocess, sys
import numpy as np
from check import qline, WANTS, TOOL
from common import LD, ld, pair_fn, bounding_radius, signed_distance, h_world
cases = {json.loads(l)["id"]: json.loads(l) for l in open(sys.argv[1])}
for cid in sys.argv[2:]:
    c = cases[cid]; exp = c["exp"]
    size = bounding_radius(c["a"]) + bounding_radius(c["b"])
    print(cid, c["cat"], "size %.3g" % size, "gap %.3g" % exp["gap"], "unique", exp["unique"])
    print("  a:", json.dumps(c["a"])[:200]); print("  b:", json.dumps(c["b"])[:200])
    F = pair_fn(c["a"], c["pa"], c["b"], c["pb"], LD)
    lines = [qline(c, w, o) for w in WANTS for o in "os"]
    out = subprocess.run([TOOL, "query"], input="\n".join(json.dumps(l) for l in lines) + "\n", capture_output=True, text=True).stdout.splitlines()
    for l, o in zip(lines, out):
        x = json.loads(o); od = l["id"].split(":")[2]
        if "point_a" not in x: print("  ", l["id"], o[:200]); continue
        A, B = np.array(x["point_a"]), np.array(x["point_b"])
        onP, onC = (A, B) if od == "o" else (B, A)
        nP = np.array(x["normal"]) * (1 if od == "o" else -1)
        msg = f"  {l['id']:22s} it={x['intersect']} d={x['distance']:.3e} depth={x.get('depth',0):.3e} F(n)-F(nexp)={(float(F(ld(nP)[None,:])[0]) - float(F(ld(exp['n'])[None,:])[0]))/size:.1e}"
        if exp.get("e"):
            e, cc = np.array(exp["e"]), np.array(exp["c"])
            msg += f" |P-e|={np.linalg.norm(onP-e)/size:.2e} |C-c|={np.linalg.norm(onC-cc)/size:.2e} n.(P-e)={np.dot(exp['n'], onP-e)/size:.1e}"
        msg += f" sdP={signed_distance(c['a'], c['pa'], onP) or 0:.1e} sdC={signed_distance(c['b'], c['pb'], onC) or 0:.1e} it={x.get('iterations')}"
        from common import world_support
        sc, uq = world_support(c["b"], c["pb"], -nP)
        msg += f" |C-s_C(-n_tool)|={np.linalg.norm(onC - np.array(sc, float))/size:.2e}({'unique' if uq else 'not unique'}) angle={np.arccos(min(1, nP @ np.array(exp['n']))) if exp.get('n') else -1:.1e}"
        print(msg)
