"""Packing elements on a surface: Poisson disk and fill-gap on a mesh (issue 20, point 3).

Sakurai & Miyata's fill-gap (§4) carried to a surface, with Davison et al.'s bounding
spheres (§5.7) as the exclusive regions:

1. Poisson-disk step (§4.1): a batch of candidate points uniform in area over the
   surface (so uniform in the geodesic metric), each with a kind and a scale; a
   candidate is kept when its bounding sphere overlaps no placed sphere and no earlier
   kept candidate of the batch (sequential dart throwing, compiled).
2. Fill-gap rounds (§4.2): later batches are drawn only on faces that still have room,
   i.e. faces whose centroid lies farther from the nearest placed element than that
   element's radius plus the smallest radius (less the face's own extent). This plays
   the role of the paper's distance field with probability ``d**16``: candidates go
   to the gaps. Rounds stop when no face has room, or after ``max_failures`` rounds in
   a row that place nothing.

Departure from "Poisson disk in geodesic distance": the overlap test uses the chord
(Euclidean) distance between bounding spheres, as Davison et al. do. A chord is never
longer than the geodesic, so geodesic separation holds as well; testing the geodesic
alone would let spheres intersect across thin parts of a mesh.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numba
import numpy as np

from .._errors import InputError
from .._progress import Reporter
from .._rng import as_rng
from .._version import __version__
from ..arrangement import Arrangement
from ..shape import Shape
from ._field import OrientationField, _any_perpendicular, orientation_field
from ._mesh import load_mesh

__all__ = ["pack"]


@numba.njit(cache=True)
def _greedy(n: int, indptr: np.ndarray, indices: np.ndarray) -> np.ndarray:
    """Sequential acceptance in index order: i is kept unless a kept j < i conflicts."""
    keep = np.zeros(n, dtype=np.bool_)
    for i in range(n):
        ok = True
        for k in range(indptr[i], indptr[i + 1]):
            j = indices[k]
            if j < i and keep[j]:
                ok = False
                break
        keep[i] = ok
    return keep


def _shapes(shapes_or_radius: Any) -> dict[str, Shape]:
    if isinstance(shapes_or_radius, bool):
        raise InputError("shapes: expected a radius, a Shape, a list or a mapping of Shapes, got a bool")
    if isinstance(shapes_or_radius, (int, float, np.integer, np.floating)):
        r = float(shapes_or_radius)
        if not np.isfinite(r) or r <= 0:
            raise InputError(f"radius: must be a positive number, got {shapes_or_radius!r}")
        return {"dot": Shape.circle(r)}
    if isinstance(shapes_or_radius, Arrangement):
        out = shapes_or_radius.shapes
    elif isinstance(shapes_or_radius, Shape):
        out = {"shape": shapes_or_radius}
    elif isinstance(shapes_or_radius, Mapping):
        out = dict(shapes_or_radius)
    elif isinstance(shapes_or_radius, Sequence) and not isinstance(shapes_or_radius, str):
        out = {f"shape{i}": s for i, s in enumerate(shapes_or_radius)}
    else:
        raise InputError(f"shapes: expected a radius, a Shape, a list or a mapping of Shapes, got {type(shapes_or_radius).__name__}")
    if not out:
        raise InputError("shapes: no shapes given")
    for k, s in out.items():
        if not isinstance(s, Shape):
            raise InputError(f"shapes.{k}: must be a Shape, got {type(s).__name__}")
        if s.radius <= 0:
            raise InputError(f"shapes.{k}: empty shape (zero bounding radius)")
    return out


def _range(value: Any, name: str) -> tuple[float, float]:
    try:
        lo, hi = (float(value), float(value)) if np.ndim(value) == 0 else (float(value[0]), float(value[1]))
    except (TypeError, ValueError, IndexError):
        raise InputError(f"{name}: expected a number or (lo, hi), got {value!r}") from None
    if not (np.isfinite(lo) and np.isfinite(hi)) or lo <= 0 or hi < lo:
        raise InputError(f"{name}: expected 0 < lo <= hi, got {value!r}")
    return lo, hi


def _conflicts(points: np.ndarray, radii: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """CSR adjacency of candidate pairs whose bounding spheres intersect."""
    from scipy.sparse import coo_matrix
    from scipy.spatial import cKDTree

    n = len(points)
    pairs = cKDTree(points).query_pairs(2.0 * float(radii.max()), output_type="ndarray")
    if len(pairs):
        d = np.linalg.norm(points[pairs[:, 0]] - points[pairs[:, 1]], axis=1)
        pairs = pairs[d < radii[pairs[:, 0]] + radii[pairs[:, 1]]]
    i = np.concatenate([pairs[:, 0], pairs[:, 1]]) if len(pairs) else np.zeros(0, np.int64)
    j = np.concatenate([pairs[:, 1], pairs[:, 0]]) if len(pairs) else np.zeros(0, np.int64)
    csr = coo_matrix((np.ones(len(i), dtype=np.int8), (i, j)), shape=(n, n)).tocsr()
    return csr.indptr.astype(np.int64), csr.indices.astype(np.int64)


def _clear_of(tree: Any, placed_r: np.ndarray, points: np.ndarray, radii: np.ndarray, k: int) -> np.ndarray:
    """Whether each candidate's sphere misses every placed sphere (conservative if crowded)."""
    rmax = float(placed_r.max())
    k = min(k, len(placed_r))
    d, j = tree.query(points, k=k, distance_upper_bound=float(radii.max()) + rmax)
    d = d.reshape(len(points), k)
    j = j.reshape(len(points), k)
    found = np.isfinite(d)
    rj = np.where(found, placed_r[np.minimum(j, len(placed_r) - 1)], 0.0)
    ok = np.all(~found | (d >= radii[:, None] + rj), axis=1)
    if k < len(placed_r):
        ok &= ~found[:, -1]  # all k neighbours within reach: more may hide beyond, refuse
    return ok


