#!/bin/bash
# w27h: hierarchy T48 worlds: main tiled, untiled control, branch tiled (helper w27h).
# bash benchmarks/w27h_chain.sh SEED TILE   (from the worktree root)
S=${1:-19}; T=${2:-48}
cd "$(dirname "$0")/.."
PYTHONPATH=/work/main/src python benchmarks/hie15_make.py --tag w27hbase --tiles $T --seeds $S --pattern hierarchy
PYTHONPATH=src python benchmarks/hie15_make.py --tag w27hC --tiles $T --seeds $S --pattern hierarchy
PYTHONPATH=/work/main/src python benchmarks/hie15_make.py --tag w27hctl --tiles $T --seeds $S --pattern hierarchy --untiled
