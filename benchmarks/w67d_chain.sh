#!/bin/bash
# w67d: tiled hierarchy worlds (tag TAG) at the tile sizes given, seed 19, one run at a time (issue 19.4 point 4).
# bash benchmarks/w67d_chain.sh TAG "32 39 ..."   (from the worktree root; the tree's src)
TAG=$1; TS=$2
cd "$(dirname "$0")/.."
for T in $TS; do
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag $TAG --tiles $T --seeds 19 --pattern hierarchy
done
