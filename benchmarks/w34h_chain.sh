#!/bin/bash
# w34h: tiled hierarchy worlds of this branch with a strew.tiles constant set (issue 19.4), one run at a time, nice 5.
# bash benchmarks/w34h_chain.sh TAG "40 48 52 56" NAME=VALUE   (from the worktree root; seed 19; controls w27hctl/w28hctl exist)
TAG=$1; TS=${2:-"40 44 48 52 56"}; SET=$3
cd "$(dirname "$0")/.."
for T in $TS; do
  PYTHONPATH=src nice -n 5 python benchmarks/hie15_make.py --tag $TAG --tiles $T --seeds 19 --pattern hierarchy ${SET:+--set $SET}
done
