#!/bin/bash
# Helper s26r: the rings audits, on the branch (new) or with LATTICE_PHASE off (base).
#     bash benchmarks/s26r_audits.sh new|base
# Writes benchmarks/results/s26r_{new,base}_*.json and .txt.
set -u
tag=$1
pre=""
if [ "$tag" = base ]; then pre="import strew.synth._grow as G; G.LATTICE_PHASE = False; "; fi
R=benchmarks/results
py() { script=$1; shift; PYTHONPATH=src python -c "${pre}import runpy, sys; sys.argv = sys.argv[1:]; sys.path.insert(0, 'benchmarks'); runpy.run_path(sys.argv[0], run_name='__main__')" "$script" "$@"; }
py benchmarks/synth_variants.py --varied-variants 17,18 --variants 17,18 --only rings --seeds 1 --json $R/s26r_${tag}_varied1718_rings.json > $R/s26r_${tag}_varied1718_rings.txt 2>&1
py benchmarks/synth_variants.py --varied-variants 15,16 --variants 15,16 --only rings --seeds 1 --json $R/s26r_${tag}_varied1516_rings.json > $R/s26r_${tag}_varied1516_rings.txt 2>&1
py benchmarks/synth_variants.py --harder --harder-variants 17,18 --only rings --seeds 1 --json $R/s26r_${tag}_harder1718_rings.json > $R/s26r_${tag}_harder1718_rings.txt 2>&1
py benchmarks/fidelity.py --method synth --only rings --seeds 1-5 --json $R/s26r_${tag}_fidelity_rings.json > $R/s26r_${tag}_fidelity_rings.txt 2>&1
