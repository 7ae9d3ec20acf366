"""Which keep rule keeps tile 10's rows past its border in a tiled vase world, tile 48, seed 1
(helper w25, issue 19.4): rows of tile 10 at 80 < y < 96 (tile 6's side) placed before and after
strew.ornament._context.keep_ancestors in strew.tiles._keep_groups.

``PYTHONPATH=src python benchmarks/w25_keep.py`` (h/w25: before 0, after 8, kept 8: keep_ancestors)
"""

import numpy as np, strew.tiles as T, strew.ornament._context as C
ok=C.keep_ancestors; ow=C.keep_whole
def ka(el,parent,grp,placed,far):
    out=ok(el,parent,grp,placed,far)
    ka.last=(placed.copy(),out.copy()); return out
C.keep_ancestors=ka
orig=T._keep_groups
def kg(arr,keep,t,job,links):
    out=orig(arr,keep,t,job,links)
    if t.index==10:
        y=np.asarray(arr.y); x=np.asarray(arr.x); m=(y<96)&(y>80)&(x>96)&(x<144)
        p0,p1=ka.last
        print("tile10 rows y in 80..96:",m.sum(),"placed before keep_ancestors",int((p0&m).sum()),"after",int((p1&m).sum()),"final kept",int((out&m).sum()),flush=True)
    return out
T._keep_groups=kg
T.tiled("ornament","vase",(192.,192.),tile_size=48.,seed=1)
