"""Worst error per category (fractions of the size) from check.py's results.
usage: python3 table.py [--by p|pf|c|regime|scale] results*.jsonl"""
import json, sys
import numpy as np
args = sys.argv[1:]
by = "pf"
if args and args[0] == "--by": by = args[1]; args = args[2:]
COLS = ["value", "normal", "witness", "struct_witness", "surface", "support_plane", "relation", "swap_value", "swap_points"]
def group(cat):
    pf, ck, reg, sc = cat.split("|")
    ck = ck.split("+")[0]
    if ck.startswith("tilted_") or ck.startswith("aligned_"): ck = ck.split("_")[0]
    f = pf.split(":")[1]
    cls = {"face": "face", "cap": "cap/base", "base": "cap/base", "edge": "edge", "corner": "corner",
           "side": "cyl side", "rim": pf.split(":")[0] + " rim", "slant": "cone slant", "apex": "cone apex",
           "random": "random (oracle)"}[f]
    return {"p": pf.split(":")[0], "pf": pf, "c": ck, "regime": reg, "scale": sc, "cls": cls}[by]
rows = {}
for fn in args:
    for l in open(fn):
        r = json.loads(l)
        g = rows.setdefault(group(r["cat"]), {"n": 0, "fail": 0, "status": 0, **{k: 0.0 for k in COLS}})
        g["n"] += 1
        g["fail"] += bool(r["issues"])
        g["status"] += len(r.get("status", []))
        for k in COLS: g[k] = max(g[k], r["errs"].get(k, 0.0))
print("| " + by + " | cases | failing | " + " | ".join(COLS) + " |")
print("|" + "---|" * (len(COLS) + 3))
for k in sorted(rows):
    g = rows[k]
    print(f"| {k} | {g['n']} | {g['fail']} | " + " | ".join(f"{g[c]:.1e}" for c in COLS) + " |")
