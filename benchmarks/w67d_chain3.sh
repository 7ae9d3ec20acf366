#!/bin/bash
# w67d: the 16 other tile sizes of 32-48 in steps of 0.5 (seed 19): main tiled (w67dM), control (w67dctl), w46d's
# patch (w67dP, SRC_P), one run at a time.   bash benchmarks/w67d_chain3.sh SRC_P "sizes"
SRCP=$1; TS=$2
cd "$(dirname "$0")/.."
for T in $TS; do
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dM --tiles $T --seeds 19 --pattern hierarchy
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dctl --tiles $T --seeds 19 --pattern hierarchy --untiled
  PYTHONPATH=$SRCP:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dP --tiles $T --seeds 19 --pattern hierarchy
done
