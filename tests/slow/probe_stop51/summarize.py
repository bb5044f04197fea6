import json, sys, collections
res = [json.loads(l) for f in sys.argv[1:] for l in open(f)]
bycat = collections.defaultdict(list)
for r in res: bycat[r["cat"]].append(r)
kinds = collections.Counter(); ex = {}
for cat, rs in sorted(bycat.items()):
    errs = collections.defaultdict(float)
    for r in rs:
        for k, v in r["errs"].items(): errs[k] = max(errs[k], v)
    nbad = sum(1 for r in rs if r["issues"])
    print(f"{cat}: {len(rs)} cases, {nbad} with issues; worst rel: " + ", ".join(f"{k}={v:.1e}" for k, v in sorted(errs.items())))
    for r in rs:
        for i in r["issues"]:
            key = (cat, i["kind"], i["want"]); kinds[key] += 1
            if key not in ex or i["rel"] > ex[key][1]: ex[key] = (r["id"], i["rel"], {k: v for k, v in i.items() if k not in ("kind", "want", "err", "rel")})
print()
for k, n in sorted(kinds.items()): print(n, k, ex[k])
