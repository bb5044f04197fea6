import json,subprocess,sys
from check import qline
from oracle import bounding_radius
f, ids = sys.argv[1], sys.argv[2:]
sys.argv = ['x']
cs={c['id']:c for c in map(json.loads,open(f))}
for i in ids:
    c=cs[i]
    print(i, c['cat'], {k: c[k] for k in c if k not in ('a','b','pa','pb','wants','id','cat')}, 'sizes', bounding_radius(c['a']), bounding_radius(c['b']))
    print(' A', json.dumps(c['a'])[:400]); print(' B', json.dumps(c['b'])[:400])
    for v in ('', 'swap'):
        out=subprocess.run(['../../../build/release/tools/mink/mink','query'],input=qline(c,'manifold',v),capture_output=True,text=True).stdout
        a=json.loads(out)
        print(' ', v or 'orig', 'int', a['intersect'], 'dist', a['distance'], 'depth', a['depth'], 'n', a['normal'], 'it', a['iterations'])
        for p in a['manifold']['points']: print('    ', p['position'], p['depth'])
