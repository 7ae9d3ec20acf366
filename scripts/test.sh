#!/usr/bin/env bash
# The whole test suite on a fresh machine: installs strew with its test extras, Debian's
# chromium for the browser tests when it is missing (needs root and apt), then runs pytest.
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
python -m pytest "$@"
