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
# The suite's numerics at one arithmetic on every x86-64 machine with AVX2: flow growth
# (grow's flow mode) is chaotic in the last bit of a float, and numpy's AVX-512 kernels
# (float64 sin/cos/exp) and OpenBLAS's per-CPU kernels round differently from the AVX2
# ones, so a few flow tests took other trajectories on an AVX-512 machine (numpy
# X86_V4, OpenBLAS SkylakeX) than on the AVX2 machines their figures were measured on.
# Both pins keep exact IEEE arithmetic; a caller's own settings win.
if [ "$(uname -m)" = x86_64 ] && grep -qw avx2 /proc/cpuinfo 2>/dev/null; then
    # numpy names its dispatched features by version and warns (an error under the suite's
    # filterwarnings) on a name it does not dispatch, so ask it which AVX-512 ones it has
    avx512=$(python -c "
try:
    from numpy._core._multiarray_umath import __cpu_dispatch__ as d
except ImportError:
    from numpy.core._multiarray_umath import __cpu_dispatch__ as d
print(' '.join(f for f in d if 'AVX512' in f or f == 'X86_V4'))")
    export NPY_DISABLE_CPU_FEATURES="${NPY_DISABLE_CPU_FEATURES-$avx512}"
    export OPENBLAS_CORETYPE="${OPENBLAS_CORETYPE-Haswell}"
fi
# one worker per core this process may use; whole files go to a worker (--dist loadfile),
# so a module's fixtures (the gallery, the tiled worlds) are built once. Later options win:
# `bash scripts/test.sh -n 0` runs in this process. pytest-benchmark, where a machine has
# it, turns itself off under xdist with a warning that the suite's filterwarnings=error
# makes fatal; strew's benchmarks are scripts (benchmarks/), so the plugin is not loaded.
workers=$(python -c "import os; print(max(1, len(os.sched_getaffinity(0))))")
python -m pytest -n "$workers" --dist loadfile -p no:benchmark "$@"
