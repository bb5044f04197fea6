import json, os, sys, subprocess
import numpy as np
sys.path.insert(0, "../../probe_stop52"); sys.path.insert(0, ".")
from common import *
from check import qline  # ../../probe_stop52/check.py
cf = sys.argv[1]
for spec in sys.argv[2:]:
    cid, w = spec.split(",")
    c = [json.loads(l) for l in open(cf) if json.loads(l)["id"] == cid][0]
    q = qline(c, w, "o")
    a = json.loads(subprocess.run([os.environ.get("MINK", "../../../../build/release/tools/mink/mink"), "query"], input=json.dumps(q) + "\n", capture_output=True, text=True).stdout)
    exp = c["exp"]; size = bounding_radius(c["a"]) + bounding_radius(c["b"])
    print("###", cid, c["cls"], c["mode"], c["cat"], "tilt", c["tilt"], "size %.6g" % size)
    print("QUERY", json.dumps(q))
    print("TOOL ", json.dumps(a))
    nt = np.array(a["normal"]); n = np.array(exp["n"])
    print("EXPECTED gap %.17g normal %s point_a %s point_b %s" % (exp["gap"], exp["n"], exp["e"], exp["c"]))
    print("  normal angle %.2e rad; |point_a-e|/size %.2e; |point_b-c|/size %.2e; value err/size %.1e" % (
        np.linalg.norm(np.cross(nt, n)), np.linalg.norm(np.array(a["point_a"]) - exp["e"]) / size,
        np.linalg.norm(np.array(a["point_b"]) - exp["c"]) / size, abs((a.get("distance", 0) - a.get("depth", 0)) - exp["gap"]) / size))
