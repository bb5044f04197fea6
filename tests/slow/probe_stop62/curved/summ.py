import json, sys, collections
cases = {}
for cf in sys.argv[1::2]:
    for l in open(cf):
        c = json.loads(l); cases[c["id"]] = c
for rf in sys.argv[2::2]:
    for l in open(rf):
        r = json.loads(l)
        if not r["issues"]: continue
        c = cases[r["id"]]
        iss = collections.defaultdict(list)
        for i in r["issues"]: iss[i["kind"]].append(i)
        s = "; ".join(f"{k} x{len(v)} max {max(i['rel'] for i in v):.1e}" for k, v in iss.items())
        print(r["id"], c["cls"], c["mode"], r["ref"], c["cat"], f"gap/size={r['gap']/r['size']:.1e}", "tilt", c.get("tilt"), "ang", c.get("angle"), "|", s)
