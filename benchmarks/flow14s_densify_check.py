"""flow14s: the figures test_grow_flow14k_densify compares (the corner (2, 18), densify on and off):
six share, stretched share, isolated defect share, largest defect group, holes, elements turned past 12 deg.
Run from the repository root: PYTHONPATH=src:tests python benchmarks/flow14s_densify_check.py [OUT.json]"""
import json
import sys
import os
sys_path_tests = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "grow")
sys.path.insert(0, sys_path_tests)
import numpy as np
from strew import Region
from strew.grow._growth import GrowParams, grow_reference
rows = {}
from test_grow_flow14d_stretch import analyze, fidelity_suite
from test_grow_flow14g_retry import _turning_90
from test_grow_flow_gaps import SP, _holes, _shares
from test_grow_flow14k_densify import _defect_groups
ref = analyze(fidelity_suite().make_exemplar("hex_lattice", nx=8, ny=8))
w = 30 * SP
region = Region.rectangle(w, 20 * SP)
kw = dict(region=region, mode="flow", flow=_turning_90(w), start=(2 * SP, 18 * SP))
for extra in ({}, dict(flow_densify_rounds=None)):
    out = grow_reference(ref, GrowParams(**kw, **extra), rng=1)
    six, st = _shares(out.xy, region)
    iso, lg = _defect_groups(out.xy, region)
    v = kw["flow"](out.xy)
    d = np.degrees(np.mod(out.rotation - np.arctan2(v[:, 1], v[:, 0]), np.pi / 3))
    rows['off' if extra else 'on'] = dict(n=len(out), six=six, stretched=st, iso=iso, largest=lg, holes=_holes(out.xy, region), turned=int((np.minimum(d, 60 - d) > 12.0).sum()))
    print(extra, len(out), 'six %.4f stretched %.3f iso %.3f largest %d holes %d turned %d' % (six, st, iso, lg, _holes(out.xy, region), int((np.minimum(d, 60 - d) > 12.0).sum())), flush=True)
if len(sys.argv) > 1:
    json.dump(rows, open(sys.argv[1], 'w'), indent=1)
