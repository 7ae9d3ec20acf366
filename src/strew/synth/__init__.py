"""Example palettes and fast region-growing synthesis (Davison, Samavati, Jacob 2018).

Discrete element texture synthesis from one or several exemplars held in a
:class:`Palette` (§5.5): per-element radii (§4.1), point-based neighbourhood distance with
greedy pairing (§4, Eq. 1), k-coherence and free-space points (§5.1), region growing
(Algorithm 1) with horizon optimisation (§5.2-5.3), and the tools of §5.4: generative
brush, filler and eraser, which work on a :class:`SynthState` one stroke segment at a time.

Entry points
------------
synthesize
    Exemplars + region (or a fill point, or a brush stroke) -> Arrangement.
new_state, fill, brush, erase, set_selection
    The incremental tools, for the studio.
Palette, load_palette, save_palette, palette_document, split_palette_document
    Example palettes, and the palette document (exemplars side by side) they are saved as.
average_neighborhood_distance, energy
    The measures of Eq. 5 and Eq. 2.

Departures from the paper (each is commented where it is made): pairing is tested on
|dp|; the ratio test's inequality reads the other way round (as printed it vetoes
every candidate); a relative kind-mismatch cost; a learned closest approach per kind
pair; a sparse LU solve with a symmetric ordering instead of a sparse Cholesky; visible
elements are placed before voids and evict the voids they land on (§5.6), which brings
the visible density to the exemplar's; while brushing, the horizon that is optimised is
the part within r-bar of the iteration's new elements (§5.2, "recently synthesized");
in near-regular exemplars each optimisation move is shortened by the spread of the
element's own predictions (at most 0.1 of its radius and 0.3 of the exemplar's spacing
slack), so that the least-squares blend does not average the exemplar's jitter away
(§5.2-5.3, ``noise_floor``); in jittered lattices (noisy rows, bricks, scales) each
prediction vector instead carries the jitter of the output elements it relates, read
from the exemplar's bond modes, so that predictions agree and the blend keeps the
jitter (§5.2-5.3, ``_optimize._own_jitter``); elements of exemplars outside the
selection do not move.

Extensions for exemplars with elements of several sizes, which §7 names a limitation
(each is commented where it is made; see ``_grow`` and ``_prepare``): radii at least 2x
apart form size classes; the copies of all seeds are placed larger classes first;
horizon elements of the last 2 iterations yield to a new element of a larger class
while the output owes that class its exemplar share (within 2 standard errors);
a small element is copied only with the larger element it leans on (its nearest larger
Delaunay neighbour in the exemplar), so a neighbourhood's rim does not scatter orphans;
the closest approach of two kinds is learned over the whole exemplar, not only within
neighbourhoods; k-coherence sets hold elements of the element's own size class; a
child whose parent is paired with an output element is placed from that element, and
not at all when that element is of a smaller class; elements whose parent the frame
may have cut off are never copied beside a candidate; a larger class whose spacing
lies beyond the default r-bar's reach sees 1.5 times its spacing (``_palette``).
Within a size class, a kind at least 3x rarer than the most common (a ring's hub) is an
anchor: its copies are placed first, the other kinds lean on it as on a parent (a ring
is copied only with its hub, never around an output element of another kind), a child
proposed beside an output anchor takes the slot of the exemplar ring that anchor was
copied as (one phase per ring), and anchors whose children the frame cut off are not
copied beside a candidate (``_grow.anchors``, ``_prepare.parents``); at the end of a
growth each new anchor's children are put back on its exemplar ring's slots and its
empty slots filled where nothing is in the way (``_grow._complete_anchor_rings``); a new
anchor beside a copy of its own exemplar anchor first takes another exemplar anchor of as
many children that none beside it repeats, its ring turned onto that anchor's slots where
they are clear, so neighbouring rings do not turn in lockstep (``_spread_ring_sources``).
A growth ends by putting into each empty circle of the output wider than the
exemplar's largest the exemplar element that fits there and whose neighbourhood matches
best (Eq. 1 over the whole selection; ``_grow.fill_holes``).
``context`` elements are frozen, already-synthesized neighbours (``_context``). The bounding radius of §4.1 is the collision bound wherever the
exemplar gives it; default radii shrink per kind to the exemplar's spacing, and where
they shrink below 0.9 of the bounding radius (elongated shapes) the shapes themselves
are tested while growing and after optimising (``_shapes``); kinds next to another size
class keep 0.95 of the exemplar's gap between their discs (``collision_radii``). While
brushing, seeds whose copies lie beyond the discs reached so far do not count as
failures. A fill with several exemplars selected deals Voronoi cells of the region to
them by weight (§5.5 extension), or puts each where ``{name: Region}`` (CLI
``--select NAME=REGION``) says.
"""

from __future__ import annotations

from ._compare import compare_methods, plot_traces
from ._stroke import brush_points, read_stroke
from ._overlap import drop_new_overlaps
from ._api import SPEC, as_selection, new_state, set_selection, synthesize
from ._grow import brush, erase, fill, grow, seed_patch
from ._metric import average_neighborhood_distance, energy, neighborhood_distances
from ._optimize import optimize
from ._palette import Palette, Selection, element_parameters, load_palette, palette_document, save_palette, split_palette_document
from ._patch import patch_initialize
from ._prepare import Prepared, prepare
from ._state import SynthParams, SynthState

__all__ = [
    "SPEC",
    "synthesize",
    "new_state",
    "set_selection",
    "as_selection",
    "fill",
    "brush",
    "erase",
    "grow",
    "seed_patch",
    "optimize",
    "patch_initialize",
    "Palette",
    "Selection",
    "load_palette",
    "save_palette",
    "palette_document",
    "split_palette_document",
    "element_parameters",
    "prepare",
    "Prepared",
    "SynthParams",
    "SynthState",
    "average_neighborhood_distance",
    "energy",
    "neighborhood_distances",
    "compare_methods",
    "plot_traces",
    "read_stroke",
    "brush_points",
    "drop_new_overlaps",
]
