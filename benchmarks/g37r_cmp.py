"""Helper g37r: two audit texts (grow_variants / synth_variants output) row by row.

    python benchmarks/g37r_cmp.py MAIN.txt NEW.txt [CLASS,...]

Prints each (class, label) row of NEW beside MAIN's, marks changed verdicts and counts.
"""
import re
import sys


def rows(path, only):
    out = {}
    with open(path) as f:
        lines = f.readlines()
    for line in lines:
        m = re.match(r"\s+(\S+)\s+(\S+)\s+seed (\d+): (pass|FAIL) n=(\d+).*?cpu ?(.*)$", line)
        if m and (not only or m.group(1) in only):
            out[(m.group(1), m.group(2), m.group(3))] = (m.group(4), int(m.group(5)), m.group(6).strip())
    return out


def main():
    only = set(sys.argv[3].split(",")) if len(sys.argv) > 3 else set()
    a, b = rows(sys.argv[1], only), rows(sys.argv[2], only)
    pa = pb = same = 0
    for k in sorted(set(a) & set(b)):
        va, vb = a[k], b[k]
        pa += va[0] == "pass"
        pb += vb[0] == "pass"
        same += va[1] == vb[1]
        mark = "  " if va[0] == vb[0] else ("++" if vb[0] == "pass" else "--")
        print(f"{mark} {k[0]:12s} {k[1]:6s} s{k[2]}  main {va[0]} n={va[1]} {va[2]:40s} new {vb[0]} n={vb[1]} {vb[2]}")
    print(f"main {pa}/{len(set(a) & set(b))}  new {pb}/{len(set(a) & set(b))}  same n on {same}")


if __name__ == "__main__":
    main()
