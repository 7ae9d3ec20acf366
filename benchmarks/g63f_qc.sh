#!/bin/bash
# g63f: the 11 qc cases of g46f/g60f (hex, rng 1), cores clustered/total, for one tree.
# usage: bash benchmarks/g63f_qc.sh OUTPREFIX SRC PIN
#   SRC: the src folder to import strew from (src = this worktree, /work/main/src = main)
#   PIN: 1 = CI's pins (NPY_DISABLE_CPU_FEATURES, OPENBLAS_CORETYPE), 0 = unpinned
cd "$(dirname "$0")/.."
o=$1; src=$2; pin=$3
if [ "$pin" = 1 ]; then export NPY_DISABLE_CPU_FEATURES="X86_V4 AVX512_ICL AVX512_SPR" OPENBLAS_CORETYPE=Haswell; fi
run() { PYTHONPATH=$src:benchmarks nice -n 10 python3.11 benchmarks/g43f_smooth.py --field qc --kind hex --rng 1 "$@"; }
run --sizes 16 --starts 14:2,2:14,14:14,c,2:2 > ${o}_16.txt 2>&1
run --sizes 20 --starts c,2:2,18:18 > ${o}_20.txt 2>&1
run --sizes 24 --starts c,2:2,22:22 > ${o}_24.txt 2>&1
{ echo "src=$src pin=$pin"; cat ${o}_16.txt ${o}_20.txt ${o}_24.txt | grep "^qc" | python3.11 -c "
import sys,re
T=C=0;cpu=0;h=0;a=0;six=0
for l in sys.stdin:
    d=dict(re.findall(r'(\w+)=([\d./]+)',l)); T+=int(d['cores']);C+=int(d['clustered']);cpu+=float(d['cpu']);h+=int(d['holes']);a+=int(d['across']);six+=float(d['six'])
    print(l.rstrip())
print(f'TOTAL clustered/total {C}/{T} six_sum {six:.4f} holes {h} across {a} cpu {cpu:.1f}')
"; } > ${o}_sum.txt
cat ${o}_sum.txt
