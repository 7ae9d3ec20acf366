"""``benchmarks/orn19m_willow.py`` with the ornament hand-over of dropped room turned off
(strew.tiles._ornament_holes hands nothing over, as before orn19n): the control for issue
19.4's dots and hierarchy strips. ``PYTHONPATH=TREE/src python benchmarks/dot19r_noholes.py
make --tag TAG --tiles 100 --pattern dots`` (the same arguments as orn19m_willow.py).
On dots this grows the same world as 8224b5f (tile 100, seed 1: the same x, 7,872 elements).
"""

import runpy
from pathlib import Path

if __name__ == "__main__":
    import strew.tiles as T

    T._ornament_holes = lambda *a, **k: []
    runpy.run_path(str(Path(__file__).resolve().parent / "orn19m_willow.py"), run_name="__main__")
