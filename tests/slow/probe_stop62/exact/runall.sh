#!/bin/bash
# usage: runall.sh name seed N
set -e
cd "$(dirname "$0")"
/usr/bin/python3 ${GEN:-gen.py} $2 $3 > $1.jsonl
/usr/bin/python3 -c "
import json,sys
sys.path.insert(0,'.')
from check import strip
with open('$1_q.jsonl','w') as f:
    for l in open('$1.jsonl'):
        c=json.loads(l)
        for o in (0,1):
            for w in ('contact','distance','intersect'):
                f.write(json.dumps(strip(c,o,w))+'\n')
"
nice -n 10 "${MINK:-../../../../build/release/tools/mink/mink}" query < $1_q.jsonl > $1_a.jsonl
nice -n 10 /usr/bin/python3 check.py $1.jsonl $1_a.jsonl $1_r.jsonl
