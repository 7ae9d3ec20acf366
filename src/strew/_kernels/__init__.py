"""The kernel floor: compiled loops that several methods share (issue 15 point 5).

One module per concern, each small and free of any method's vocabulary:

``geometry``
    point-segment distance, segment intersection with a robust tolerance, even-odd
    point-in-rings tests on a flat ring layout.
``prng``
    the one compiled random stream (xoshiro256+), seeded from the caller's
    ``numpy.random.Generator``.
``raster``
    the one scanline rasteriser (even-odd fill of ring edges at pixel centres) and the
    exact Euclidean distance transforms (why compiled and not scipy's: see its
    docstring).
``grid``
    the uniform bucket grid over points (built once) and the one incremental grid:
    hashed, unbounded cells whose items (points or boxes) may move and leave
    (pack's placed regions and domain edges, ornament's placed elements, grow's points
    and edges).

The kernels are numba functions compiled with ``cache=True``; small helpers carry no
Python wrapper (``no_cpython_wrapper``), so that a method's first run compiles no more
than it did when each method held its own copy (issue 16). Import the submodule you
need (``from strew._kernels.grid import bucket_grid``); this package imports nothing.
"""
