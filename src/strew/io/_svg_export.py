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
    has_area = not shape.area_geometry.is_empty
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


def to_svg(
    arr: Arrangement,
    *,
    width: float | None = None,
    margin: float = 0.02,
    background: str | None = None,
    show_region: bool = True,
    show_guides: bool = True,
    stroke_width: float | None = None,
) -> str:
    """SVG text for an arrangement.

    Parameters
    ----------
    arr : Arrangement
    width : float, optional
        Display width (``width`` attribute); default: the drawing's own width in user
        units, enlarged so that the longer side is at least 400 for small drawings.
    margin : float
        Fraction of the drawing size left around it.
    background : str, optional
        A fill colour for a background rectangle.
    show_region : bool
        Draw the region outline in its own layer.
    show_guides : bool
        Draw the tool strokes recorded in ``arr.extra["guides"]`` (a list of ``(m, 2)``
        polylines, e.g. grow's boundary strokes) in a layer ``strew-guides``, so a
        picture shows what shaped it. SVG import skips that layer.
    stroke_width : float, optional
        Default outline width in shape units for shapes without one (default: 3% of
        the median shape radius).

    Returns
    -------
    str
    """
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
    disp_h = disp_w * vb[3] / vb[2]

    radii = [sh.radius for sh in arr.shapes.values() if sh.radius > 0]
    sw = stroke_width if stroke_width is not None else 0.03 * (float(np.median(radii)) if radii else 1.0)
    color = arr.columns.get("color")
    inherit_fill = color is not None and color.ndim == 1
    void = arr.columns.get("void")
    parts = arr.element_parts

    out: list[str] = []
    out.append('<?xml version="1.0" encoding="UTF-8"?>')
    out.append(
        f'<svg xmlns="{SVG_NS}" xmlns:xlink="{XLINK_NS}" xmlns:inkscape="{INKSCAPE_NS}" '
        f'xmlns:rdf="{RDF_NS}" xmlns:cc="{CC_NS}" xmlns:dc="{DC_NS}" version="1.1" '
        f'width="{_num(disp_w)}" height="{_num(disp_h)}" '
        f'viewBox="{" ".join(_num(v) for v in vb)}">'
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
    col_attrs = _column_attr_values(arr)
    kind = arr.kind
    xs, ys, rot, sc = arr.x, arr.y, arr.rotation, arr.scale
    for k, name in enumerate(arr.kinds):
        idx = np.flatnonzero(kind == k)
        if len(idx) == 0:
            continue
        label = quoteattr(name)
        out.append(f'<g id="layer-{ids[k]}" inkscape:groupmode="layer" inkscape:label={label} data-kind={label}>')
        for i in idx.tolist():
            t = f"translate({_num(xs[i])} {_num(ys[i])})"
            if rot[i] != 0:
                t += f" rotate({_num(math.degrees(rot[i]))})"
            if sc[i] != 1:
                t += f" scale({_num(sc[i])})"
            extra = [f'data-index="{i}"']
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
        out.append("</g>")
    # drawn last: an overlay over the elements
    guides = arr.extra.get("guides") if show_guides else None
    if guides:
        d = " ".join(
            "M" + " L".join(f"{_num(x)},{_num(y)}" for x, y in np.asarray(g, dtype=float).reshape(-1, 2))
            for g in guides if len(g) >= 2
        )
        gw = max(2 * sw, 0.004 * max(vb[2], vb[3]))  # legible at any zoom of the page
        out.append(
            f'<g id="strew-guides" inkscape:groupmode="layer" inkscape:label="guides">'
            f'<path d={quoteattr(d)} fill="none" stroke="#d0453a" stroke-width="{_num(gw)}" '
            f'stroke-dasharray="{_num(4 * gw)} {_num(2.5 * gw)}" stroke-linecap="round" stroke-linejoin="round"/></g>'
        )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def _json_default(obj: Any) -> Any:
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    return str(obj)