def pack(
    shapes_or_radius: Any,
    mesh: Any,
    *,
    field: OrientationField | str | None = "smoothest",
    rotation: str = "field",
    scale: Any = 1.0,
    margin: float = 0.0,
    weights: Sequence[float] | Mapping[str, float] | None = None,
    max_failures: int = 3,
    max_rounds: int = 200,
    rng: int | np.random.Generator | None = None,
    progress: Callable[[int, int | None, str], None] | None = None,
    should_cancel: Callable[[], bool] | None = None,
) -> Arrangement:
    """Pack elements over a surface so that no two bounding spheres overlap.

    Parameters
    ----------
    shapes_or_radius : float, Shape, sequence or mapping of Shape, or Arrangement
        A radius (discs of that radius, kind ``"dot"``) or the element kinds (an
        Arrangement gives its shape library). Each kind's bounding sphere has radius
        ``shape.radius * scale + margin`` about the element's origin.
    mesh : path, trimesh.Trimesh or (vertices, faces)
        The surface (:func:`strew.surface.load_mesh` validates it).
    field : OrientationField, "smoothest" or None
        Orientation of the elements' tangents (§5.7); ``"smoothest"`` computes the
        automatic field, ``None`` takes an arbitrary tangent.
    rotation : {"field", "random"}
        Tangent along the field, or turned about the normal by a uniform random angle.
    scale : float or (lo, hi)
        Uniform scale, or a range drawn uniformly per element.
    margin : float
        Added to every bounding radius (gaps are at least twice the margin).
    weights : sequence or mapping of kind -> float, optional
        Probability of each kind for a candidate (default equal).
    max_failures : int
        Fill-gap rounds in a row that place nothing before stopping.
    max_rounds : int
        Upper bound on rounds.
    rng : int, Generator or None
        Every random choice comes from it.
    progress, should_cancel : callable, optional
        ``progress(done, total, message)`` and a cancellation check.

    Returns
    -------
    Arrangement
        Core columns ``x``, ``y`` (world x, y), ``rotation`` (the tangent's bearing in
        the x-y plane) and ``scale``; 3D columns ``z nx ny nz tx ty tz``, ``radius``
        (bounding sphere) and ``face`` (the mesh face each element lies on).

    Raises
    ------
    InputError
        Bad mesh, radius, scale, weights or options (the message names the field).

    Examples
    --------
    >>> import trimesh
    >>> a = pack(0.1, trimesh.creation.icosphere(subdivisions=3), rng=1)
    >>> len(a) > 100 and {"z", "nx", "tx"} <= set(a.columns)
    True
    """
    from scipy.spatial import cKDTree

    mesh = load_mesh(mesh)
    lib = _shapes(shapes_or_radius)
    kinds = list(lib)
    lo, hi = _range(scale, "scale")
    try:
        margin = float(margin)
    except (TypeError, ValueError):
        raise InputError(f"margin: must be a number, got {margin!r}") from None
    if not np.isfinite(margin):
        raise InputError("margin: must be finite")
    if rotation not in ("field", "random"):
        raise InputError(f"rotation: expected 'field' or 'random', got {rotation!r}")
    for name, v in (("max_failures", max_failures), ("max_rounds", max_rounds)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 1:
            raise InputError(f"{name}: must be a positive integer, got {v!r}")
    if weights is None:
        p_kind = np.full(len(kinds), 1.0 / len(kinds))
    else:
        w = [weights.get(k, 0.0) for k in kinds] if isinstance(weights, Mapping) else list(weights)
        if isinstance(weights, Mapping) and set(weights) - set(kinds):
            raise InputError(f"weights: unknown kind {sorted(set(weights) - set(kinds))[0]!r}")
        try:
            p_kind = np.asarray(w, dtype=float)
        except (TypeError, ValueError):
            raise InputError("weights: must be numbers") from None
        if p_kind.shape != (len(kinds),) or not np.all(np.isfinite(p_kind)) or np.any(p_kind < 0) or p_kind.sum() <= 0:
            raise InputError(f"weights: expected {len(kinds)} non-negative numbers with a positive sum")
        p_kind = p_kind / p_kind.sum()
    base_r = np.array([lib[k].radius for k in kinds])
    r_small = float(base_r[p_kind > 0].min() * lo + margin)
    r_big = float(base_r[p_kind > 0].max() * hi + margin)
    if r_small <= 0:
        raise InputError(f"margin: {margin} leaves no positive bounding radius")
    gen = as_rng(rng)

    V = np.asarray(mesh.vertices, dtype=float)
    F = np.asarray(mesh.faces, dtype=np.int64)
    areas = np.asarray(mesh.area_faces, dtype=float)
    total = float(areas.sum())
    n_est = total / (2.0 * np.sqrt(3.0) * r_small * r_small)  # hexagonal packing of the smallest
    from .._limits import check_elements

    check_elements(int(n_est), "surface pack")
    batch = int(min(max(2000, 1.5 * n_est), 400_000))
    k_nbrs = int(min(64, np.ceil((r_big * 2 / r_small + 1) ** 2)))
    centroids = V[F].mean(axis=1)
    extent = np.linalg.norm(V[F] - centroids[:, None, :], axis=2).max(axis=1)

    pts_l: list[np.ndarray] = []
    rad_l: list[np.ndarray] = []
    face_l: list[np.ndarray] = []
    bary_l: list[np.ndarray] = []
    kind_l: list[np.ndarray] = []
    scale_l: list[np.ndarray] = []
    weight = areas.copy()
    failures = 0
    rounds = 0
    rep = Reporter(progress, should_cancel, total=int(n_est), message="surface pack")
    placed = 0
    tree = None
    placed_r = np.zeros(0)
    for rounds in range(1, max_rounds + 1):
        rep.tick(placed)
        wsum = weight.sum()
        if wsum <= 0:
            break
        faces = gen.choice(len(F), size=batch, p=weight / wsum)
        u = gen.random((batch, 2))
        flip = u.sum(axis=1) > 1.0
        u[flip] = 1.0 - u[flip]
        bary = np.column_stack([1.0 - u[:, 0] - u[:, 1], u[:, 0], u[:, 1]])
        kind = gen.choice(len(kinds), size=batch, p=p_kind).astype(np.int32)
        sc = gen.uniform(lo, hi, size=batch) if hi > lo else np.full(batch, lo)
        radii = base_r[kind] * sc + margin
        pts = np.einsum("mk,mkj->mj", bary, V[F[faces]])
        if tree is not None:
            ok = _clear_of(tree, placed_r, pts, radii, k_nbrs)
            sel = np.flatnonzero(ok)
        else:
            sel = np.arange(batch)
        new = 0
        if len(sel):
            indptr, indices = _conflicts(pts[sel], radii[sel])
            keep = sel[_greedy(len(sel), indptr, indices)]
            new = len(keep)
            pts_l.append(pts[keep])
            rad_l.append(radii[keep])
            face_l.append(faces[keep])
            bary_l.append(bary[keep])
            kind_l.append(kind[keep])
            scale_l.append(sc[keep])
        placed += new
        failures = failures + 1 if new == 0 else 0
        if failures >= max_failures:
            break
        if new == 0:
            continue
        P = np.concatenate(pts_l)
        placed_r = np.concatenate(rad_l)
        tree = cKDTree(P)
        # fill-gap (§4.2): draw the next batch only where a smallest element could fit.
        # Room only shrinks, so only faces that had room are tested, against the new
        # elements of this round.
        active = np.flatnonzero(weight > 0)
        d, j = cKDTree(pts_l[-1]).query(centroids[active])
        full = d + extent[active] < rad_l[-1][j] + r_small
        weight[active[full]] = 0.0
    rep.done(placed)

    if placed:
        P = np.concatenate(pts_l)
        R = np.concatenate(rad_l)
        faces = np.concatenate(face_l)
        bary = np.concatenate(bary_l)
        kind = np.concatenate(kind_l)
        sc = np.concatenate(scale_l)
    else:
        P, R, bary = np.zeros((0, 3)), np.zeros(0), np.zeros((0, 3))
        faces, kind, sc = np.zeros(0, np.int64), np.zeros(0, np.int32), np.zeros(0)
    vn = np.asarray(mesh.vertex_normals, dtype=float)
    normals = np.einsum("mk,mkj->mj", bary, vn[F[faces]])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True).clip(1e-300)
    design: dict[str, Any] = {}
    if isinstance(field, str):
        if field != "smoothest":
            raise InputError(f"field: expected an OrientationField, 'smoothest' or None, got {field!r}")
        field = orientation_field(mesh) if placed else None
        design = {"method": "smoothest"}
    elif field is not None:
        if not isinstance(field, OrientationField):
            raise InputError(f"field: expected an OrientationField, 'smoothest' or None, got {type(field).__name__}")
        if field.directions.shape != (len(V), 3):
            raise InputError(f"field: has {len(field.directions)} directions, the mesh {len(V)} vertices")
        design = field.design
    if field is not None and placed:
        tangents = field.at(faces, bary, normals)
    else:
        tangents = _any_perpendicular(normals) if placed else np.zeros((0, 3))
    if rotation == "random" and placed:
        ang = gen.uniform(0.0, 2.0 * np.pi, size=placed)
        b = np.cross(normals, tangents)
        tangents = np.cos(ang)[:, None] * tangents + np.sin(ang)[:, None] * b
    columns = {
        "z": P[:, 2], "nx": normals[:, 0], "ny": normals[:, 1], "nz": normals[:, 2],
        "tx": tangents[:, 0], "ty": tangents[:, 1], "tz": tangents[:, 2],
        "radius": R, "face": faces.astype(np.int64),
    }
    meta = {
        "generator": f"strew {__version__}",
        "method": "surface.pack",
        "seed": rng if isinstance(rng, (int, np.integer)) else None,
        "params": {
            "scale": [lo, hi], "margin": margin, "rotation": rotation, "weights": p_kind.tolist(),
            "max_failures": int(max_failures), "rounds": int(rounds), "field": design,
        },
        "surface": {"vertices": int(len(V)), "faces": int(len(F)), "area": total,
                    "bounds": np.asarray(mesh.bounds, dtype=float).tolist()},
    }
    return Arrangement(lib, kind, P[:, 0], P[:, 1], np.arctan2(tangents[:, 1], tangents[:, 0]) if placed else None, sc,
                       columns=columns, meta=meta)
