"""Tiny benchmark convention shared by every script in ``benchmarks/``.

Each script measures its subject and a named baseline in the same run, prints one table
(medians of N runs, and ratios against the baseline) and writes the same figures as JSON
to ``benchmarks/results/<name>.json`` (or ``--json PATH``).

Usage inside a script::

    from _runner import Bench, median_time

    bench = Bench("pack", "fill-gap vs naive dart throwing")
    t = median_time(lambda: work(), repeat=5)
    bench.row("elongated", fill_gap_s=t, naive_s=tb, speedup=tb / t, count=n)
    bench.finish()
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["Bench", "median_time", "timed", "parse_args", "SKIPPED"]

# Exit status of a script that could not measure here (a missing extra or browser); it has
# printed why. run_all.py reports it as skipped, not failed.
SKIPPED = 3


def fidelity_suite() -> Any:
    """The fidelity suite's exemplar maker, ``examples/fidelity/make.py`` (``NAMES``, ``make_exemplar``)."""
    import importlib.util

    path = Path(__file__).resolve().parents[1] / "examples" / "fidelity" / "make.py"
    spec = importlib.util.spec_from_file_location("fidelity_make", path)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def parse_args(description: str = "", extra: Callable[[argparse.ArgumentParser], None] | None = None) -> argparse.Namespace:
    """Common flags: ``--repeat N``, ``--quick`` (smaller problem), ``--json PATH``."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--repeat", type=int, default=5, help="runs per measurement; the median is reported")
    p.add_argument("--quick", action="store_true", help="smaller problem sizes, for a fast check")
    p.add_argument("--json", default=None, help="where to write the JSON figures")
    if extra is not None:
        extra(p)
    return p.parse_args()


def timed(fn: Callable[[], Any]) -> tuple[float, Any]:
    """Run ``fn`` once; return (seconds, result)."""
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def median_time(fn: Callable[[], Any], repeat: int = 5, warmup: int = 1) -> tuple[float, Any]:
    """Median wall time of ``repeat`` runs after ``warmup`` runs; returns (seconds, last result)."""
    result = None
    for _ in range(warmup):
        result = fn()
    times = []
    for _ in range(max(1, repeat)):
        t, result = timed(fn)
        times.append(t)
    return statistics.median(times), result


class Bench:
    """Collects rows of figures, prints them as one table, writes them as JSON."""

    def __init__(self, name: str, title: str, *, baseline: str, json_path: str | None = None) -> None:
        self.name = name
        self.title = title
        self.baseline = baseline
        self.rows: list[dict[str, Any]] = []
        self.json_path = Path(json_path) if json_path else Path(__file__).parent / "results" / f"{name}.json"

    def row(self, label: str, **figures: Any) -> None:
        self.rows.append({"case": label, **figures})

    @staticmethod
    def _fmt(v: Any) -> str:
        if isinstance(v, float):
            if v == 0:
                return "0"
            if abs(v) >= 1000:
                return f"{v:,.0f}"
            if abs(v) >= 10:
                return f"{v:.1f}"
            return f"{v:.3g}"
        return str(v)

    def table(self) -> str:
        cols: list[str] = []
        for r in self.rows:
            cols.extend(k for k in r if k not in cols)
        cells = [[self._fmt(r.get(c, "")) for c in cols] for r in self.rows]
        widths = [max(len(c), *(len(row[i]) for row in cells)) if cells else len(c) for i, c in enumerate(cols)]
        lines = [f"{self.title}  (baseline: {self.baseline})"]
        lines.append("  ".join(c.ljust(w) for c, w in zip(cols, widths)))
        lines.append("  ".join("-" * w for w in widths))
        for row in cells:
            lines.append("  ".join(v.ljust(w) for v, w in zip(row, widths)))
        return "\n".join(lines)

    def finish(self) -> None:
        print(self.table())
        payload = {
            "benchmark": self.name,
            "title": self.title,
            "baseline": self.baseline,
            "python": sys.version.split()[0],
            "machine": platform.machine(),
            "cpus": os.cpu_count(),
            "rows": self.rows,
        }
        self.json_path.parent.mkdir(parents=True, exist_ok=True)
        self.json_path.write_text(json.dumps(payload, indent=2) + "\n")
        print(f"figures written to {self.json_path}")
