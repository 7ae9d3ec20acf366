"""Helper s67t: pytest plugin (``-p s67t_pytest_noshort``, benchmarks on PYTHONPATH) that patches
``_grow._larger_short`` to False (as ``s67t_patched.py noshort``) and reports at the end how often main's
would have held: 0 means every run in the session was byte-identical to main's."""
import strew.synth._grow as G

_short = G._larger_short
HELD = [0, 0]
NODE = [""]
WHERE = []


def _patched(state):
    HELD[1] += 1
    if _short(state):
        HELD[0] += 1
        WHERE.append(NODE[0])
    return False


G._larger_short = _patched


def pytest_runtest_setup(item):
    NODE[0] = item.nodeid


def pytest_terminal_summary(terminalreporter):
    terminalreporter.write_line(f"[s67t] main's _larger_short held {HELD[0]} of {HELD[1]} calls (patched to False): {sorted(set(WHERE))}")
