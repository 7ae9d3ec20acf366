"""Helper s65h: main vs branch table of two s65h_probe.py --brief scans: python3.11 benchmarks/s65h_compare.py SCAN.txt (per row: 2 se / p, growth share against the owed bound, final signed densities)."""
import math
import re
import sys

rows = []
cur = None
with open(sys.argv[1]) as fh:
    lines = fh.readlines()
for line in lines:
    m = re.match(r"== (\S+) kinds \['(\w+)', '(\w+)'\] counts \[(\d+), (\d+)\] size classes \[(\d), (\d)\]", line)
    if m:
        cur = {"row": m[1], "ns": int(m[4]), "np_": int(m[5]), "cls": (int(m[6]), int(m[7]))}
        continue
    m = re.match(r" seed \d+: (\w+) n=(\d+) counts .*density out/ex-1 \[\s*([-\d.]+)\s+([-\d.]+)\s*\]\s*(.*)", line)
    if m:
        cur.update(v=m[1], ds=float(m[3]), dp=float(m[4]), fails=m[5].strip()); continue
    m = re.match(r"\s+growth\s+n=\s*\d+ .*whole/ex-whole \[\s*([-\d.]+)\s+([-\d.]+)\s*\]", line)
    if m:
        rs, rp = float(m[1]), float(m[2])
        c = cur; N = c['ns'] + c['np_']; p = c['ns'] / N
        se = math.sqrt(p * (1 - p) / N)
        gs = p * rs / (p * rs + (1 - p) * rp)
        big = 0 if c['cls'][0] > c['cls'][1] else 1
        c.update(rs=rs, rp=rp, p=p, rel=2 * se / p, gs=gs, bound=p + 2 * se)
        rows.append(c)
for c in sorted(rows, key=lambda c: c['rel']):
    two = c['cls'][0] != c['cls'][1]
    print(f"{c['row']:18s} {'2cls' if two else '1cls'} stones {c['ns']:3d} peb {c['np_']:3d} p {c['p']:.3f} 2se/p {c['rel']:.2f} growth share {c['gs']:.3f} bound {c['bound']:.3f} (gs-p)/(2se) {(c['gs']-c['p'])/(c['bound']-c['p']):+.2f} growth stones x{c['rs']:.2f} final dens stone {c['ds']:+.3f} peb {c['dp']:+.3f} {c['v']} {c['fails']}")
