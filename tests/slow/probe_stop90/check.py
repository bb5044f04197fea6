# Checks `mink query` answers (argv[2]) to the lines argv[1] against the oracle files argv[3:]
# (oracle.py, in the order of the lines): the depth against the least support value (the oracle
# and the support value along the answer's normal), the normal's optimality, point_b - point_a =
# -depth normal and both points on their shapes, each at 1e-9 of the size; by family.
import os, sys; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import *
import collections
inp=[json.loads(l) for l in open(sys.argv[1])]
outs=[json.loads(l) for l in open(sys.argv[2])]
orc=sum((json.load(open(f)) for f in sys.argv[3:]), [])
T=1e-9
fam=collections.defaultdict(collections.Counter); its=collections.defaultdict(list); worst=collections.defaultdict(float)
for L,o,best in zip(inp,outs,orc):
    H=Hfun(L); A,B=L['a'],L['b']; size=bound(A)+bound(B)
    f=L['id'].split('|')[0]; fam[f]['n']+=1
    if o.get('status')!='ok' or not o.get('intersect'): fam[f]['bad:'+str(o.get('status'))+str(o.get('intersect'))]+=1; continue
    n=np.array(o['normal']); dep=o['depth']; pa=np.array(o['point_a']); pb=np.array(o['point_b'])
    best=min(best,H(n/np.linalg.norm(n))[0])
    derr=abs(dep-best)/size; opt=abs(H(n/np.linalg.norm(n))[0]-dep)/size
    rel=np.linalg.norm(pb-pa+dep*n)/size
    RA=R(np.array(L['pa']['q'])); RB=R(np.array(L['pb']['q']))
    pin=max(outside(A,RA.T@(pa-np.array(L['pa']['t']))),outside(B,RB.T@(pb-np.array(L['pb']['t']))))/size
    its[f].append(o['iterations'])
    for k,v in (('depth',derr),('opt',opt),('rel',rel),('pin',pin)):
        worst[f+':'+k]=max(worst[f+':'+k],v)
        if v>T: fam[f][k]+=1
for f in sorted(fam):
    v=sorted(its[f]); print(f'{f:26s}', dict(fam[f]), 'calls mean %.1f med %d max %d'%(sum(v)/len(v), v[len(v)//2], v[-1]) if v else '', ' worst d %.1e pin %.1e'%(worst[f+':depth'],worst[f+':pin']))
