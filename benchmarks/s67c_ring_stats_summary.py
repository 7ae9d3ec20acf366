"""s67c: summary of s67c_ring_stats_{varied,harder}.txt: per parameter set and gate
(CAP: s65c's patch caps the group; near: nearly), how many exemplars and the range of the
guard's statistic (mean children per parent), median and largest ring."""
import collections
import re
import sys

rows = collections.defaultdict(list)
for fn in sys.argv[1:]:
    for line in open(fn).read().splitlines():  # noqa: SIM115
        t = line.split()
        if len(t) < 10 or t[0] not in ("varied", "harder"):
            continue
        lab = re.sub(r"s\d+$", "", t[2])
        lab = "v" if lab.startswith("v") else lab
        g = {"mean": float(t[t.index("mean") + 1]), "med": float(t[t.index("median") + 1]), "mx": int(t[t.index("max") + 1])}
        rows[(t[0], t[1], lab, t[3], t[4])].append(g)
for k in sorted(rows):
    v = rows[k]
    m = sorted(x["mean"] for x in v)
    print(f"{' '.join(k):45s} exemplars {len(v):3d} mean children/parent {m[0]:.2f}..{m[-1]:.2f} "
          f"median {min(x['med'] for x in v):.1f}..{max(x['med'] for x in v):.1f} largest {min(x['mx'] for x in v)}..{max(x['mx'] for x in v)}")
