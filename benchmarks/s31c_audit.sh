#!/bin/bash
# Helper s31c: the clusters audits on one tree (SRC: main's src unpacked, or src), seed 1.
#   bash benchmarks/s31c_audit.sh SRC TAG [CLASSES]
# Writes benchmarks/results/s31c_TAG_{v,h}VV.txt for variant pairs 23,24 21,22 19,20 17,18.
SRC=$1; TAG=$2; ONLY=${3:-clusters}
for vv in 23,24 21,22 19,20 17,18; do
  n=${vv/,/}
  nice -n 5 env PYTHONPATH=$SRC python benchmarks/synth_variants.py --varied --varied-variants $vv --variants $vv --only $ONLY --seeds 1 --json /tmp/s31c/${TAG}_v$n.json > benchmarks/results/s31c_${TAG}_v$n.txt 2>&1
  nice -n 5 env PYTHONPATH=$SRC python benchmarks/synth_variants.py --harder --harder-variants $vv --only $ONLY --seeds 1 --json /tmp/s31c/${TAG}_h$n.json > benchmarks/results/s31c_${TAG}_h$n.txt 2>&1
done
