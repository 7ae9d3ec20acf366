#!/bin/bash
# w67d: main tiled (w67dM) and the untiled control (w67dctl) at more tile sizes of 32-48 (seed 19), one run at a time.
# bash benchmarks/w67d_chain4.sh "sizes"
cd "$(dirname "$0")/.."
for T in $1; do
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dM --tiles $T --seeds 19 --pattern hierarchy
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dctl --tiles $T --seeds 19 --pattern hierarchy --untiled
done
