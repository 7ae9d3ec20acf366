"""Helper g37r: digests of grow outputs of chosen audit rows, to compare two trees.

    PYTHONPATH=src:benchmarks python benchmarks/g37r_same.py clusters:v20,rings:v27 1-2

One line per row and seed: n and the SHA-256 (16 hex digits) of kind, xy and rotation.
"""
import hashlib
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import _variants
from _runner import fidelity_suite
from fresh17_rows import exemplar
from grow_variants import run


def main():
    mk = fidelity_suite()
    for spec in sys.argv[1].split(","):
        cls, label = spec.split(":")
        ex = exemplar(mk, cls, label)
        for seed in _variants.ints(sys.argv[2]):
            out, _ = run(ex, 3.5, seed, SimpleNamespace(mode="fixed", times=10.0))
            h = hashlib.sha256(out.kind.tobytes() + out.xy.tobytes() + out.rotation.tobytes()).hexdigest()[:16]
            print(f"{spec} seed {seed}: n={len(out)} {h}", flush=True)


if __name__ == "__main__":
    main()
