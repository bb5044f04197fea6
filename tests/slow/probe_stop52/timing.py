"""Runs every query line of a case file through `mink query --timing` and lists the slow ones.
usage: python3 timing.py cases.jsonl [threshold_us=50]"""
import json, subprocess, sys, time
import numpy as np
from check import qline, WANTS, TOOL
cases = [json.loads(l) for l in open(sys.argv[1])]
thr = float(sys.argv[2]) if len(sys.argv) > 2 else 50.0
lines = [qline(c, w, o) for c in cases for w in WANTS for o in "os"]
t0 = time.time()
out = subprocess.run([TOOL, "query", "--timing"], input="\n".join(json.dumps(l) for l in lines) + "\n", capture_output=True, text=True).stdout.splitlines()
wall = time.time() - t0
us = []
byid = {l["id"]: l for l in lines}
cat = {c["id"]: c["cat"] for c in cases}
slow = []
for o in out:
    a = json.loads(o)
    if "us" in a:
        us.append(a["us"])
        if a["us"] > thr: slow.append((a["us"], a["id"], a.get("iterations"), a.get("status")))
us = np.array(us)
print(f"{len(lines)} lines, {wall:.1f}s wall with --timing; query time median {np.median(us):.2f} us, p99 {np.percentile(us, 99):.1f}, max {us.max():.1f}")
for s in sorted(slow, reverse=True)[:15]:
    print(f"  {s[0]:8.1f} us  {s[1]}  {cat[s[1].split(':')[0]]}  iterations={s[2]} status={s[3]}")
print(f"{len(slow)} lines over {thr} us")
