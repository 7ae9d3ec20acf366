"""SVG export: one ``<symbol>`` per kind, one ``<use>`` per element, a layer per kind.

The output opens in Inkscape (each kind is a layer, each element a clone of its symbol)
and in browsers. Element ``i`` is written as::

    <use xlink:href="#k-NAME" transform="translate(x y) rotate(deg) scale(s)"/>

which is the strew transform convention. ``meta`` goes into ``<metadata>`` as JSON (the RDF ``dc:description`` with id ``strew-meta``),
the region into a layer ``strew-region``, and scalar extra columns into ``data-*``
attributes so that :func:`strew.io.svg.read_svg` can bring them back.
"""

from __future__ import annotations

import json
import math
import re
from typing import Any
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from .._periodic import frame, images
from .._errors import InputError
from ..arrangement import Arrangement
from ..shape import Shape

__all__ = ["to_svg", "path_data", "kind_id", "SVG_NS", "STREW_NS"]

SVG_NS = "http://www.w3.org/2000/svg"
XLINK_NS = "http://www.w3.org/1999/xlink"
INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
STREW_NS = "urn:strew:document"
RDF_NS = "http://www.w3.org/1999/02/22-rdf-syntax-ns#"
CC_NS = "http://creativecommons.org/ns#"
DC_NS = "http://purl.org/dc/elements/1.1/"

DEFAULT_AREA_STYLE = {"fill": "#8a8f99", "stroke": "#2b2f36"}
DEFAULT_LINE_STYLE = {"fill": "none", "stroke": "#2b2f36"}


def _num(v: float) -> str:
    """Compact number text with about 10 significant digits (positions to ~1e-6)."""
    v = float(v)
    if v == 0:
        return "0"
    s = format(v, ".10g")
    if "e" in s:
        s = format(v, ".12f").rstrip("0").rstrip(".")
    return s


def path_data(shape: Shape) -> str:
    """SVG path data of a shape: its exact ``d`` when kept, else its polylines."""
    if shape.d:
        return shape.d
    parts = []
    for p in shape.paths:
        if len(p.points) == 0:
            continue
        pts = p.points
        seg = "M" + " L".join(f"{_num(x)},{_num(y)}" for x, y in pts)
        if p.closed:
            seg += " Z"
        parts.append(seg)
    return " ".join(parts)


def kind_id(name: str, index: int) -> str:
    """A valid, unique XML id for a kind's symbol."""
    safe = re.sub(r"[^A-Za-z0-9_.-]", "_", name)
    return f"k{index}-{safe}"


def _style_attrs(shape: Shape, *, inherit_fill: bool, stroke_width: float) -> str:
    has_area = shape.has_area
    style = dict(DEFAULT_AREA_STYLE if has_area else DEFAULT_LINE_STYLE)
    style["stroke_width"] = stroke_width
    style.update(shape.style)
    attrs = []
    for key, val in style.items():
        if key == "fill" and inherit_fill and has_area:
            continue
        attrs.append(f"{key.replace('_', '-')}={quoteattr(str(val))}")
    if has_area:
        attrs.append('fill-rule="evenodd"')
    attrs.append('stroke-linejoin="round"')
    return " ".join(attrs)


def _column_attr_values(arr: Arrangement) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for name, col in arr.columns.items():
        if col.ndim != 1 or not re.fullmatch(r"[a-z_][a-z0-9_.-]*", name) or name in {"kind", "index", "parts"}:
            continue
        vals = []
        for v in col.tolist():
            if isinstance(v, float) and not math.isfinite(v):
                v = None
            vals.append(json.dumps(v))
        out[name] = vals
    return out


