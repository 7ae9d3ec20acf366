cd /tmp/s59/S3
R=/work/wt_integ34/benchmarks/results
ALL=hex_lattice,bricks,clusters,rings,rows_noisy,scales,sparse_voids,sticks,stones,stripes,three_sizes,two_sizes
export PYTHONPATH=src:benchmarks
python benchmarks/synth_variants.py --varied-variants 33,34 --variants 33,34 --only $ALL --seeds 1 --json $R/integ34_S3_synth_v3334.json > $R/integ34_S3_synth_v3334.txt 2>&1
python benchmarks/synth_variants.py --harder --harder-variants 33,34 --only two_sizes,three_sizes,clusters,stones,sparse_voids --seeds 1 --json $R/integ34_S3_synth_h3334.json > $R/integ34_S3_synth_h3334.txt 2>&1
python benchmarks/grow_variants.py --varied-variants 33,34 --variants 33,34 --only $ALL --seeds 1 --json $R/integ34_S3_grow_v3334.json > $R/integ34_S3_grow_v3334.txt 2>&1
python benchmarks/grow_variants.py --harder --harder-variants 33,34 --only two_sizes,three_sizes,clusters --seeds 1 --json $R/integ34_S3_grow_h3334.json > $R/integ34_S3_grow_h3334.txt 2>&1
touch $R/integ34_S3_fresh_done
python benchmarks/fresh17_rows.py synth three_sizes:p2s34,three_sizes:p2s32 1-6 > $R/integ34_S3_six_synth.txt 2>&1
python benchmarks/fresh17_rows.py grow two_sizes:p2s33 1-6 > $R/integ34_S3_six_grow.txt 2>&1
for v in 31,32 29,30; do t=${v/,/}
python benchmarks/synth_variants.py --varied-variants $v --variants $v --only $ALL --seeds 1 --json $R/integ34_S3_synth_v$t.json > $R/integ34_S3_synth_v$t.txt 2>&1
python benchmarks/synth_variants.py --harder --harder-variants $v --only two_sizes,three_sizes,clusters,stones,sparse_voids --seeds 1 --json $R/integ34_S3_synth_h$t.json > $R/integ34_S3_synth_h$t.txt 2>&1
done
touch $R/integ34_S3_done
