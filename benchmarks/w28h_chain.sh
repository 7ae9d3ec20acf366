#!/bin/bash
# w28h: worlds for the pooled strip shares (issue 19.4, helper w28h): for each tile size, main tiled
# (TAG base, /work/main/src) and the untiled control (TAG ctl, /work/main/src), one run at a time, nice 5.
# bash benchmarks/w28h_chain.sh SEEDS "40 52 56" [base|branch] [TAG] [PATTERN]   (from the worktree root)
#   base:   w28hbase / w28hctl (hierarchy) or w28hvbase / w28hvctl (vase)
#   branch: only the tiled world, PYTHONPATH=src, tag TAG (default w28hC)
# e.g. bash benchmarks/w28h_chain.sh 19 "40 52 56"; bash benchmarks/w28h_chain.sh 21,22 48 base - vase
S=${1:-19}; TS=${2:-"40 52 56"}; MODE=${3:-base}; TAG=${4:-w28hC}; PAT=${5:-hierarchy}
P=w28h; [ "$PAT" = vase ] && P=w28hv
cd "$(dirname "$0")/.."
for T in $TS; do
  if [ "$MODE" = branch ]; then
    PYTHONPATH=src nice -n 5 python benchmarks/hie15_make.py --tag $TAG --tiles $T --seeds $S --pattern $PAT
  else
    PYTHONPATH=/work/main/src nice -n 5 python benchmarks/hie15_make.py --tag ${P}base --tiles $T --seeds $S --pattern $PAT
    PYTHONPATH=/work/main/src nice -n 5 python benchmarks/hie15_make.py --tag ${P}ctl --tiles $T --seeds $S --pattern $PAT --untiled
  fi
done
