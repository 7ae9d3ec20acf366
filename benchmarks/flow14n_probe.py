"""flow14n: the flow cases of benchmarks/grow.py --structure (--flow-only, then the 7 alternates: --only alt|all|NAMES) with a patch file exec'd first (--patch), each pass's interior score (--stages); six share, holes, largest defect group, crossings, CPU s."""
import sys, json, time, argparse
sys.path.insert(0, str(__import__('pathlib').Path(__file__).resolve().parent))
import numpy as np
from strew import Region
from strew.fields import flow_field
from strew.grow import grow
import grow as gb

ap = argparse.ArgumentParser()
ap.add_argument('--only', default='')
ap.add_argument('--set', action='append', default=[])
ap.add_argument('--patch', default='')
ap.add_argument('--stages', action='store_true')
ap.add_argument('--json', default='')
a = ap.parse_args()
kw = {}
for s in a.set:
    k, v = s.split('='); kw[k] = eval(v)

ex = gb._suite_exemplar("hex_lattice", nx=8, ny=8)
sp = 12.0
th = np.linspace(0, np.pi / 2, 30)
def turning(deg, w):
    def field(p):
        aa = np.radians(deg) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
        return np.c_[np.cos(aa), np.sin(aa)]
    return field
cases = []
def add(name, ex_, region, field, start, sp_=sp):
    cases.append((name, ex_, region, field, start, sp_))
for deg in (60.0, 90.0):
    w, h = 30*sp, 20*sp
    add(f"t{deg:.0f}", ex, Region.rectangle(w, h), turning(deg, w), None)
w, h = 24*sp, 16*sp
t = np.linspace(0, w, 30)
waves = [np.c_[t, h*(0.3+0.05*np.sin(2*np.pi*t/w))], np.c_[t, h*(0.7+0.05*np.sin(2*np.pi*t/w+0.5))]]
add("wavy", ex, Region.rectangle(w, h), flow_field(waves), None)
arcs = [np.c_[r*np.cos(th), r*np.sin(th)] for r in (10*sp, 25*sp)]
add("qc", ex, Region.rectangle(30*sp, 30*sp), flow_field(arcs), None)
for f in (1.0, 1.5):
    w, h = 30*sp*f, 20*sp*f
    field = turning(90.0, w); region = Region.rectangle(w, h)
    starts = [(w/2, 2*sp), (2*sp, h-2*sp)] if f == 1.0 else [None]
    for st in starts:
        add(f"t90_{f}_{'c' if st is None else '%d,%d' % (st[0]/sp, st[1]/sp)}", ex, region, field, st)
    aa = 30*sp*f; region = Region.rectangle(aa, aa)
    af = flow_field([np.c_[r*np.cos(th), r*np.sin(th)] for r in (aa/3, aa*5/6)])
    starts = [(aa-2*sp, aa-2*sp), (2*sp, 2*sp)] if f == 1.0 else [None]
    for st in starts:
        add(f"qc_{f}_{'c' if st is None else '%d,%d' % (st[0]/sp, st[1]/sp)}", ex, region, af, st)
from scipy.spatial import cKDTree
scales = gb._suite_exemplar("scales")
s_sp = float(np.median(cKDTree(scales.xy).query(scales.xy, 7)[0][:, 1:]))
w, h = 30*s_sp, 20*s_sp
add("sc_t90", scales, Region.rectangle(w, h), turning(90.0, w), None, s_sp)
add("sc_qc", scales, Region.rectangle(30*s_sp, 30*s_sp), flow_field([np.c_[r*np.cos(th), r*np.sin(th)] for r in (10*s_sp, 25*s_sp)]), None, s_sp)
# alternates
w, h = 30*sp, 20*sp
for st in ((28, 2), (28, 18), (2, 2), (10, 10)):
    add(f"A_t90_{st[0]},{st[1]}", ex, Region.rectangle(w, h), turning(90.0, w), (st[0]*sp, st[1]*sp))
aa = 30*sp
af = flow_field([np.c_[r*np.cos(th), r*np.sin(th)] for r in (aa/3, aa*5/6)])
for st in ((15, 15), (2, 28), (28, 2)):
    add(f"A_qc_{st[0]},{st[1]}", ex, Region.rectangle(aa, aa), af, (st[0]*sp, st[1]*sp))

names = [c[0] for c in cases]
sel = a.only.split(';') if a.only else names[:12]
if a.only == 'alt': sel = [n for n in names if n.startswith('A_')]
if a.only == 'all': sel = names

if a.patch:
    exec(open(a.patch).read())

stage_log = []
if a.stages:
    import strew.grow._growth as G
    from strew.grow._flow_retry import interior_score
    def wrap(name):
        orig = getattr(G, name)
        def f(g, *args, **k):
            r = orig(g, *args, **k)
            stage_log.append((name + ('(band)' if k.get('band') else ''), interior_score(g)))
            return r
        setattr(G, name, f)
    for nm in ('retry_shear', 'insert_stretched', 'reshape_shear', 'close_holes', 'relax_network', 'densify'):
        if hasattr(G, nm):
            wrap(nm)

res = {}
tot = 0
for name, ex_, region, field, st, sp_ in cases:
    if name not in sel: continue
    stage_log.clear()
    t0 = time.process_time()
    out = grow(ex_, region=region, mode="flow", flow=field, rng=1, start=st, **kw)
    dt = time.process_time() - t0
    xy = out.xy
    inner = region.distance_to_boundary(xy) > 2*sp_
    six = gb.hex_share(xy, sp_, inner)
    x0, y0, x1, y1 = region.bounds
    g = np.mgrid[x0+2*sp_:x1-2*sp_:3.0, y0+2*sp_:y1-2*sp_:3.0].reshape(2, -1).T
    d = gb.lattice_defects(xy, sp_, inner, g)
    cross = int((~region.contains_geometry(out.geometry, tolerance=1e-9)).sum())
    res[name] = dict(six=six, n=len(out), holes=d['holes'], grp=d['largest_defect_group'], cross=cross, cpu=dt)
    tot += six
    print(f"{name:14s} six={six:.4f} n={len(out)} holes={d['holes']} grp={d['largest_defect_group']} cross={cross} cpu={dt:.1f}", ' '.join(f"{s}:{v}" for s, v in stage_log) if a.stages else '', flush=True)
print('SUM', round(tot, 4), 'n>=0.9', sum(r['six'] >= 0.9 for r in res.values()))
if a.json:
    json.dump(res, open(a.json, 'w'), indent=1)
