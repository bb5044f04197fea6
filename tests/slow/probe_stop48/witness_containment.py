#!/usr/bin/env python3
"""How far the witness points of cylinder and cone pairs lie outside their shapes.
usage: mink query < LINES > ANSWERS; witness_containment.py LINES ANSWERS
prints each line (1-based) whose point is off its shape by more than 1e-10 of the size."""
import json, sys, math
def R(q):
    w,x,y,z=q; n=math.sqrt(w*w+x*x+y*y+z*z); w,x,y,z=w/n,x/n,y/n,z/n
    return [[1-2*(y*y+z*z),2*(x*y-w*z),2*(x*z+w*y)],[2*(x*y+w*z),1-2*(x*x+z*z),2*(y*z-w*x)],[2*(x*z-w*y),2*(y*z+w*x),1-2*(x*x+y*y)]]
def outside(shape, pose, p):
    t=pose.get('t',[0,0,0]); r=R(pose.get('q',[1,0,0,0]))
    d=[p[i]-t[i] for i in range(3)]
    l=[sum(r[j][i]*d[j] for j in range(3)) for i in range(3)]
    h=shape['half_height']; rad=shape['radius']
    if shape['type']=='cone': rad=rad*(h-l[2])/(2*h)
    return max(math.hypot(l[0],l[1])-rad, abs(l[2])-h, 0)
qs=[json.loads(l) for l in open(sys.argv[1])]
ans=[json.loads(l) for l in open(sys.argv[2])]
for i,(q,a) in enumerate(zip(qs,ans)):
    if q['a']['type'] not in ('cone','cylinder') or q['b']['type'] not in ('cone','cylinder') or 'point_a' not in a: continue
    oa=outside(q['a'],q.get('pa',{}),a['point_a']); ob=outside(q['b'],q.get('pb',{}),a['point_b'])
    size=math.hypot(q['a']['radius'],q['a']['half_height'])+math.hypot(q['b']['radius'],q['b']['half_height'])
    m=max(oa,ob)/size
    if m>1e-10: print(i+1, a['status'], f"{oa:.2e} {ob:.2e} rel {m:.2e}")
