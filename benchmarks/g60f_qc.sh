#!/bin/bash
# g60f: the 11 qc cases of g46f (hex, rng 1), cores clustered/total; G60F_SEED passes through.
# usage: bash benchmarks/g60f_qc.sh OUTPREFIX
cd "$(dirname "$0")/.."
o=$1
PYTHONPATH=src:benchmarks nice -n 5 python3.11 benchmarks/g43f_smooth.py --field qc --sizes 16 --kind hex --rng 1 --starts 14:2,2:14,14:14,c,2:2 > ${o}_16.txt 2>&1
PYTHONPATH=src:benchmarks nice -n 5 python3.11 benchmarks/g43f_smooth.py --field qc --sizes 20 --kind hex --rng 1 --starts c,2:2,18:18 > ${o}_20.txt 2>&1
PYTHONPATH=src:benchmarks nice -n 5 python3.11 benchmarks/g43f_smooth.py --field qc --sizes 24 --kind hex --rng 1 --starts c,2:2,22:22 > ${o}_24.txt 2>&1
cat ${o}_16.txt ${o}_20.txt ${o}_24.txt | grep "^qc" | python3.11 -c "
import sys,re
T=C=0;cpu=0;h=0;a=0
for l in sys.stdin:
    d=dict(re.findall(r'(\w+)=([\d./]+)',l)); T+=int(d['cores']);C+=int(d['clustered']);cpu+=float(d['cpu']);h+=int(d['holes']);a+=int(d['across'])
    print(l.rstrip())
print(f'TOTAL clustered/total {C}/{T} holes {h} across {a} cpu {cpu:.1f}')
"
