"""Helper seam17 (issue 13 point 2): three sizes at 50x, seed 4: the one failing window
(10,6) (nn[medium>medium] 1.064) counted, against the spread of synth's windows and of the
exemplar's generator drawn at 50x (``seam13m_oracle50``'s framed draws, seeds 1-3): the
medium count's z-score, its residual once the large count is regressed out, and each
generator draw's worst window with its medium z-score.

    python benchmarks/seam17_three_window.py
"""
import sys

import numpy as np

sys.path.insert(0,'benchmarks')
import seam13n_windows as W
from _runner import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize

if '--quick' in sys.argv[1:]:
    print('seam17_three_window: skipped: 50x canvases (minutes)')
    sys.exit(W.SKIPPED)
mk=fidelity_suite(); ex=mk.make_exemplar('three_sizes')
x0,y0,x1,y1=ex.region.bounds; region=Region.rectangle(7.07*(x1-x0),7.07*(y1-y0))
out=synthesize(ex,region,rng=4,measure=False)
rep=fidelity(ex,out,region,eq5=False); L=rep.local; S=np.asarray(L['score'],float)
geom=(L['x0'],L['y0'],L['step'],L['window'],S.shape[0],S.shape[1])
st=W.window_stats(np.asarray(out.xy),W._classes(out),geom)
i,j=10,6; k=i*S.shape[1]+j
print('synth s4 window (10,6) score',round(S[i,j],3),'counts small/medium/large',st[k,:3],'sl median',round(st[k,3],2))
print('synth windows mean',np.round(st[:,:3].mean(0),2),'sd',np.round(st[:,:3].std(0),2))
med=st[:,1]; lg=st[:,2]
z=(st[k,1]-med.mean())/med.std(); print('medium z',round(z,2),'rank from lowest',int((med<st[k,1]).sum())+1,'of',len(med))
same=lg==st[k,2]; print('windows with the same large count',int(same.sum()),'their medium mean',round(med[same].mean(),2))
# residual of medium on large
A=np.c_[np.ones(len(lg)),lg]; c=np.linalg.lstsq(A,med,rcond=None)[0]; r=med-A@c
print('medium residual after large: window',round(r[k],2),'sd',round(r.std(),2),'z',round(r[k]/r.std(),2))
# medium nn distances in the window vs exemplar
import seam13m_oracle50 as O

outl=O._outlines('three_sizes')
for seed in (1,2,3):
    arr,reg,_=O.oracle('three_sizes',seed,50.0,'framed',2.0,outl)
    rp=fidelity(ex,arr,reg,eq5=False); Lg=rp.local; Sg=np.asarray(Lg['score'],float)
    g=(Lg['x0'],Lg['y0'],Lg['step'],Lg['window'],Sg.shape[0],Sg.shape[1])
    sg=W.window_stats(np.asarray(arr.xy),W._classes(arr),g)
    mg=sg[:,1]; lgg=sg[:,2]; A=np.c_[np.ones(len(lgg)),lgg]; c=np.linalg.lstsq(A,mg,rcond=None)[0]; rg=mg-A@c
    wi=np.nanargmax(np.where(np.isfinite(Sg.ravel()),Sg.ravel(),-1))
    print(f'generator s{seed}: medium mean {mg.mean():.2f} sd {mg.std():.2f}; min-medium z {(mg.min()-mg.mean())/mg.std():.2f}; residual sd {rg.std():.2f} min z {rg.min()/rg.std():.2f}; worst window score {Sg.ravel()[wi]:.3f} {Lg["worst"]["metric"]} its medium z {(mg[wi]-mg.mean())/mg.std():.2f}')
