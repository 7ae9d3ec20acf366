"""s35c: compare two synth_variants.py outputs row by row (verdict and n); prints the rows that differ and pass counts.

    python benchmarks/s35c_cmp.py MAIN.txt NEW.txt
"""
import sys, re
def rows(f):
    d = {}
    for l in open(f):
        m = re.match(r'\s+(\S+)\s+(\S+)\s+seed (\d+): (pass|FAIL) n=(\d+)(.*)', l)
        if m:
            d[(m[1], m[2], m[3])] = (m[4], int(m[5]), re.sub(r'[0-9.]+s cpu', '', m[6]).strip())
    return d
a, b = rows(sys.argv[1]), rows(sys.argv[2])
same = 0; pa = pb = 0
for k in b:
    if k not in a: print('missing in main', k); continue
    pa += a[k][0] == 'pass'; pb += b[k][0] == 'pass'
    if a[k][:2] == b[k][:2]: same += 1
    else: print(' '.join(k), 'main', a[k], '| new', b[k])
print(f'{len(b)} rows, {same} same verdict+n; main {pa} pass, new {pb} pass')