def _repeat_counts(repeat: Any) -> tuple[int, int]:
    """``(n, m)`` copies across and down from ``(n, m)`` or ``"NxM"``; at least 1 each."""
    if isinstance(repeat, str):
        parts = repeat.lower().split("x")
        try:
            if len(parts) != 2:
                raise ValueError
            n, m = int(parts[0]), int(parts[1])
        except ValueError:
            raise InputError(f"repeat: expected NxM (copies across x down, e.g. 3x3), got {repeat!r}") from None
    else:
        try:
            n, m = (int(v) for v in repeat)
        except (TypeError, ValueError):
            raise InputError(f"repeat: expected (n, m), got {repeat!r}") from None
    if n < 1 or m < 1:
        raise InputError(f"repeat: needs at least 1x1 copies, got {n}x{m}")
    if n * m > 10_000:
        raise InputError(f"repeat: at most 10000 copies, got {n}x{m}")
    return n, m


def to_svg(
    arr: Arrangement,
    *,
    width: float | None = None,
    margin: float = 0.02,
    background: str | None = None,
    show_region: bool = True,
    show_guides: bool = True,
    stroke_width: float | None = None,
    repeat: Any = None,
    height: float | None = None,
    tile_pixels: tuple[int, int] | None = None,
) -> str:
    """SVG text for an arrangement.

    A periodic arrangement (``meta["periodic"]``, issue 18) is drawn as its tile: the page
    is the tile (no margin, no region outline, which would draw a seam), each element
    once in its kind's layer, and the parts of elements that wrap in at the opposite
    edges as clones in a layer ``strew-wrap`` (SVG import skips it), all clipped to the
    tile. With ``repeat``, the page instead repeats the tile ``n x m`` times through an
    SVG ``<pattern>`` (``id="strew-pattern"``, ``patternUnits="userSpaceOnUse"``, one
    tile wide and high) filling a rectangle; Inkscape lists the pattern among the
    document's patterns, to fill any shape with.

    Parameters
    ----------
    arr : Arrangement
    width : float, optional
        Display width (``width`` attribute); default: the drawing's own width in user
        units, enlarged so that the longer side is at least 400 for small drawings.
    margin : float
        Fraction of the drawing size left around it (not for periodic arrangements).
    background : str, optional
        A fill colour for a background rectangle.
    show_region : bool
        Draw the region outline in its own layer (not for periodic arrangements).
    show_guides : bool
        Draw the tool strokes recorded in ``arr.extra["guides"]`` (a list of ``(m, 2)``
        polylines, e.g. grow's boundary strokes) in a layer ``strew-guides``, so a
        picture shows what shaped it. SVG import skips that layer.
    stroke_width : float, optional
        Default outline width in shape units for shapes without one (default: 3% of
        the median shape radius).
    repeat : (int, int) or str, optional
        Copies of a periodic tile across and down (``(3, 2)`` or ``"3x2"``), drawn
        through a ``<pattern>``. Refused for an arrangement that is not periodic.
    height : float, optional
        Display height; default from ``width`` and the page's aspect. Given both, the
        page is stretched to them (``preserveAspectRatio="none"``): the PNG writer maps a
        tile to whole pixels this way.
    tile_pixels : (int, int), optional
        For rasterising a periodic tile (the PNG writer): the page is laid out in pixels,
        one tile ``tile_pixels`` wide and high, and repeated through the ``<pattern>``
        (``repeat``, default 1 x 1). resvg draws a pattern from one raster of its tile
        when the tile is whole pixels, so every copy is the same pixels: the PNG tiles
        without a seam.

    Returns
    -------
    str
    """
    tile = frame(arr)
    counts = None
    if repeat is not None:
        counts = _repeat_counts(repeat)
        if tile is None:
            raise InputError("repeat: the arrangement is not periodic (no meta.periodic); make it with periodic=True")
    if tile_pixels is not None:
        if tile is None:
            raise InputError("tile_pixels: the arrangement is not periodic (no meta.periodic)")
        counts = counts or (1, 1)
        px = (int(tile_pixels[0]), int(tile_pixels[1]))
        if min(px) < 1:
            raise InputError(f"tile_pixels: must be positive, got {tile_pixels!r}")
        vb = (0.0, 0.0, float(px[0] * counts[0]), float(px[1] * counts[1]))
        width, height = vb[2], vb[3]
        show_region = False
    elif tile is not None:
        vb = (tile[0], tile[1], tile[2] * (counts[0] if counts else 1), tile[3] * (counts[1] if counts else 1))
        show_region = False
    else:
        x0, y0, x1, y1 = arr.bounds
        if arr.region is not None:
            rx0, ry0, rx1, ry1 = arr.region.bounds
            x0, y0, x1, y1 = min(x0, rx0), min(y0, ry0), max(x1, rx1), max(y1, ry1)
        w, h = x1 - x0, y1 - y0
        if w <= 0 or h <= 0:
            s = max(w, h, 1.0)
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            x0, y0, w, h = cx - s / 2, cy - s / 2, s, s
        pad = margin * max(w, h)
        vb = (x0 - pad, y0 - pad, w + 2 * pad, h + 2 * pad)
    # Default page size: 1 user unit = 1 px, but small drawings are enlarged to 400 px.
    disp_w = float(width) if width else max(vb[2], 400.0 * vb[2] / max(vb[2], vb[3]))
    disp_h = float(height) if height else disp_w * vb[3] / vb[2]
    stretch = ' preserveAspectRatio="none"' if height else ""

    radii = [sh.radius for sh in arr.shapes.values() if sh.radius > 0]
    sw = stroke_width if stroke_width is not None else 0.03 * (float(np.median(radii)) if radii else 1.0)
    color = arr.columns.get("color")
    inherit_fill = color is not None and color.ndim == 1

    out: list[str] = []
    out.append('<?xml version="1.0" encoding="UTF-8"?>')
    out.append(
        f'<svg xmlns="{SVG_NS}" xmlns:xlink="{XLINK_NS}" xmlns:inkscape="{INKSCAPE_NS}" '
        f'xmlns:rdf="{RDF_NS}" xmlns:cc="{CC_NS}" xmlns:dc="{DC_NS}" version="1.1" '
        f'width="{_num(disp_w)}" height="{_num(disp_h)}" '
        f'viewBox="{" ".join(_num(v) for v in vb)}"{stretch}>'
    )
    # meta as JSON in the RDF description that Inkscape shows under Document Metadata
    meta_json = json.dumps(arr.meta, sort_keys=False, default=_json_default)
    out.append(
        f'<metadata id="strew-metadata"><rdf:RDF><cc:Work rdf:about="">'
        f"<dc:format>image/svg+xml</dc:format><dc:source>strew</dc:source>"
        f'<dc:description id="strew-meta">{escape(meta_json)}</dc:description></cc:Work></rdf:RDF></metadata>'
    )
    out.append("<defs>")
    ids = []
    for i, (name, shape) in enumerate(arr.shapes.items()):
        sid = kind_id(name, i)
        ids.append(sid)
        label = quoteattr(name)
        out.append(
            f'<symbol id="{sid}" data-kind={label} inkscape:label={label} style="overflow:visible">'
            f'<path d={quoteattr(path_data(shape))} {_style_attrs(shape, inherit_fill=inherit_fill, stroke_width=sw)}/>'
        )
        for lname, (lx, ly) in shape.labels.items():
            out.append(f'<circle data-label={quoteattr(lname)} cx="{_num(lx)}" cy="{_num(ly)}" r="0" display="none"/>')
        out.append("</symbol>")
    clip = ""
    if tile is not None:
        tx, ty, tw, th = tile
        box = f'x="{_num(tx)}" y="{_num(ty)}" width="{_num(tw)}" height="{_num(th)}"'
        out.append(f'<clipPath id="strew-tile" clipPathUnits="userSpaceOnUse"><rect {box}/></clipPath>')
        clip = ' clip-path="url(#strew-tile)"'
    if counts is not None:
        # the tile drawn once inside the pattern (which clips to its own tile); the page
        # is a rectangle filled with it
        if tile_pixels is None:
            out.append(f'<pattern id="strew-pattern" inkscape:label="strew tile" patternUnits="userSpaceOnUse" {box}>')
        else:  # tile units to pixels inside the pattern
            sx, sy = px[0] / tw, px[1] / th
            out.append(f'<pattern id="strew-pattern" patternUnits="userSpaceOnUse" x="0" y="0" width="{px[0]}" height="{px[1]}">')
            out.append(f'<g transform="matrix({_num(sx)} 0 0 {_num(sy)} {_num(-tx * sx)} {_num(-ty * sy)})">')
        if background:
            out.append(f'<rect {box} fill={quoteattr(background)}/>')
        out.extend(_draw_tile(arr, ids, sw, inherit_fill, layers=False))
        if tile_pixels is not None:
            out.append("</g>")
        out.append("</pattern>")
        out.append("</defs>")
        out.append(
            f'<rect id="strew-repeat" inkscape:label="repeat {counts[0]}x{counts[1]}" x="{_num(vb[0])}" y="{_num(vb[1])}" '
            f'width="{_num(vb[2])}" height="{_num(vb[3])}" fill="url(#strew-pattern)"/>'
        )
        out.append("</svg>")
        return "\n".join(out) + "\n"
    out.append("</defs>")
    if background:
        out.append(f'<rect x="{_num(vb[0])}" y="{_num(vb[1])}" width="{_num(vb[2])}" height="{_num(vb[3])}" fill={quoteattr(background)}/>')
    if show_region and arr.region is not None:
        d = " ".join(
            "M" + " L".join(f"{_num(x)},{_num(y)}" for x, y in p.points) + " Z" for p in arr.region.paths
        )
        out.append(
            f'<g id="strew-region" inkscape:groupmode="layer" inkscape:label="region">'
            f'<path d={quoteattr(d)} fill="none" stroke="#b8bcc4" stroke-width="{_num(sw)}" fill-rule="evenodd"/></g>'
        )
    if tile is not None:
        out.extend(_draw_tile(arr, ids, sw, inherit_fill, layers=True))
    else:
        out.extend(_element_layers(arr, ids, sw, inherit_fill, clip=""))
    # drawn last: an overlay over the elements
    guides = arr.extra.get("guides") if show_guides else None
    if guides:
        d = " ".join(
            "M" + " L".join(f"{_num(x)},{_num(y)}" for x, y in np.asarray(g, dtype=float).reshape(-1, 2))
            for g in guides if len(g) >= 2
        )
        gw = max(2 * sw, 0.004 * max(vb[2], vb[3]))  # legible at any zoom of the page
        out.append(
            f'<g id="strew-guides" inkscape:groupmode="layer" inkscape:label="guides"{clip}>'
            f'<path d={quoteattr(d)} fill="none" stroke="#d0453a" stroke-width="{_num(gw)}" '
            f'stroke-dasharray="{_num(4 * gw)} {_num(2.5 * gw)}" stroke-linecap="round" stroke-linejoin="round"/></g>'
        )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _draw_tile(arr: Arrangement, ids: list[str], sw: float, inherit_fill: bool, *, layers: bool) -> list[str]:
    """A periodic tile: its elements once (per-kind layers), then the wrapped copies that
    reach into the tile (layer ``strew-wrap``), all clipped to the tile (``#strew-tile``).

    A copy is a clone of its element (``<use xlink:href="#strew-eI">`` moved by a whole
    tile, ``data-copy-of="I"``): in Inkscape, moving or restyling an element near an edge
    moves and restyles the part that wraps in at the opposite edge.
    """
    clip = ' clip-path="url(#strew-tile)"'
    n = len(arr)
    im = images(arr.with_columns(copy_of=np.arange(n))) if n else arr
    copies = im.select(np.arange(n, len(im)))
    src = np.asarray(copies["copy_of"], dtype=np.int64) if len(copies) else np.zeros(0, np.int64)
    out = _element_layers(arr, ids, sw, inherit_fill, clip=clip, layers=layers, named=set(src.tolist()))
    if len(copies) == 0:
        return out
    group = 'id="strew-wrap" inkscape:groupmode="layer" inkscape:label="wrapped copies"' if layers else 'data-strew="wrap"'
    out.append(f"<g {group}{clip}>")
    dx, dy = copies.x - arr.x[src], copies.y - arr.y[src]
    for i, a, b in zip(src.tolist(), dx.tolist(), dy.tolist()):
        out.append(f'<use xlink:href="#strew-e{i}" transform="translate({_num(a)} {_num(b)})" data-copy-of="{i}"/>')
    out.append("</g>")
    return out


