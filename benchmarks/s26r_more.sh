#!/bin/bash
# Helper s26r: tuned-draw rings audits (no row lost), on the branch (new) or with LATTICE_PHASE off (base).
#     bash benchmarks/s26r_more.sh new|base   -> benchmarks/results/s26r_{new,base}_{harder1516,harder78,varied78,varied910,varied1112,varied1314}_rings.txt
tag=$1
pre=""
if [ "$tag" = base ]; then pre="import strew.synth._grow as G; G.LATTICE_PHASE = False; "; fi
R=benchmarks/results
py() { script=$1; shift; PYTHONPATH=src python -c "${pre}import runpy, sys; sys.argv = sys.argv[1:]; sys.path.insert(0, 'benchmarks'); runpy.run_path(sys.argv[0], run_name='__main__')" "$script" "$@"; }
py benchmarks/synth_variants.py --harder --harder-variants 15,16 --only rings --seeds 1 > $R/s26r_${tag}_harder1516_rings.txt 2>&1
py benchmarks/synth_variants.py --harder --harder-variants 7,8 --only rings --seeds 1 > $R/s26r_${tag}_harder78_rings.txt 2>&1
for v in 7,8 9,10 11,12 13,14; do
  py benchmarks/synth_variants.py --varied-variants $v --variants $v --only rings --seeds 1 > $R/s26r_${tag}_varied${v/,/}_rings.txt 2>&1
done
