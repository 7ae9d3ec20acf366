"""Helper s68r: pytest plugin (``-p s68r_pytest_log``, benchmarks on PYTHONPATH, no xdist) that logs,
unchanged, where ``_grow._larger_short`` holds (fill_room's second pass runs only there; elsewhere the
run is byte-identical to integ38's)."""
import strew.synth._grow as G

_short = G._larger_short
HELD = [0, 0]
NODE = [""]
WHERE = []


def _logged(state):
    r = _short(state)
    HELD[1] += 1
    if r:
        HELD[0] += 1
        WHERE.append(NODE[0])
    return r


G._larger_short = _logged


def pytest_runtest_setup(item):
    NODE[0] = item.nodeid


def pytest_terminal_summary(terminalreporter):
    terminalreporter.write_line(f"[s68r] _larger_short held {HELD[0]} of {HELD[1]} calls: {sorted(set(WHERE))}")
