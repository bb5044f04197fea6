"""Feeds failures.jsonl to `mink query` (the "why" field stripped: the protocol rejects unknown
fields) and prints each answer after its why.  usage: python3 run_failures.py [failures.jsonl]"""
import json, os, subprocess, sys
TOOL = os.environ.get("MINK", "../../../build/release/tools/mink/mink")
rows = [json.loads(l) for l in open(sys.argv[1] if len(sys.argv) > 1 else "failures.jsonl")]
qs = [{k: v for k, v in r.items() if k != "why"} for r in rows]
out = subprocess.run([TOOL, "query"], input="\n".join(json.dumps(q) for q in qs) + "\n", capture_output=True, text=True).stdout.split("\n")
for r, a in zip(rows, out):
    print(r["id"], "--", r["why"]); print("   ", a[:600])
