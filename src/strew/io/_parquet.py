"""Worlds as partitioned Parquet datasets (issue 19 point 3), through pyarrow.

A dataset is a folder: ``part-NNNNNN.parquet`` per tile (columns ``tile`` int32,
``kind`` dictionary<string>, ``x``, ``y``, ``rotation``, ``scale`` float64, the
arrangement's numeric and text extra columns, and ``parts``, each element's own
geometry as JSON text, where it has one: ornament) and ``_common_metadata``, whose schema metadata
holds ``strew`` = JSON ``{"shapes": {name: shape}, "meta": {...}, "region": ...}``.
pandas (``pd.read_parquet(folder)``), DuckDB (``read_parquet('folder/*.parquet')``) and
GeoPandas-by-way-of-pandas read it as it is; :func:`iter_parquet_tiles` streams it back
as arrangements, one tile at a time.
"""

from __future__ import annotations

import json
import os
import shutil
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from .._errors import InputError

__all__ = ["ParquetWriter", "iter_parquet_tiles", "table_to_arrangement", "TEXT_LIMIT", "parquet_info", "parquet_summary", "load_parquet", "is_dataset", "LOAD_LIMIT"]

#: largest dataset :func:`load_parquet` reads into one Arrangement
LOAD_LIMIT = 2_000_000
#: largest world written as SVG or JSON (``strew render world.parquet --out x.svg``):
#: about 100-300 bytes an element, so at most a few hundred MB of text
TEXT_LIMIT = 1_000_000

_HINT = "pip install 'strew[distributed]'"
_CORE = ("x", "y", "rotation", "scale")
PARTS_COLUMN = "parts"


def _pa() -> Any:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise InputError(f"--out: writing Parquet needs pyarrow: {_HINT}") from None
    return pa, pq


def is_dataset(path: str | os.PathLike[str]) -> bool:
    """Whether ``path`` is a strew Parquet dataset folder."""
    p = Path(path)
    return p.is_dir() and (p / "_common_metadata").is_file()


class ParquetWriter:
    """Writes one file per tile; :meth:`close` writes the metadata and publishes it.

    Parameters
    ----------
    folder : path
        The dataset folder; an existing strew dataset there is replaced on
        :meth:`close`, anything else is refused.
    """

    def __init__(self, folder: str | os.PathLike[str]) -> None:
        self.pa, self.pq = _pa()
        self.target = Path(folder)
        if self.target.exists() and not is_dataset(self.target):
            raise InputError(f"--out: {self.target} exists and is not a strew Parquet dataset")
        # tiles go to NAME.partial/ (made on the first tile), renamed by close(): a failed
        # or interrupted run leaves the old dataset, or nothing, at the target
        self.folder = self.target.with_name(self.target.name + ".partial")
        self.kinds: list[str] | None = None
        self.extra: dict[str, Any] = {}

    def _schema(self) -> Any:
        pa = self.pa
        fields = [pa.field("tile", pa.int32()), pa.field("kind", pa.dictionary(pa.int32(), pa.string()))]
        fields += [pa.field(c, pa.float64()) for c in _CORE]
        fields += [pa.field(c, t) for c, t in sorted(self.extra.items())]
        return pa.schema(fields)

    def write(self, index: int, arr: Any) -> None:
        """Write tile ``index`` (an Arrangement; numeric extra columns are kept)."""
        pa, pq = self.pa, self.pq
        if self.kinds is None:
            self.kinds = list(arr.shapes)
        kinds = self.kinds
        if list(arr.shapes) != kinds:
            raise InputError(f"tile {index}: its kinds {list(arr.shapes)} differ from the dataset's {kinds}")
        cols: dict[str, Any] = {
            "tile": pa.array(np.full(len(arr), index, np.int32)),
            "kind": pa.DictionaryArray.from_arrays(pa.array(arr.kind.astype(np.int32)), pa.array(kinds, pa.string())),
        }
        for c in _CORE:
            cols[c] = pa.array(np.asarray(getattr(arr, c), np.float64))
        for c, v in arr.columns.items():
            if c == "tile":
                continue
            if c == PARTS_COLUMN:  # per-element geometry (ornament): JSON text, null where none
                cols[c] = pa.array([None if p is None else json.dumps(p, separators=(",", ":")) for p in v], pa.string())
            elif v.dtype.kind in "biuf":
                cols[c] = pa.array(np.asarray(v))
            elif v.dtype.kind in "UO" and all(e is None or isinstance(e, str) for e in v):
                cols[c] = pa.array(v.tolist(), pa.string())
            else:
                continue  # other objects do not go to Parquet
            self.extra.setdefault(c, cols[c].type)
        for c, typ in self.extra.items():  # a column the first tiles had and this one lacks: nulls
            if c not in cols:
                cols[c] = pa.nulls(len(arr), typ)
        table = pa.table(cols)
        if not self.folder.is_dir():
            if self.folder.exists():
                shutil.rmtree(self.folder)
            self.folder.mkdir(parents=True)
        pq.write_table(table, self.folder / f"part-{index:06d}.parquet", compression="zstd")

    def close(self, shapes: Mapping[str, Any], meta: Mapping[str, Any], region: Any = None) -> Path:
        """Write ``_common_metadata`` (shapes, meta, region) and return the folder."""
        doc = {
            "format": "strew-parquet-1",
            "shapes": {k: s.to_dict() for k, s in shapes.items()},
            "meta": dict(meta),
            "region": region.to_dict() if region is not None else None,
        }
        text = json.dumps(doc, sort_keys=True, default=str)
        schema = self._schema().with_metadata({"strew": text})
        self.folder.mkdir(parents=True, exist_ok=True)
        self.pq.write_metadata(schema, self.folder / "_common_metadata")
        if self.target.exists():
            shutil.rmtree(self.target)
        self.folder.rename(self.target)
        return self.target

    def abort(self) -> None:
        """Remove the partial dataset."""
        if self.folder.exists():
            shutil.rmtree(self.folder)


