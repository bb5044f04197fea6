# The oracle: the least support value of A - B over 20,000 directions (a Fibonacci sphere) and
# the axes both ways, refined by Nelder-Mead from the best three. argv[1]: lines, argv[2]: output.
import os, sys; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import *
M=20000; i=np.arange(M)+0.5; phi=np.arccos(1-2*i/M); th=np.pi*(1+5**0.5)*i
G=np.stack([np.cos(th)*np.sin(phi),np.sin(th)*np.sin(phi),np.cos(phi)],1)
inp=[json.loads(l) for l in open(sys.argv[1])]
out=[]
for L in inp:
    H=Hfun(L); vals=H(G); best=np.inf
    # the axes' directions too (kinks of the caps)
    cands=[G[j] for j in np.argsort(vals)[:3]]
    for s,p in (('a','pa'),('b','pb')):
        ax=R(np.array(L[p]['q']))@[0,0,1]; cands+= [ax,-ax]
    for n0 in cands: best=min(best,H(n0)[0]); 
    for n0 in cands[:3]: best=refine(H,n0,best)
    out.append(best)
json.dump(out,open(sys.argv[2],'w'))
