# Monte Carlo of the linear-time overlapping Allan estimator (AllanOffsets::Linear, docs/reference/metrics.md):
# full overlap vs offsets at a stride of 256 at m = 2^17, 2^18 on 300 white-noise and 300 random-walk
# records of 2^20 samples (seed 1). Needs numpy; about 15 s CPU.  python3 bench/io/allan_stride_mc.py
import numpy as np, sys
rng=np.random.default_rng(1)
n=1<<20; s=256
def avar_full(x,m):
    d=x[2*m:]-2*x[m:-m]+x[:-2*m]
    return np.mean((d/m)**2)/2
def avar_str(x,m):
    xs=x[::s]; q=m//s
    d=xs[2*q:]-2*xs[q:-q]+xs[:-2*q]
    return np.mean((d/m)**2)/2
for kind in ['white','rw']:
  res={m:([],[],[]) for m in [1<<17,1<<18]}
  for t in range(300):
    y=rng.standard_normal(n)
    if kind=='rw': y=np.cumsum(y)*1e-3
    y=y-y.mean()
    x=np.concatenate([[0],np.cumsum(y)])
    for m in res:
      a=np.sqrt(avar_full(x,m)); b=np.sqrt(avar_str(x,m))
      res[m][0].append(a); res[m][1].append(b); res[m][2].append(abs(b/a-1))
  for m,(a,b,r) in res.items():
    a=np.array(a);b=np.array(b);r=np.array(r)
    truth = 1/np.sqrt(m) if kind=='white' else 1e-3*np.sqrt(m/3.0)
    print(kind,'m=2^%d'%int(np.log2(m)),'N/m=%d'%(n//m),'truth %.4g'%truth,'full mean %.4g sd/mean %.3f'%(a.mean(),a.std()/a.mean()),'strided mean %.4g sd/mean %.3f'%(b.mean(),b.std()/b.mean()),'|strided/full-1| median %.2g max %.2g'%(np.median(r),r.max()))
