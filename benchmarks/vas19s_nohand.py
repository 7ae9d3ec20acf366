"""Measurement for issue 19.4 (vase, vas19s): ``benchmarks/orn19m_willow.py make`` with
strew.ornament._engine._handed_over turned off (the later tile's rules see the empty
circle itself, not raised to the finished neighbour's handed-over circle). A
measurement of where the tiled vase's border deficit comes from, not a fix: the engine
is not changed.

``python benchmarks/vas19s_nohand.py make --tag vas19s_nohand --tiles 60 --pattern vase
--overlaps``; then ``python benchmarks/vas19s_compare.py vas19s_nohand vas19s_newctl``.
"""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import strew.ornament._engine as E  # noqa: E402

E._handed_over = lambda goal, holes: goal
import orn19m_willow  # noqa: E402

sys.argv = ["orn19m_willow.py", *sys.argv[1:]]
orn19m_willow.main()
