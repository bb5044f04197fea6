"""Targeted: cylinders, cones and coaxial sums of them standing on a box face, tilted 1e-10..1e-5 rad,
both argument orders. Measures the first manifold point's depth against the contact depth and each
point's closed-form distance to both surfaces (exact.py), relative to the size. usage: probe_rim.py SEED N"""
import json, subprocess, sys, numpy as np
from oracle import bounding_radius
from exact import signed_distance
from shapes import Gen, quat_to_R, qmul
g = Gen(int(sys.argv[1])); N = int(sys.argv[2]); rng = g.rng
TOOL = "../../../build/release/tools/mink/mink"
lines, meta = [], []
for i in range(N):
    A = {"type": "box", "half_extents": [g.U(1.5, 3), g.U(1.5, 3), g.U(0.2, 1)]}
    k = rng.integers(4)
    r, h = g.U(0.1, 0.8), g.U(0.05, 0.8)
    if k == 0: B = {"type": "cylinder", "radius": r, "half_height": h}; hb = h
    elif k == 1: B = {"type": "cone", "radius": r, "half_height": h}; hb = h
    elif k == 2:
        r2, h2 = g.U(0.05, 0.5), g.U(0.05, 0.5)
        B = {"type": "sum", "shapes": [{"type": "cylinder", "radius": r, "half_height": h}, {"type": "cylinder", "radius": r2, "half_height": h2}]}; hb = h + h2
    else:
        rr = g.U(0.01, 0.2); B = {"type": "rounded", "shape": {"type": "cylinder", "radius": r, "half_height": h}, "radius": rr}; hb = h + rr
    tilt = g.LU(1e-10, 1e-5)
    qa = g.rquat(); RA = quat_to_R(qa); tA = rng.normal(size=3)
    pen = g.LU(max(1e-7, 4 * tilt), 1e-2)
    tB = tA + RA @ np.array([g.U(-0.5, 0.5), g.U(-0.5, 0.5), A["half_extents"][2] + hb - pen])
    qb = qmul(qa, qmul(g.tilt_quat(tilt), g.axis_quat(g.U(0, 6.28), [0, 0, 1])))
    pa = {"t": [float(v) for v in tA], "q": qa}; pb = {"t": [float(v) for v in tB], "q": qb}
    size = bounding_radius(A) + bounding_radius(B)
    for o in ("ab", "ba"):
        q = {"id": f"{i}:{o}", "a": A, "pa": pa, "b": B, "pb": pb, "want": "manifold"} if o == "ab" else {"id": f"{i}:{o}", "a": B, "pa": pb, "b": A, "pb": pa, "want": "manifold"}
        lines.append(json.dumps(q)); meta.append((q, size, tilt, B["type"] if B["type"] != "sum" else "sum_cyl_cyl"))
out = subprocess.run(["timeout", "300", TOOL, "query"], input="\n".join(lines) + "\n", capture_output=True, text=True).stdout.split("\n")
ans = [json.loads(l) for l in out if l.strip()]
worst = {}
rows = []
for (q, size, tilt, kind), a in zip(meta, ans):
    pts = a["manifold"]["points"]
    short = (a["depth"] - pts[0]["depth"]) / size
    off = max(max(abs(signed_distance(q["a"], q["pa"], p["point_a"]) or 0), abs(signed_distance(q["b"], q["pb"], p["point_b"]) or 0)) for p in pts) / size
    w = worst.setdefault(kind, [0, 0, len(pts), len(pts)])
    w[0] = max(w[0], short); w[1] = max(w[1], off); w[2] = min(w[2], len(pts)); w[3] = max(w[3], len(pts))
    if short > 1e-9 or off > 1e-9 or a["status"] != "ok": rows.append({"short": short, "off": off, "tilt": tilt, "kind": kind, "n": len(pts), "status": a["status"], "line": json.dumps(q)})
for k, w in worst.items(): print(k, "first-depth shortfall/size %.2e, off-surface/size %.2e, points %d..%d" % tuple(w))
print("bad", len(rows))
with open(f"rim_{sys.argv[1]}.jsonl", "w") as f:
    for r in sorted(rows, key=lambda r: -max(r["short"], r["off"])): f.write(json.dumps(r) + "\n")
