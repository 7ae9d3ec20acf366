"""The test suite's time per file and its split over pytest-xdist workers (task t31).

Reads a JUnit XML written by ``pytest --junitxml=F`` (each test's time is its setup, call
and teardown), prints the per-file totals and simulates ``--dist loadfile``: files are
queued by number of tests, most first (xdist's default ``--loadscope-reorder``; ties keep
the collection order), or in the collection order given by ``--order F`` (a file of
``pytest --collect-only -q`` node ids), and each file goes to the worker that frees up
first. Prints the simulated wall time (the last worker's end) against the ideal (total
over workers).

    python benchmarks/t31_suite_balance.py before.xml [--workers 2] [--top 40]
    python benchmarks/t31_suite_balance.py before.xml --order collect.txt --no-reorder
"""

from __future__ import annotations

import argparse
import heapq
import xml.etree.ElementTree as ET
from collections import defaultdict
from pathlib import Path


def _module_file(file: str | None, classname: str) -> str:
    """The test file of a JUnit test case: its ``file`` attribute, or the longest dotted
    prefix of its class name (module, then any test class) that names a file."""
    if file:
        return file
    parts = classname.split(".")
    for k in range(len(parts), 0, -1):
        f = "/".join(parts[:k]) + ".py"
        if Path(f).exists():
            return f
    return "/".join(parts) + ".py"


def per_file(xml: str) -> tuple[dict[str, float], dict[str, int]]:
    """Per test file: the summed time (s) and the number of tests."""
    secs: dict[str, float] = defaultdict(float)
    count: dict[str, int] = defaultdict(int)
    for tc in ET.parse(xml).getroot().iter("testcase"):
        f = _module_file(tc.get("file"), tc.get("classname", ""))
        secs[f] += float(tc.get("time", 0.0))
        count[f] += 1
    return dict(secs), dict(count)


def simulate(order: list[str], secs: dict[str, float], workers: int) -> tuple[float, list[list[str]]]:
    """List scheduling: each file in ``order`` to the worker free first. Wall time and
    each worker's files."""
    heap = [(0.0, w) for w in range(workers)]
    got: list[list[str]] = [[] for _ in range(workers)]
    for f in order:
        t, w = heapq.heappop(heap)
        got[w].append(f)
        heapq.heappush(heap, (t + secs.get(f, 0.0), w))
    return max(t for t, _ in heap), got


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("xml")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--top", type=int, default=40)
    ap.add_argument("--order", help="node ids in collection order (pytest --collect-only -q)")
    ap.add_argument("--no-reorder", action="store_true", help="keep the collection order (--no-loadscope-reorder)")
    a = ap.parse_args()
    secs, count = per_file(a.xml)
    total = sum(secs.values())
    print(f"{sum(count.values())} tests in {len(secs)} files, {total:.0f} s summed; ideal over {a.workers} workers {total / a.workers:.0f} s")
    for f, s in sorted(secs.items(), key=lambda kv: -kv[1])[: a.top]:
        print(f"{s:8.1f} s {100 * s / total:5.1f} % {count[f]:4d} tests  {f}")
    if a.order:
        files: list[str] = []
        collected: dict[str, int] = {}
        with open(a.order) as fh:
            lines = fh.read().splitlines()
        for line in lines:
            f = line.strip().split("::")[0]
            if f.endswith(".py"):
                if f not in files:
                    files.append(f)
                    collected[f] = 0
                collected[f] += 1
        count = collected  # the queue's key: tests collected per file
    else:
        files = sorted(secs)
    order = files if a.no_reorder else sorted(files, key=lambda f: -count.get(f, 0))
    wall, got = simulate(order, secs, a.workers)
    print(f"simulated --dist loadfile {'in collection order' if a.no_reorder else '(files by test count)'}: {wall:.0f} s")
    for w, fs in enumerate(got):
        tail = fs[-3:]
        print(f"  worker {w}: {sum(secs.get(f, 0) for f in fs):.0f} s, {len(fs)} files, last {tail}")


if __name__ == "__main__":
    main()
