"""Start-up time of ``strew --help`` against ``python -c "import numpy"``.

``strew --help`` imports no heavy module (numpy, shapely, scipy ...), so it should answer
in less time than importing numpy alone: the ratio printed is strew / numpy (< 1 is good).

    python benchmarks/cli_startup.py [--repeat N]
"""

from __future__ import annotations

import shutil
import subprocess
import sys

from _runner import Bench, median_time, parse_args


def run(args: list[str]) -> None:
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def main() -> None:
    opts = parse_args(__doc__)
    repeat = max(opts.repeat, 3) if not opts.quick else 3
    bench = Bench("cli_startup", "strew --help start-up", baseline='python -c "import numpy"', json_path=opts.json)
    t_numpy, _ = median_time(lambda: run([sys.executable, "-c", "import numpy"]), repeat=repeat)
    t_python, _ = median_time(lambda: run([sys.executable, "-c", "pass"]), repeat=repeat)
    exe = shutil.which("strew")
    strew = [exe] if exe else [sys.executable, "-m", "strew"]
    t_help, _ = median_time(lambda: run([*strew, "--help"]), repeat=repeat)
    t_version, _ = median_time(lambda: run([*strew, "--version"]), repeat=repeat)
    bench.row("python -c pass", median_s=t_python, ratio_to_numpy=t_python / t_numpy)
    bench.row('python -c "import numpy"', median_s=t_numpy, ratio_to_numpy=1.0)
    bench.row("strew --help", median_s=t_help, ratio_to_numpy=t_help / t_numpy)
    bench.row("strew --version", median_s=t_version, ratio_to_numpy=t_version / t_numpy)
    bench.finish()


if __name__ == "__main__":
    main()
