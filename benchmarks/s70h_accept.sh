#!/bin/bash
# Helper s70h: acceptance grids, pinned; MODE=on runs with _grow._TWO_CLASS_AREA on (s69h_on.py), off = the flag off.
# usage: MODE=on|off bash benchmarks/s70h_accept.sh varied|harder
export NPY_DISABLE_CPU_FEATURES="X86_V4 AVX512_ICL AVX512_SPR" OPENBLAS_CORETYPE=Haswell PYTHONPATH=src:benchmarks
cd "$(dirname "$0")/.."
if [ "$MODE" = on ]; then pre="benchmarks/s69h_on.py SE=0"; else pre=""; fi
R=benchmarks/results
case $1 in
  varied) /usr/bin/time -f "cpu %U+%S s wall %e s" nice -n 10 python3.11 $pre benchmarks/synth_variants.py --varied-variants 30,31,32,33,34,35,36,37,38 --variants 30,31,32,33,34,35,36,37,38 --only two_sizes --seeds 1 --json $R/s70h_varied_ts_3038_$MODE.json > $R/s70h_varied_ts_3038_$MODE.txt 2>&1 ;;
  harder) /usr/bin/time -f "cpu %U+%S s wall %e s" nice -n 10 python3.11 $pre benchmarks/synth_variants.py --harder --harder-variants 25,26,27,28,29,30,31,32,33,34,35,36,37,38 --only two_sizes --seeds 1 --json $R/s70h_harder_ts_2538_$MODE.json > $R/s70h_harder_ts_2538_$MODE.txt 2>&1 ;;
esac
