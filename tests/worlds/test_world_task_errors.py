"""A tile task that raises on a Dask worker reaches the user as one line (issue 17)."""

import subprocess
import sys

import pytest

pytest.importorskip("dask.distributed")


@pytest.mark.slow
def test_failing_tiles_on_two_workers_print_one_line_and_write_nothing(tmp_path):
    script = tmp_path / "bad.py"
    script.write_text("from strew.program import *\narrangement = undefined_name\n")
    out = tmp_path / "w.parquet"
    p = subprocess.run(
        [sys.executable, "-m", "strew", "world", "program", str(script), "--size", "160x160", "--tile-size", "40",
         "--workers", "2", "-o", str(out), "-q"],
        capture_output=True, text=True, timeout=300,
    )
    assert p.returncode == 2, p.stderr
    lines = [ln for ln in p.stderr.splitlines() if ln.strip()]
    # before: every worker logged "Compute Failed" and the traceback, once per tile
    assert lines == [lines[0]] and lines[0].startswith("strew: error:") and "undefined_name" in lines[0], p.stderr[-2000:]
    assert "Traceback" not in p.stderr and "Compute Failed" not in p.stderr
    assert not out.exists()
