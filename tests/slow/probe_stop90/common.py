# Shared by oracle.py and check.py: support values of cylinders, cones and capsules, written
# from their equations, and a rough outside test for the points.
import numpy as np, json
from scipy.optimize import minimize
def R(q):
    w,x,y,z=q
    return np.array([[1-2*(y*y+z*z),2*(x*y-w*z),2*(x*z+w*y)],[2*(x*y+w*z),1-2*(x*x+z*z),2*(y*z-w*x)],[2*(x*z-w*y),2*(y*z+w*x),1-2*(x*x+y*y)]])
def hloc(s,n):
    t=s['type']; r=s['radius']; h=s['half_height']; a=np.hypot(n[...,0],n[...,1]); z=n[...,2]
    if t=='cylinder': return r*a+h*np.abs(z)
    if t=='cone': return np.maximum(h*z, r*a-h*z)
    if t=='capsule': return h*np.abs(z)+r
def bound(s): return s['half_height']+s['radius'] if s['type']=='capsule' else float(np.hypot(s['radius'],s['half_height']))
def outside(s,p):
    t=s['type']; r=s['radius']; h=s['half_height']; a=np.hypot(p[0],p[1])
    if t=='cylinder': return max(a-r,abs(p[2])-h)
    if t=='capsule': z=np.clip(p[2],-h,h); return np.linalg.norm(p-[0,0,z])-r
    if t=='cone':
        # distance-ish: max of plane violations (base plane, slant)
        L=np.hypot(r,2*h); slant=(a*2*h + r*(p[2]-h))/L
        return max(-h-p[2], slant)
def Hfun(L):
    A,B=L['a'],L['b']; tA=np.array(L['pa']['t']); tB=np.array(L['pb']['t'])
    RA=R(np.array(L['pa']['q'])); RB=R(np.array(L['pb']['q'])); d=tA-tB
    def H(N): N=np.atleast_2d(N); return N@d+hloc(A,N@RA)+hloc(B,-(N@RB))
    return H
def refine(H,n0,best):
    n0=n0/np.linalg.norm(n0); e1=np.cross(n0,[1,0,0] if abs(n0[0])<0.9 else [0,1,0]); e1/=np.linalg.norm(e1); e2=np.cross(n0,e1)
    f=lambda x: H((n0+x[0]*e1+x[1]*e2)/np.linalg.norm(n0+x[0]*e1+x[1]*e2))[0]
    for sc in (1e-2,1e-4,1e-6):
        r=minimize(f,[0,0],method='Nelder-Mead',options={'xatol':1e-15,'fatol':1e-18,'maxiter':3000,'initial_simplex':[[0,0],[sc,0],[0,sc]]})
        best=min(best,r.fun)
    return best
