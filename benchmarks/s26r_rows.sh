#!/bin/bash
# Helper s26r: rings rows of the large-rings set at seeds 1-6, on the branch (new) or with LATTICE_PHASE off (base).
#     bash benchmarks/s26r_rows.sh new|base   -> benchmarks/results/s26r_rows_{new,base}.txt
tag=$1
pre=""
if [ "$tag" = base ]; then pre="import strew.synth._grow as G; G.LATTICE_PHASE = False; "; fi
PYTHONPATH=src python -c "${pre}import runpy, sys; sys.argv = sys.argv[1:]; sys.path.insert(0, 'benchmarks'); runpy.run_path(sys.argv[0], run_name='__main__')" \
  benchmarks/fresh17_rows.py synth rings:p2s11,rings:p2s15,rings:p2s16,rings:p2s17,rings:p2s18 1-6 > benchmarks/results/s26r_rows_${tag}.txt 2>&1
