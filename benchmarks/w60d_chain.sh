#!/bin/bash
# w60d: tiled hierarchy worlds (tag TAG) and their untiled control (TAG ctl, seeded at the tiled seed points) at the
# tile sizes given, seed 19, one run at a time, nice 5 (issue 19.4: split the strip measure's bias from the seams).
# bash benchmarks/w60d_chain.sh TAG CTLTAG "32 32.5 ..."   (from the worktree root)
TAG=$1; CTL=$2; TS=$3
cd "$(dirname "$0")/.."
for T in $TS; do
  PYTHONPATH=src nice -n 5 python3.11 benchmarks/hie15_make.py --tag $TAG --tiles $T --seeds 19 --pattern hierarchy
  PYTHONPATH=src nice -n 5 python3.11 benchmarks/hie15_make.py --tag $CTL --tiles $T --seeds 19 --pattern hierarchy --untiled
done
