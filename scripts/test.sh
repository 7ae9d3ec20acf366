#!/usr/bin/env bash
# The whole test suite on a fresh machine: installs strew with its test extras, Debian's
# chromium for the browser tests when it is missing (needs root and apt), then runs pytest on every core (pytest-xdist).
set -euo pipefail
cd "$(dirname "$0")/.."
python -m pip install --quiet '.[test]'
if ! command -v chromium >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        echo "installing Debian's chromium for the browser tests" >&2
        apt-get update -qq
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends chromium >/dev/null
    else
        echo "chromium is missing and cannot be installed here (needs root and apt)" >&2
    fi
fi
# one worker per core this process may use; whole files go to a worker (--dist loadfile),
# so a module's fixtures (the gallery, the tiled worlds) are built once. Later options win:
# `bash scripts/test.sh -n 0` runs in this process. pytest-benchmark, where a machine has
# it, turns itself off under xdist with a warning that the suite's filterwarnings=error
# makes fatal; strew's benchmarks are scripts (benchmarks/), so the plugin is not loaded.
workers=$(python -c "import os; print(max(1, len(os.sched_getaffinity(0))))")
python -m pytest -n "$workers" --dist loadfile -p no:benchmark "$@"
