# Nearly parallel solids of revolution (cylinder, cone, capsule) penetrating: side by side, end to
# end, near-coaxial; tilts 1e-9..1e-2; 60 % of pairs 1e3..1e5 from the origin. Both orders.
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import R, hloc, bound, np, json
rng=np.random.default_rng(int(sys.argv[1])); N=int(sys.argv[2])
def qmul(a,b):
    w1,x1,y1,z1=a; w2,x2,y2,z2=b
    return np.array([w1*w2-x1*x2-y1*y2-z1*z2,w1*x2+x1*w2+y1*z2-z1*y2,w1*y2-x1*z2+y1*w2+z1*x2,w1*z2+x1*y2-y1*x2+z1*w2])
def qax(ax,ang):
    ax=np.asarray(ax,float); ax/=np.linalg.norm(ax); return np.r_[np.cos(ang/2),np.sin(ang/2)*ax]
def lu(a,b): return float(np.exp(rng.uniform(np.log(a),np.log(b))))
def shape():
    t=rng.choice(['cylinder','cylinder','cone','capsule'])
    r=lu(0.1,2); h=r*lu(0.05,10)
    return {'type':str(t),'radius':r,'half_height':h}
M=4000; i=np.arange(M)+0.5; phi=np.arccos(1-2*i/M); th=np.pi*(1+5**0.5)*i
G=np.stack([np.cos(th)*np.sin(phi),np.sin(th)*np.sin(phi),np.cos(phi)],1)
out=[]
k=0
while len(out)<2*N:
    A=shape(); B=shape(); q=rng.normal(size=4); qA=q/np.linalg.norm(q)
    ax=R(qA)@[0,0,1]; e1=R(qA)@[1,0,0]; e2=R(qA)@[0,1,0]
    tilt=lu(1e-9,1e-2); ph=rng.uniform(0,2*np.pi)
    qB=qmul(qax(np.cos(ph)*e1+np.sin(ph)*e2,tilt),qA)
    if rng.random()<0.2: qB=qmul(qB,qax(e1,np.pi))  # B upside down
    mode=rng.choice(['side','end','coax'])
    ps=rng.uniform(0,2*np.pi); d=np.cos(ps)*e1+np.sin(ps)*e2
    if mode=='side': off=rng.uniform(0.2,1.0)*(A['radius']+B['radius'])*d+rng.uniform(-1,1)*A['half_height']*ax
    elif mode=='end': off=rng.uniform(0,0.8)*min(A['radius'],B['radius'])*d+(A['half_height']+B['half_height'])*rng.uniform(0.5,1.05)*rng.choice([-1,1])*ax
    else: off=lu(1e-9,1e-2)*(A['radius']+B['radius'])*d+rng.uniform(-0.5,0.5)*A['half_height']*ax
    far=lu(1e3,1e5)*rng.normal(size=3)/np.sqrt(3) if rng.random()<0.6 else rng.normal(size=3)
    far=np.round(far,3); tB=far+off
    RA=R(qA); RB=R(qB); dd=far-tB
    vals=G@dd+hloc(A,G@RA)+hloc(B,-(G@RB))
    size=bound(A)+bound(B)
    if vals.min()<=1e-6*size: continue
    k+=1
    for swap in (0,1):
        if swap: a,pa,b,pb=B,{'t':list(tB),'q':list(qB)},A,{'t':list(far),'q':list(qA)}
        else: a,pa,b,pb=A,{'t':list(far),'q':list(qA)},B,{'t':list(tB),'q':list(qB)}
        out.append({'id':f'{mode}_{A["type"]}_{B["type"]}|{len(out)}','a':a,'pa':pa,'b':b,'pb':pb,'want':'contact'})
for l in out: print(json.dumps(l))
