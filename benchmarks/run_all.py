"""Run every benchmark script in this folder, one after another.

    python benchmarks/run_all.py [--quick]

Each script prints its own table (medians and ratios against its baseline, measured in
the same run) and writes JSON to benchmarks/results/.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _runner import SKIPPED  # noqa: E402


def main() -> int:
    here = Path(__file__).resolve().parent
    extra = sys.argv[1:]
    failed, skipped = [], []
    for script in sorted(here.glob("*.py")):
        if script.name.startswith("_") or script.name == "run_all.py":
            continue
        print(f"\n=== {script.name} ===", flush=True)
        rc = subprocess.run([sys.executable, str(script), *extra], cwd=here).returncode
        if rc == SKIPPED:
            skipped.append(script.name)
        elif rc != 0:
            failed.append(script.name)
    if skipped:
        print(f"\nskipped (see the reason above): {', '.join(skipped)}")
    if failed:
        print(f"\nfailed: {', '.join(failed)}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
