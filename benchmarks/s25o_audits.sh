#!/bin/bash
# Helper s25o: the audits of the cluster-centre spacing (_prepare.centre_spacing) on a tree
# against main, clusters and the three_sizes rows it reaches, seed 1.
#     bash benchmarks/s25o_audits.sh TREE_SRC TAG      (e.g. src new; /work/main/src base)
export PYTHONPATH=$1
T=$2
R=benchmarks/results
python benchmarks/synth_variants.py --varied --only clusters --seeds 1 --json $R/s25o_${T}_varied78_clusters.json 2>&1 | grep -v "^  .* pass "
python benchmarks/synth_variants.py --varied-variants 15,16 --variants 15,16 --only clusters --seeds 1 --json $R/s25o_${T}_varied1516_clusters.json 2>&1 | grep -v "^  .* pass "
python benchmarks/synth_variants.py --harder --only clusters --seeds 1 --json $R/s25o_${T}_harder78_clusters.json 2>&1 | grep -v "^  .* pass "
python benchmarks/synth_variants.py --harder-variants 15,16 --only clusters --seeds 1 --json $R/s25o_${T}_harder1516_clusters.json 2>&1 | grep -v "^  .* pass "
python benchmarks/syn13z_rows.py three_sizes:0:16:1 three_sizes:5:8:1 three_sizes:5:16:1 three_sizes:8:16:1 three_sizes:13:7:1 three_sizes:13:16:1 2>&1