def _doc(folder: Path) -> dict[str, Any]:
    _, pq = _pa()
    if not is_dataset(folder):
        raise InputError(f"{folder}: not a strew Parquet dataset (no _common_metadata)")
    md = pq.read_schema(folder / "_common_metadata").metadata or {}
    if b"strew" not in md:
        raise InputError(f"{folder.name}: its _common_metadata holds no strew entry")
    return json.loads(md[b"strew"])


def parquet_info(folder: str | os.PathLike[str]) -> dict[str, Any]:
    """Shapes, meta, element and tile counts, read from the footers only (no element data).

    Returns
    -------
    dict
        ``{"shapes": {...}, "meta": {...}, "region": ..., "elements": n, "tiles": k}``.
    """
    _, pq = _pa()
    folder = Path(folder)
    doc = _doc(folder)
    parts = sorted(folder.glob("part-*.parquet"))
    doc["elements"] = int(sum(pq.ParquetFile(p).metadata.num_rows for p in parts))
    doc["tiles"] = len(parts)
    return doc


def parquet_summary(folder: str | os.PathLike[str]) -> dict[str, Any]:
    """Counts per kind, bounds of the centres and the world's meta, reading only the
    ``kind``, ``x`` and ``y`` columns one record batch at a time (``strew info world.parquet``)."""
    _, pq = _pa()
    folder = Path(folder)
    info = parquet_info(folder)
    counts = dict.fromkeys(info["shapes"], 0)
    lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
    for p in sorted(folder.glob("part-*.parquet")):  # row group by row group: memory is one batch
        for t in pq.ParquetFile(p).iter_batches(batch_size=65536, columns=["kind", "x", "y"]):
            if len(t) == 0:
                continue
            kind = t.column("kind")
            names = kind.dictionary.to_pylist()
            for k, c in zip(*np.unique(kind.indices.to_numpy(zero_copy_only=False), return_counts=True)):
                counts[names[k]] = counts.get(names[k], 0) + int(c)
            xy = np.c_[t.column("x").to_numpy(), t.column("y").to_numpy()]
            lo, hi = np.minimum(lo, xy.min(axis=0)), np.maximum(hi, xy.max(axis=0))
    n = max(info["elements"], 1)
    return {
        "elements": info["elements"], "tiles": info["tiles"], "counts": counts,
        "kind_fractions": {k: c / n for k, c in counts.items()},
        "centre_bounds": [float(v) for v in (*lo, *hi)] if info["elements"] else None,
        "meta": info["meta"],
    }


def table_to_arrangement(t: Any, shapes: Mapping[str, Any]) -> Any:
    """An Arrangement of the rows of a pyarrow table of this format (a file, or a
    filtered scan of the dataset), with ``shapes`` as its library."""
    from ..arrangement import Arrangement

    pa, _ = _pa()
    names = list(shapes)
    where = {k: i for i, k in enumerate(names)}
    pieces = [np.zeros(0, np.int64)]
    for chunk in t.column("kind").chunks:  # the files of a scan each have their own dictionary
        lookup = np.array([where[k] for k in chunk.dictionary.to_pylist()] + [0], np.int64)
        pieces.append(lookup[chunk.indices.to_numpy(zero_copy_only=False)])
    idx = np.concatenate(pieces)
    extra: dict[str, Any] = {}
    for c in t.column_names:
        if c in ("kind", *_CORE):
            continue
        col = t.column(c)
        if c == PARTS_COLUMN:
            extra[c] = [None if v is None else json.loads(v) for v in col.to_pylist()]
        elif col.type == pa.string():
            extra[c] = np.array(col.to_pylist(), dtype=object)
        else:
            extra[c] = col.to_numpy()
    return Arrangement(dict(shapes), idx, *(np.asarray(t.column(c).to_numpy(), np.float64) for c in _CORE), columns=extra)


def iter_parquet_tiles(folder: str | os.PathLike[str]) -> Iterator[Any]:
    """The dataset's tiles as Arrangements, one file at a time, in tile order."""
    from ..shape import Shape

    _, pq = _pa()
    folder = Path(folder)
    doc = _doc(folder)
    shapes = {k: Shape.from_dict(v) for k, v in doc["shapes"].items()}
    for p in sorted(folder.glob("part-*.parquet")):
        yield table_to_arrangement(pq.read_table(p), shapes)


def load_parquet(folder: str | os.PathLike[str], *, max_elements: int = LOAD_LIMIT) -> Any:
    """The whole dataset as one Arrangement, if it holds at most ``max_elements``."""
    from ..arrangement import concat
    from ..region import Region

    info = parquet_info(folder)
    if info["elements"] > max_elements:
        raise InputError(f"{Path(folder).name}: {info['elements']:,} elements is too many to load whole "
                         f"(limit {max_elements:,}); stream it with strew.io.iter_parquet_tiles or read it with pandas/DuckDB")
    region = Region.from_dict(info["region"]) if info.get("region") else None
    tiles = [a for a in iter_parquet_tiles(folder) if len(a)]
    if not tiles:
        from ..arrangement import Arrangement
        from ..shape import Shape

        shapes = {k: Shape.from_dict(v) for k, v in info["shapes"].items()}
        return Arrangement(shapes, [], [], [], region=region, meta=info["meta"])
    return concat(tiles).replace(region=region, meta=info["meta"])
