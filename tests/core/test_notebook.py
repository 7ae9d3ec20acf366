"""The example notebook runs top to bottom in a fresh kernel (issue 22 point 4).

Executed with nbclient, as a reader would with "Run all". The notebook's own cells
assert that the result is faithful and that the pandas round trip keeps the elements;
here we check that each display cell produced what it promises.
"""

from __future__ import annotations

from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

NOTEBOOK = Path(__file__).resolve().parents[2] / "examples" / "notebooks" / "strew_quicktour.ipynb"


@pytest.fixture(scope="module")
def executed():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(NOTEBOOK.parent)}}
    )
    client.execute()  # raises CellExecutionError, with the traceback, if any cell fails
    return [c for c in nb.cells if c.cell_type == "code"]


def _outputs(cell, mime):
    return [o["data"][mime] for o in cell.get("outputs", []) if "data" in o and mime in o["data"]]


def test_arrangements_display_as_svg(executed):
    # cells 0 (the exemplar) and 1 (the result) end with an Arrangement
    for cell in executed[:2]:
        svgs = _outputs(cell, "image/svg+xml")
        assert svgs, cell.source
        assert "<use" in svgs[0]


def test_fidelity_report_is_a_table_with_a_verdict(executed):
    html = _outputs(executed[2], "text/html")
    assert html and "<table" in html[0]
    assert "faithful" in html[0].lower()


def test_counts_and_saved_files(executed):
    printed = "".join(o.get("text", "") for o in executed[4].get("outputs", []) if o.get("output_type") == "stream")
    assert "faithful: True" in printed
    saved = _outputs(executed[5], "text/plain")
    assert saved and all(n in saved[0] for n in ("stones.svg", "stones.png", "stones.json"))
