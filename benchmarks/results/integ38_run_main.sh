cd /work/wt_audit
R=/work/main/benchmarks/results
ALL=hex_lattice,bricks,clusters,rings,rows_noisy,scales,sparse_voids,sticks,stones,stripes,three_sizes,two_sizes
export PYTHONPATH=src:benchmarks
python benchmarks/synth_variants.py --varied-variants 41,42 --variants 41,42 --only $ALL --seeds 1 --json $R/integ38_main_synth_v4142.json > $R/integ38_main_synth_v4142.txt 2>&1
python benchmarks/grow_variants.py --varied-variants 41,42 --variants 41,42 --only $ALL --seeds 1 --json $R/integ38_main_grow_v4142.json > $R/integ38_main_grow_v4142.txt 2>&1
touch $R/integ38_main_v_done
python benchmarks/synth_variants.py --harder --harder-variants 41,42 --only two_sizes,three_sizes,clusters,stones,sparse_voids --seeds 1 --json $R/integ38_main_synth_h4142.json > $R/integ38_main_synth_h4142.txt 2>&1
python benchmarks/grow_variants.py --harder --harder-variants 41,42 --only two_sizes,three_sizes,clusters --seeds 1 --json $R/integ38_main_grow_h4142.json > $R/integ38_main_grow_h4142.txt 2>&1
touch $R/integ38_main_h_done
for f in synth_v4142 synth_h4142; do python benchmarks/svar13i_oracle.py $R/integ38_main_$f.json --draws 2 --json $R/integ38_oracle_$f.json > $R/integ38_oracle_$f.txt 2>&1; done
for f in grow_v4142 grow_h4142; do python benchmarks/svar13i_oracle.py $R/integ38_main_$f.json --draws 2 --harder --json $R/integ38_oracle_$f.json > $R/integ38_oracle_$f.txt 2>&1; done
touch $R/integ38_main_all_done
