cd /tmp/s59/main
R=/work/main/benchmarks/results
ALL=hex_lattice,bricks,clusters,rings,rows_noisy,scales,sparse_voids,sticks,stones,stripes,three_sizes,two_sizes
export PYTHONPATH=src:benchmarks
python benchmarks/synth_variants.py --varied-variants 33,34 --variants 33,34 --only $ALL --seeds 1 --json $R/integ34_main_synth_v3334.json > $R/integ34_main_synth_v3334.txt 2>&1
python benchmarks/synth_variants.py --harder --harder-variants 33,34 --only two_sizes,three_sizes,clusters,stones,sparse_voids --seeds 1 --json $R/integ34_main_synth_h3334.json > $R/integ34_main_synth_h3334.txt 2>&1
touch $R/integ34_main_synth_done
python benchmarks/grow_variants.py --varied-variants 33,34 --variants 33,34 --only $ALL --seeds 1 --json $R/integ34_main_grow_v3334.json > $R/integ34_main_grow_v3334.txt 2>&1
python benchmarks/grow_variants.py --harder --harder-variants 33,34 --only two_sizes,three_sizes,clusters --seeds 1 --json $R/integ34_main_grow_h3334.json > $R/integ34_main_grow_h3334.txt 2>&1
touch $R/integ34_main_grow_done
for f in synth_v3334 synth_h3334; do python benchmarks/svar13i_oracle.py $R/integ34_main_$f.json --draws 2 --json $R/integ34_oracle_$f.json > $R/integ34_oracle_$f.txt 2>&1; done
for f in grow_v3334 grow_h3334; do python benchmarks/svar13i_oracle.py $R/integ34_main_$f.json --draws 2 --harder --json $R/integ34_oracle_$f.json > $R/integ34_oracle_$f.txt 2>&1; done
touch $R/integ34_main_all_done
