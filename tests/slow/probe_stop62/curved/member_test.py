"""independent check that e is in A and c in B (support-function search: min_u h(u) - u.x >= 0)"""
import json, sys
sys.path.insert(0, "../../probe_stop52")
from common import *
worst = (0, None); k = 0
for l in open(sys.argv[1]):
    c = json.loads(l)
    if c["exp"]["n"] is None: continue
    if not any(s["type"] == "sum" for s in (c["a"], c["b"])): continue
    k += 1
    if k > int(sys.argv[2]): break
    size = bounding_radius(c["a"]) + bounding_radius(c["b"])
    for s, p, x, hint in ((c["a"], c["pa"], c["exp"]["e"], c["exp"]["n"]), (c["b"], c["pb"], c["exp"]["c"], [-v for v in c["exp"]["n"]])):
        F = member_fn(s, p, ld(x), LD)
        v, u = minimize(member_fn(s, p, np.array(x)), ngrid=4000, nstarts=4, extra=[hint])
        v2, u2 = refine(F, u, r0=1e-4)
        out = max(0.0, -float(v2)) / size   # distance outside
        if out > worst[0]: worst = (out, c["id"])
print(k, "sum cases; worst outside distance / size", worst)