def _element_layers(arr: Arrangement, ids: list[str], sw: float, inherit_fill: bool, *, clip: str, layers: bool = True, named: set[int] | None = None) -> list[str]:
    """One group per kind (an Inkscape layer when ``layers``) with its elements."""
    out: list[str] = []
    kind = arr.kind
    col_attrs = _column_attr_values(arr)  # once: a library may hold hundreds of kinds
    order = np.argsort(kind, kind="stable")
    cuts = np.searchsorted(kind[order], np.arange(len(arr.kinds) + 1))
    for k, name in enumerate(arr.kinds):
        idx = order[cuts[k] : cuts[k + 1]]
        if len(idx) == 0:
            continue
        label = quoteattr(name)
        if layers:
            out.append(f'<g id="layer-{ids[k]}" inkscape:groupmode="layer" inkscape:label={label} data-kind={label}{clip}>')
        else:
            out.append(f"<g data-kind={label}{clip}>")
        out.extend(_element_lines(arr, ids, sw, inherit_fill, idx, col_attrs=col_attrs, named=named))
        out.append("</g>")
    return out


def _element_lines(arr: Arrangement, ids: list[str], sw: float, inherit_fill: bool, idx: np.ndarray, *, col_attrs: dict[str, list[str]] | None = None, named: set[int] | None = None) -> list[str]:
    """``<use>`` (or a group of parts) for each element in ``idx``; those in ``named`` get
    ``id="strew-eI"`` (their wrapped copies clone them)."""
    out: list[str] = []
    color = arr.columns.get("color")
    void = arr.columns.get("void")
    parts = arr.element_parts
    if col_attrs is None:
        col_attrs = _column_attr_values(arr)
    kind = arr.kind
    xs, ys, rot, sc = arr.x, arr.y, arr.rotation, arr.scale
    names = arr.kinds
    for i in idx.tolist():
        k = int(kind[i])
        label = quoteattr(names[k])
        t = f"translate({_num(xs[i])} {_num(ys[i])})"
        if rot[i] != 0:
            t += f" rotate({_num(math.degrees(rot[i]))})"
        if sc[i] != 1:
            t += f" scale({_num(sc[i])})"
        extra = [f'id="strew-e{i}" data-index="{i}"' if named and i in named else f'data-index="{i}"']
        for cname, vals in col_attrs.items():
            extra.append(f"data-{cname}={quoteattr(vals[i])}")
        if inherit_fill and isinstance(color[i], str):
            extra.append(f"fill={quoteattr(color[i])}")
        if void is not None and bool(void[i]):
            extra.append('display="none"')
        if parts is not None and parts[i] is not None:
            # an element with its own geometry (the `parts` column): a group named by
            # its kind, one path per part; read_svg brings it back as that kind
            out.append(f'<g transform="{t}" data-kind={label} {" ".join(extra)}>')
            for part in parts[i]:
                out.append(f'<path d={quoteattr(path_data(part))} {_style_attrs(part, inherit_fill=False, stroke_width=sw)}/>')
            out.append("</g>")
            continue
        out.append(f'<use xlink:href="#{ids[k]}" transform="{t}" {" ".join(extra)}/>')
    return out


def _json_default(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    return str(obj)
