#!/bin/bash
# w67d: main's tiled hierarchy worlds with one strew.tiles constant changed (hie15_make --set), seed 19, one run at a time.
# bash benchmarks/w67d_chain_set.sh TAG NAME=VALUE "sizes"
TAG=$1; SET=$2; TS=$3
cd "$(dirname "$0")/.."
for T in $TS; do
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag $TAG --tiles $T --seeds 19 --pattern hierarchy --set $SET
done
