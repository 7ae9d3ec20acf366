cd /work/wt_audit
R=/work/main/benchmarks/results
ALL=hex_lattice,bricks,clusters,rings,rows_noisy,scales,sparse_voids,sticks,stones,stripes,three_sizes,two_sizes
export PYTHONPATH=src:benchmarks
python benchmarks/synth_variants.py --varied-variants 45,46 --variants 45,46 --only $ALL --seeds 1 --json $R/integ40_main_synth_v4546.json > $R/integ40_main_synth_v4546.txt 2>&1
python benchmarks/grow_variants.py --varied-variants 45,46 --variants 45,46 --only $ALL --seeds 1 --json $R/integ40_main_grow_v4546.json > $R/integ40_main_grow_v4546.txt 2>&1
touch $R/integ40_main_v_done
python benchmarks/synth_variants.py --harder --harder-variants 45,46 --only two_sizes,three_sizes,clusters,stones,sparse_voids --seeds 1 --json $R/integ40_main_synth_h4546.json > $R/integ40_main_synth_h4546.txt 2>&1
python benchmarks/grow_variants.py --harder --harder-variants 45,46 --only two_sizes,three_sizes,clusters --seeds 1 --json $R/integ40_main_grow_h4546.json > $R/integ40_main_grow_h4546.txt 2>&1
touch $R/integ40_main_h_done
for f in synth_v4546 synth_h4546; do python benchmarks/svar13i_oracle.py $R/integ40_main_$f.json --draws 2 --json $R/integ40_oracle_$f.json > $R/integ40_oracle_$f.txt 2>&1; done
for f in grow_v4546 grow_h4546; do python benchmarks/svar13i_oracle.py $R/integ40_main_$f.json --draws 2 --harder --json $R/integ40_oracle_$f.json > $R/integ40_oracle_$f.txt 2>&1; done
touch $R/integ40_main_all_done
