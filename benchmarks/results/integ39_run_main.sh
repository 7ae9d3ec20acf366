cd /work/wt_audit
R=/work/main/benchmarks/results
ALL=hex_lattice,bricks,clusters,rings,rows_noisy,scales,sparse_voids,sticks,stones,stripes,three_sizes,two_sizes
export PYTHONPATH=src:benchmarks
python benchmarks/synth_variants.py --varied-variants 43,44 --variants 43,44 --only $ALL --seeds 1 --json $R/integ39_main_synth_v4344.json > $R/integ39_main_synth_v4344.txt 2>&1
python benchmarks/grow_variants.py --varied-variants 43,44 --variants 43,44 --only $ALL --seeds 1 --json $R/integ39_main_grow_v4344.json > $R/integ39_main_grow_v4344.txt 2>&1
touch $R/integ39_main_v_done
python benchmarks/synth_variants.py --harder --harder-variants 43,44 --only two_sizes,three_sizes,clusters,stones,sparse_voids --seeds 1 --json $R/integ39_main_synth_h4344.json > $R/integ39_main_synth_h4344.txt 2>&1
python benchmarks/grow_variants.py --harder --harder-variants 43,44 --only two_sizes,three_sizes,clusters --seeds 1 --json $R/integ39_main_grow_h4344.json > $R/integ39_main_grow_h4344.txt 2>&1
touch $R/integ39_main_h_done
for f in synth_v4344 synth_h4344; do python benchmarks/svar13i_oracle.py $R/integ39_main_$f.json --draws 2 --json $R/integ39_oracle_$f.json > $R/integ39_oracle_$f.txt 2>&1; done
for f in grow_v4344 grow_h4344; do python benchmarks/svar13i_oracle.py $R/integ39_main_$f.json --draws 2 --harder --json $R/integ39_oracle_$f.json > $R/integ39_oracle_$f.txt 2>&1; done
touch $R/integ39_main_all_done
