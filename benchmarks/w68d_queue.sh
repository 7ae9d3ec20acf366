#!/bin/bash
# w68d: tiled hierarchy worlds (seed 19) of one variant from a snapshot of src (SRC), one run at a time, after PID ends.
# bash benchmarks/w68d_queue.sh PID SRC TAG "sizes" [NAME=VALUE ...]
PID=$1; SRC=$2; TAG=$3; TS=$4; shift 4
cd "$(dirname "$0")/.."
while kill -0 "$PID" 2>/dev/null; do sleep 3; done
SETS=""; for kv in "$@"; do SETS="$SETS --set $kv"; done
for T in $TS; do
  PYTHONPATH=$SRC:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag "$TAG" --tiles "$T" --seeds 19 --pattern hierarchy $SETS
done
