#!/bin/bash
# w67d: the rest of w46d's 17 tile sizes, seed 19, one run at a time: main tiled (w67dM), the untiled control seeded at
# the tiled seed points (w67dctl), and w46d's not-landed in-turn hand-over (w67dP: SRC_P = main's src with
# benchmarks/results/w46d_not_landed_in_turn.patch applied).
# bash benchmarks/w67d_chain2.sh SRC_P "missing sizes" "all sizes"
SRCP=$1; MISS=$2; ALL=$3
cd "$(dirname "$0")/.."
for T in $MISS; do
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dM --tiles $T --seeds 19 --pattern hierarchy
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dctl --tiles $T --seeds 19 --pattern hierarchy --untiled
done
for T in $ALL; do
  PYTHONPATH=$SRCP:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dP --tiles $T --seeds 19 --pattern hierarchy
done
