"""s67c: over the groups s65c's ring cap caps (CAP lines of s67c_ring_stats_{varied,harder}.txt),
candidate guard statistics from each group's histogram of children per parent: mean children
per parent; share of parents holding >= 2 and >= 3 children. Per parameter set: range; then
the largest value among non-ring groups (classes other than clusters) and the smallest among
clusters (by the generator's ring_min)."""
import collections
import json
import re
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants
from synth_variants import _harder

rows = collections.defaultdict(list)
for fn in sys.argv[1:]:
    for line in open(fn).read().splitlines():  # noqa: SIM115
        t = line.split()
        if len(t) < 10 or t[4] != "CAP":
            continue
        h = np.array(json.loads(line[line.index("hist ") + 5: line.index("]", line.index("hist ")) + 1]))
        k = np.arange(len(h))
        npar = h.sum()
        stats = ((h * k).sum() / npar, h[2:].sum() / npar, h[3:].sum() / npar)
        lab = re.sub(r"s\d+$", "", t[2])
        lab = "v" if lab.startswith("v") else lab
        rows[(t[0], t[1], lab)].append(stats + (t[2],))
ring_min = {}
for (which, cls, lab) in rows:
    if cls != "clusters":
        continue
    if which == "harder":
        kw = _harder()["clusters"][int(lab[1:])]
    else:
        kw = {} if lab == "v" else (_variants.VARIED["clusters"] + _variants.EDGE["clusters"])[int(lab[1:])]
    ring_min[(which, cls, lab)] = (kw.get("ring_min", 4), kw.get("ring_max", 6))
names = ("mean", "share>=2", "share>=3")
for key in sorted(rows, key=lambda k: (k[1] != "clusters", ring_min.get(k, (0,)), k)):
    v = rows[key]
    rm = f"rings {ring_min[key][0]}-{ring_min[key][1]}" if key in ring_min else "not rings"
    print(f"{' '.join(key):28s} {rm:10s} n {len(v):3d} " + " ".join(f"{nm} {min(x[i] for x in v):.2f}..{max(x[i] for x in v):.2f}" for i, nm in enumerate(names)))
ring = [x for k, v in rows.items() if k[1] == "clusters" for x in v]
other = [x for k, v in rows.items() if k[1] != "clusters" for x in v]
for i, nm in enumerate(names):
    print(f"{nm}: non-ring groups up to {max(x[i] for x in other):.2f} ({max(other, key=lambda x: x[i])[3]}); clusters from "
          f"{min(x[i] for x in ring):.2f} ({min(ring, key=lambda x: x[i])[3]}); clusters with ring_min >= 3 from "
          f"{min(x[i] for k, v in rows.items() if k[1] == 'clusters' and ring_min[k][0] >= 3 for x in v):.2f}")
for thr in (2.0, 2.5, 3.0):
    below = [(k, x[3], round(x[0], 2)) for k, v in rows.items() if k[1] == "clusters" for x in v if x[0] < thr]
    print(f"mean < {thr}: {len(below)} cluster exemplars un-capped: " + " ".join(f"{k[0][0]}:{lbl}:{m}" for k, lbl, m in below))
