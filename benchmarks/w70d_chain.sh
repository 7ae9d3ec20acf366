#!/bin/bash
# w70d: rebuild the control (untiled, w67dctl), main (w67dM, SRC_MAIN) and VK0O (w69dVK0O, SRC_V) hierarchy worlds,
# seed 19, at the tile sizes given, one run at a time.   bash benchmarks/w70d_chain.sh SRC_MAIN SRC_V "32 34 ..."
SM=$1; SV=$2; TS=$3
cd "$(dirname "$0")/.."
for T in $TS; do
  PYTHONPATH=src:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dctl --tiles $T --seeds 19 --pattern hierarchy --untiled
  PYTHONPATH=$SM:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w67dM --tiles $T --seeds 19 --pattern hierarchy
  PYTHONPATH=$SV:benchmarks nice -n 10 python3.11 benchmarks/hie15_make.py --tag w69dVK0O --tiles $T --seeds 19 --pattern hierarchy --set _VINES_FIRST=1 --set _KEEP_FIRST_REACH=0.0 --set _VINES_FIRST_OPEN=1
done
