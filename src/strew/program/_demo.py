"""Gallery section: the example scripts of ``examples/program`` (Loi et al. figures)."""

from __future__ import annotations

import runpy

import numpy as np

from .._resources import examples_dir
from .._demo_item import DemoItem
from ._script import run_script


def items(rng: np.random.Generator) -> list[DemoItem]:
    """One picture per panel of every ``examples/program/fig*.py`` script.

    A script lists its panels in ``demo_panels`` (module-level variables, default
    ``["arrangement"]``) and its gallery size in ``demo_size`` (default 1000).
    """
    seed = int(rng.integers(0, 2**31))
    out = []
    for script in sorted((examples_dir() / "program").glob("fig*.py")):
        info = runpy.run_path(str(script))
        doc = (info.get("__doc__") or "").strip().splitlines()
        title = doc[0].rstrip(".") if doc else script.stem
        size = float(info.get("demo_size", 1000))
        for name in info.get("demo_panels", ["arrangement"]):
            pm, arr = run_script(script, size=size, seed=seed, name=name)
            out.append(
                DemoItem(
                    name=f"program-{script.stem}-{name}".replace("_", "-"),
                    title=f"{title} ({name})" if name != "arrangement" else title,
                    arrangement=arr,
                    description=(
                        f"strew run {script.name} --name {name} --size {size:g} --seed {seed}: "
                        f"{pm.n_vertices} vertices, {pm.n_edges} edges, {pm.n_faces - 1} bounded faces."
                    ),
                )
            )
    return out
