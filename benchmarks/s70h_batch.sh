#!/bin/bash
# Helper s69h: the brief's rows, pinned, integ38 (prototype off) or prototype on (MODE=on [SE=k]).
# usage: MODE=off|on SE=0 bash benchmarks/s69h_batch.sh TAG
export NPY_DISABLE_CPU_FEATURES="X86_V4 AVX512_ICL AVX512_SPR" OPENBLAS_CORETYPE=Haswell PYTHONPATH=src:benchmarks
cd "$(dirname "$0")/.."
tag=$1
if [ "$MODE" = on ]; then pre="benchmarks/s69h_on.py SE=${SE:-0}"; else pre=""; fi
out=benchmarks/results/s70h_probe_$tag.txt
: > $out
for spec in "two_sizes:h5s38 1-6" "two_sizes:h5s11 1-3" "two_sizes:p3s31,two_sizes:p4s35,two_sizes:p3s30 1-4" "two_sizes:h11s37,two_sizes:h11s29 1-4"; do
  set -- $spec
  nice -n 10 python3.11 $pre benchmarks/s67h_probe.py $1 $2 >> $out 2>&1
done
echo DONE >> $out
