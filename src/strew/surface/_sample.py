"""Packing elements on a surface: Poisson disk and fill-gap on a mesh (issue 20, point 3).

Sakurai & Miyata's fill-gap (§4) carried to a surface, with Davison et al.'s bounding
spheres (§5.7) as the exclusive regions:

1. Free-space points (Davison et al. §5.1): samples uniform in area over the surface
   (so uniform in the geodesic metric), about 6 per ``r_small**2``, ``r_small`` the
   smallest bounding radius.
2. Poisson-disk step (§4.1): the free-space points in random order, each with a random
   kind and scale, are darts; one is placed when its bounding sphere meets no placed
   sphere, earlier darts included (sequential dart throwing, compiled, on a grid).
3. Fill-gap rounds (§4.2): free-space points where a sphere of the smallest radius no
   longer fits are removed; the rest are thrown again with fresh kinds and scales, so
   every round throws only into the gaps (the role of the paper's distance field with
   probability ``d**16``). Rounds stop when no free-space point is left, or after
   ``max_failures`` rounds in a row that place nothing. The packing is maximal up to the
   resolution of the free-space points.

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
from .._method import as_shapes
from .._limits import check_elements
from .._progress import Reporter
from .._rng import as_rng
from .._version import __version__
from ..arrangement import Arrangement
from ..shape import Shape
from ._field import OrientationField, _any_perpendicular, orientation_field
from ._mesh import load_mesh

__all__ = ["pack"]


@numba.njit(cache=True)
def _cell(p: np.ndarray, origin: np.ndarray, h: float, dims: np.ndarray) -> tuple[int, int, int]:
    out = np.empty(3, dtype=np.int64)
    for a in range(3):
        c = int((p[a] - origin[a]) / h)
        out[a] = min(max(c, 0), dims[a] - 1)
    return out[0], out[1], out[2]


@numba.njit(cache=True)
def _hits(q: np.ndarray, rq: float, P: np.ndarray, R: np.ndarray, heads: np.ndarray, nxt: np.ndarray,
          origin: np.ndarray, h: float, dims: np.ndarray) -> bool:
    """Whether the sphere (q, rq) meets a placed sphere (the grid's cells are >= rq + max R)."""
    cx, cy, cz = _cell(q, origin, h, dims)
    for ix in range(max(cx - 1, 0), min(cx + 2, dims[0])):
        for iy in range(max(cy - 1, 0), min(cy + 2, dims[1])):
            for iz in range(max(cz - 1, 0), min(cz + 2, dims[2])):
                j = heads[(ix * dims[1] + iy) * dims[2] + iz]
                while j >= 0:
                    d0 = q[0] - P[j, 0]
                    d1 = q[1] - P[j, 1]
                    d2 = q[2] - P[j, 2]
                    lim = rq + R[j]
                    if d0 * d0 + d1 * d1 + d2 * d2 < lim * lim:
                        return True
                    j = nxt[j]
    return False


@numba.njit(cache=True)
def _covered(Q: np.ndarray, rq: float, P: np.ndarray, R: np.ndarray, heads: np.ndarray, nxt: np.ndarray,
             origin: np.ndarray, h: float, dims: np.ndarray) -> np.ndarray:
    """For each free-space point, whether a sphere of radius rq there would meet a placed one."""
    out = np.zeros(len(Q), dtype=np.bool_)
    for i in range(len(Q)):
        out[i] = _hits(Q[i], rq, P, R, heads, nxt, origin, h, dims)
    return out


@numba.njit(cache=True)
def _throw(C: np.ndarray, rc: np.ndarray, n: int, P: np.ndarray, R: np.ndarray, heads: np.ndarray, nxt: np.ndarray,
           origin: np.ndarray, h: float, dims: np.ndarray) -> np.ndarray:
    """Sequential dart throwing: candidate i is placed unless its sphere meets a placed one
    (earlier candidates included). Placed spheres go to P[n:], R[n:]; returns the mask."""
    keep = np.zeros(len(C), dtype=np.bool_)
    for i in range(len(C)):
        if _hits(C[i], rc[i], P[:n], R[:n], heads, nxt, origin, h, dims):
            continue
        keep[i] = True
        for a in range(3):
            P[n, a] = C[i, a]
        R[n] = rc[i]
        cx, cy, cz = _cell(C[i], origin, h, dims)
        c = (cx * dims[1] + cy) * dims[2] + cz
        nxt[n] = heads[c]
        heads[c] = n
        n += 1
    return keep


def _shapes(shapes_or_radius: Any) -> dict[str, Shape]:
    if isinstance(shapes_or_radius, bool):
        raise InputError("shapes: expected a radius, a Shape, a list or a mapping of Shapes, got a bool")
    if isinstance(shapes_or_radius, (int, float, np.integer, np.floating)):
        r = float(shapes_or_radius)
        if not np.isfinite(r) or r <= 0:
            raise InputError(f"radius: must be a positive number, got {shapes_or_radius!r}")
        return {"dot": Shape.circle(r)}
    out = as_shapes(shapes_or_radius.shapes if isinstance(shapes_or_radius, Arrangement) else shapes_or_radius)
    for k, s in out.items():
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
    check_elements(int(n_est), "surface pack")
    # free-space samples per round: about 6 per r_small^2 of the area that still has room
    density = 6.0 / (r_small * r_small)

    # the compiled grid: cells at least as wide as two of the largest spheres
    lo_c = V.min(axis=0)
    span = np.maximum(V.max(axis=0) - lo_c, 1e-12)
    h = max(2.0 * r_big, float(span.max()) / 128.0)
    dims = np.maximum(np.ceil(span / h).astype(np.int64), 1)
    heads = np.full(int(np.prod(dims)), -1, dtype=np.int64)
    cap = int(2 * n_est) + 1024
    P = np.zeros((cap, 3))
    R = np.zeros(cap)
    nxt = np.full(cap, -1, dtype=np.int64)

    # free-space points (Davison §5.1): samples uniform in area, about 6 per r_small^2
    m = int(min(max(2000, density * total), 4_000_000))
    q_face = gen.choice(len(F), size=m, p=areas / total)
    u = gen.random((m, 2))
    flip = u.sum(axis=1) > 1.0
    u[flip] = 1.0 - u[flip]
    q_bary = np.column_stack([1.0 - u[:, 0] - u[:, 1], u[:, 0], u[:, 1]])
    q_pts = np.einsum("mk,mkj->mj", q_bary, V[F[q_face]])
    free = np.arange(m)

    face_l: list[np.ndarray] = []
    bary_l: list[np.ndarray] = []
    kind_l: list[np.ndarray] = []
    scale_l: list[np.ndarray] = []
    failures = 0
    rounds = 0
    rep = Reporter(progress, should_cancel, total=int(n_est), message="surface pack")
    placed = 0
    for rounds in range(1, max_rounds + 1):
        rep.tick(placed)
        if placed:
            # fill-gap (§4.2): only points where a sphere of the smallest radius still
            # fits stay candidates, so every round throws into the gaps
            free = free[~_covered(q_pts[free], r_small, P[:placed], R[:placed], heads, nxt, lo_c, h, dims)]
        if len(free) == 0:
            break
        sel = free[gen.permutation(len(free))]
        kind = gen.choice(len(kinds), size=len(sel), p=p_kind).astype(np.int32)
        sc = gen.uniform(lo, hi, size=len(sel)) if hi > lo else np.full(len(sel), lo)
        radii = base_r[kind] * sc + margin
        if placed + len(sel) > cap:
            cap = placed + len(sel)
            P = np.concatenate([P, np.zeros((cap - len(P), 3))])
            R = np.concatenate([R, np.zeros(cap - len(R))])
            nxt = np.concatenate([nxt, np.full(cap - len(nxt), -1, dtype=np.int64)])
        keep = _throw(q_pts[sel], radii, placed, P, R, heads, nxt, lo_c, h, dims)
        new = int(keep.sum())
        if new:
            face_l.append(q_face[sel[keep]])
            bary_l.append(q_bary[sel[keep]])
            kind_l.append(kind[keep])
            scale_l.append(sc[keep])
        placed += new
        failures = failures + 1 if new == 0 else 0
        if failures >= max_failures:
            break
    rep.done(placed)

    P, R = P[:placed], R[:placed]
    if placed:
        faces = np.concatenate(face_l)
        bary = np.concatenate(bary_l)
        kind = np.concatenate(kind_l)
        sc = np.concatenate(scale_l)
    else:
        bary = np.zeros((0, 3))
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
