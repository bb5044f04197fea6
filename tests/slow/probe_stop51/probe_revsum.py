"""Targeted: manifold points of sums of solids of revolution (cone/cylinder/capsule + capsule) and
rounded cones/cylinders against boxes, both argument orders; every point checked with the closed-form
signed distance (exact.py).  usage: probe_revsum.py SEED N"""
import json, subprocess, sys, numpy as np
from oracle import bounding_radius, minimize, pair_fn
from exact import signed_distance
from shapes import Gen
g = Gen(int(sys.argv[1])); N = int(sys.argv[2]); rng = g.rng
TOOL = "../../../build/release/tools/mink/mink"
def rev(L):
    k = rng.integers(3); t = ["cone", "cylinder", "capsule"][k]
    return {"type": t, "radius": L * g.U(0.1, 1), "half_height": L * g.U(0.05, 1)}
cases = []
for i in range(N):
    k = rng.integers(4)
    if k == 0: B = {"type": "sum", "shapes": [rev(0.6), {"type": "capsule", "radius": g.U(0, 0.3) * (rng.uniform() < 0.8), "half_height": g.U(0.01, 0.3)}]}
    elif k == 1: B = {"type": "sum", "shapes": [rev(0.6), rev(0.6)]}
    elif k == 2: B = {"type": "rounded", "shape": rev(1.0), "radius": g.LU(1e-3, 0.3)}
    else: B = {"type": "sum", "shapes": [rev(0.6), {"type": "sphere", "radius": g.U(0.01, 0.3)}]}
    A = g.basic(1.0, ["box", "sphere", "capsule", "triangle", "segment"]) if rng.uniform() < 0.5 else {"type": "box", "half_extents": [g.U(0.2, 1) for _ in range(3)]}
    pa = {"t": [float(v) for v in rng.normal(size=3)], "q": g.rquat()}
    d = rng.normal(size=3); d /= np.linalg.norm(d)
    size = bounding_radius(A) + bounding_radius(B)
    pb = {"t": [float(v) for v in np.array(pa["t"]) + d * g.U(0.3, 1) * size], "q": g.rquat()}
    s, u = minimize(pair_fn(A, pa, B, pb), ngrid=6000, nstarts=3)
    tgt = size * g.LU(1e-5, 0.1)
    pb["t"] = [float(v) for v in np.array(pb["t"]) + (s - tgt) * u]
    cases.append((A, pa, B, pb, size))
lines = []
for i, (A, pa, B, pb, size) in enumerate(cases):
    lines.append(json.dumps({"id": f"{i}:ab", "a": A, "pa": pa, "b": B, "pb": pb, "want": "manifold"}))
    lines.append(json.dumps({"id": f"{i}:ba", "a": B, "pa": pb, "b": A, "pb": pa, "want": "manifold"}))
out = subprocess.run(["timeout", "300", TOOL, "query"], input="\n".join(lines) + "\n", capture_output=True, text=True).stdout.split("\n")
ans = {}
for l in out:
    if l.strip(): a = json.loads(l); ans[a["id"]] = a
worst = {}
bad = []
for i, (A, pa, B, pb, size) in enumerate(cases):
    counts = {}
    for o in ("ab", "ba"):
        a = ans[f"{i}:{o}"]
        SA, PA, SB, PB = (A, pa, B, pb) if o == "ab" else (B, pb, A, pa)
        pts = a["manifold"]["points"]; counts[o] = len(pts)
        for k, p in enumerate(pts):
            da = signed_distance(SA, PA, p["point_a"]); db = signed_distance(SB, PB, p["point_b"])
            e = max(abs(da), abs(db)) / size
            worst[o] = max(worst.get(o, 0), e)
            if e > 1e-9: bad.append({"i": i, "order": o, "k": k, "off_a": da / size, "off_b": db / size, "depth": p["depth"], "n": len(pts), "line": lines[2 * i + (o == "ba")]})
    if counts["ab"] != counts["ba"]: bad.append({"i": i, "asym": counts, "line": lines[2 * i]})
print("worst off-surface / size:", worst, "bad:", sum(1 for b in bad if "k" in b), "asym:", sum(1 for b in bad if "asym" in b))
with open(f"revsum_{sys.argv[1]}.jsonl", "w") as f:
    for b in bad: f.write(json.dumps(b) + "\n")
