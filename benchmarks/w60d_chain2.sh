#!/bin/bash
# w60d: the untiled controls first (cheap: the bias split needs them at every size), then the tiled worlds,
# one run at a time, nice 5. bash benchmarks/w60d_chain2.sh WAITPID "ctl sizes" "tiled sizes"
cd "$(dirname "$0")/.."
while kill -0 $1 2>/dev/null; do sleep 5; done
for T in $2; do
  PYTHONPATH=src nice -n 5 python3.11 benchmarks/hie15_make.py --tag w60dctl --tiles $T --seeds 19 --pattern hierarchy --untiled
done
for T in $3; do
  PYTHONPATH=src nice -n 5 python3.11 benchmarks/hie15_make.py --tag w60dM --tiles $T --seeds 19 --pattern hierarchy
done
