#!/bin/bash
# Helper s25r: the audits of the hub-lattice basis change, one after another (rings only, seed 1).
#     bash benchmarks/s25r_audits.sh [SRC] [TAG]     (SRC: the strew source tree, default src; TAG: file prefix)
SRC=${1:-src}; T=${2:-s25r_new}
export PYTHONPATH=$SRC
python benchmarks/synth_variants.py --varied-variants 15,16 --variants 15,16 --only rings --seeds 1 --json benchmarks/results/${T}_varied1516_rings.json 2>&1 | grep -E "rings|FAIL|pass" | tail -20
python benchmarks/synth_variants.py --harder-variants 15,16 --only rings --seeds 1 --json benchmarks/results/${T}_harder1516_rings.json 2>&1 | grep -E "rings|FAIL|pass" | tail -20
python benchmarks/synth_variants.py --varied --only rings --seeds 1 --json benchmarks/results/${T}_varied_rings.json 2>&1 | grep -E "rings|FAIL|pass" | tail -20
python benchmarks/fidelity.py --method synth --only rings --seeds 1-5 2>&1 | tail -8
