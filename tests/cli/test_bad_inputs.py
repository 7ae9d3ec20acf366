"""The bad-input table (issue 17, point 8): every command x every bad-input class.

Each case runs one command in-process and asserts exit code 2, a one-line message that
names the field or option, no traceback and no file written (no temporary leftovers).
A handful of cases are valid input the command must accept (``OK``).

``python tests/cli/test_bad_inputs.py`` runs the same table in subprocesses with a time
limit per case and prints how many inputs were tried, handled and mishandled (the
measurement quoted in issue 17); a hang counts as mishandled.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest

OK = None  # expected: a valid run, exit 0

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TRI = [[0, 0], [10, 0], [0, 10]]


def _doc(shapes=None, region=None, **elements):
    # a 3 x 3 grid of triangles: a valid exemplar for every method
    base = {"kind": ["a"] * 9, "x": [0, 12, 24] * 3, "y": [0] * 3 + [12] * 3 + [24] * 3, "rotation": [0] * 9, "scale": [1] * 9}
    base.update(elements)
    doc = {
        "format": "strew.arrangement",
        "version": 1,
        "shapes": shapes if shapes is not None else {"a": {"paths": [{"points": TRI, "closed": True}]}},
        "elements": base,
    }
    if region is not None:
        doc["region"] = {"paths": [{"points": region, "closed": True}]}
    return json.dumps(doc)


_VALID = _doc()
_SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">{}</svg>'

# name -> file text (bytes are written as is)
FILES: dict[str, str | bytes] = {
    "valid.json": _VALID,
    "malformed.json": "{ this is not json",
    "truncated.json": _VALID[: len(_VALID) // 2],
    "list.json": "[1, 2, 3]",
    "wrongshape.json": _doc(x={"a": 1}),
    "badpoints.json": _doc(shapes={"a": {"paths": [{"points": [1, 2, 3], "closed": True}]}}),
    "deep.json": "[" * 100_000 + "]" * 100_000,
    "nan.json": _doc(x=[0, "NAN", 24] * 3).replace('"NAN"', "NaN"),
    "inf.json": _doc(y=[0, "INF", 0] * 3).replace('"INF"', "Infinity"),
    "huge.json": _doc(x=[0, 1e308, -1e308] * 3),
    "hugeshape.json": _doc(shapes={"a": {"paths": [{"points": [[0, 0], [1e300, 0], [0, 1e300]], "closed": True}]}}),
    "hugescale.json": _doc(scale=[1, 1e300, 1] * 3),
    "zeroscale.json": _doc(scale=[1, 0, 1] * 3),
    "negscale.json": _doc(scale=[1, -2, 1] * 3),
    "empty.json": _doc(kind=[], x=[], y=[], rotation=[], scale=[]),
    "emptyfile.json": "",
    "noshapes.svg": _SVG.format("<text>hi</text>"),
    "emptyfile.svg": "",
    "selfint.json": _doc(shapes={"a": {"paths": [{"points": [[0, 0], [10, 10], [10, 0], [0, 10]], "closed": True}]}}),
    "zeroarea.json": _doc(shapes={"a": {"paths": [{"points": [[0, 0], [5, 5], [10, 10]], "closed": True}]}}),
    "nanpath.svg": _SVG.format('<path d="M 0 0 L 10 0 L nan 10 Z"/>'),
    "hugepath.svg": _SVG.format('<path d="M 0 0 L 1e308 0 L 0 1e308 Z"/>'),
    "region_zero.json": json.dumps({"paths": [{"points": [[0, 0], [5, 5], [10, 10]], "closed": True}]}),
    "region_tiny.json": json.dumps({"paths": [{"points": [[0, 0], [0.01, 0], [0.01, 0.01], [0, 0.01]], "closed": True}]}),
    "region_huge.json": json.dumps({"paths": [{"points": [[0, 0], [1e300, 0], [1e300, 1e300], [0, 1e300]], "closed": True}]}),
    "region_list.json": "[]",
    "xxe.svg": (
        '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>'
        '<svg xmlns="http://www.w3.org/2000/svg"><path id="&xxe;" d="M0 0 L10 0 L0 10 Z"/></svg>'
    ),
    "lol.svg": (
        '<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaaaaaaaa">'
        + "".join(f'<!ENTITY {chr(98 + i)} "{("&" + chr(97 + i) + ";") * 10}">' for i in range(8))
        + ']><svg xmlns="http://www.w3.org/2000/svg"><path id="&i;" d="M0 0 L10 0 L0 10 Z"/></svg>'
    ),
    "bad.txt": "hello",
    "notutf8.json": b"\xff\xfe\x00garbage",
    "script.txt": "arrangement = None\n",
}
# Oversized files: over the limit set below through STREW_LIMIT_FILE_SIZE (a byte count).
OVERSIZE_LIMIT = 4096
FILES["big.json"] = _doc(x=[0.0] * 600, y=[0.0] * 600, kind=["a"] * 600, rotation=[0.0] * 600, scale=[1.0] * 600)
FILES["big.svg"] = _SVG.format('<path d="M0 0 L10 0 L0 10 Z"/>' * 200)

EXEMPLAR_BAD = {
    # file -> token the message must contain
    "malformed.json": "malformed JSON",
    "truncated.json": "malformed JSON",
    "list.json": "document",
    "wrongshape.json": "elements.x",
    "badpoints.json": "shapes.a",
    "deep.json": "nested",
    "nan.json": "elements.x[1]",
    "inf.json": "elements.y[1]",
    "huge.json": "elements.x[1]",
    "hugeshape.json": "shapes.a",
    "hugescale.json": "elements.scale[1]",
    "zeroscale.json": "elements.scale[1]",
    "negscale.json": "elements.scale[1]",
    "emptyfile.json": "malformed JSON",
    "noshapes.svg": "no shapes",
    "emptyfile.svg": "malformed XML",
    "nanpath.svg": "nanpath.svg",
    "hugepath.svg": "hugepath.svg",
    "xxe.svg": "xxe.svg",
    "lol.svg": "lol.svg",
    "bad.txt": "unsupported extension",
    "notutf8.json": "UTF-8",
    "missing.json": "no such file",
    "DIR.json": "DIR.json",
    "big.json": "--limit-file-size",
    "big.svg": "--limit-file-size",
}
# Documents that are unusable as an exemplar (no element, degenerate shapes).
# A self-intersecting shape is repaired under the even-odd rule (with a warning): valid.
EXEMPLAR_ONLY = {"empty.json": "elements", "selfint.json": OK, "zeroarea.json": "area"}

REGION_BAD = {
    "malformed.json": "malformed JSON",
    "list.json": "region",
    "region_list.json": "region",
    "region_zero.json": "region",
    "region_huge.json": "region",
    "hugeshape.json": "shapes.a",
    "noshapes.svg": "region",
    "bad.txt": "unsupported extension",
    "missing.json": "no such file",
    "DIR.json": "DIR.json",
    "xxe.svg": "xxe.svg",
    "lol.svg": "lol.svg",
    "big.svg": "--limit-file-size",
}

OUT_BAD = {
    "/proc/strew-probe.json": "--out",
    "LONG": "--out",
    "OUTPATH/out.txt": "unsupported extension",
    "OUTPATH/nofolder/out.json": "does not exist",
    "OUTDIR": "--out",
}

# A valid run of each command with --out; {OUT} is replaced by the output path.
BASE = {
    "render": ["render", "IN/valid.json", "--out", "{OUT}"],
    "pack": ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--out", "{OUT}"],
    "ornament": ["ornament", "dots", "--size", "60x60", "--out", "{OUT}"],
    "run": ["run", str(EXAMPLES / "program" / "fig03_two_scales.py"), "--size", "100", "--out", "{OUT}"],
    "grow": ["grow", str(EXAMPLES / "exemplars" / "scales.svg"), "--count", "5", "--out", "{OUT}"],
    "synth": ["synth", str(EXAMPLES / "synth" / "stones.json"), "--size", "60x60", "--out", "{OUT}"],
}


def _cases() -> list[tuple[str, list[str], str | None]]:
    cases: list[tuple[str, list[str], str | None]] = []
    # -- input files -------------------------------------------------------------------
    exemplar_slots = {
        "render": lambda f: ["render", f, "--out", "{OUT}"],
        "info": lambda f: ["info", f],
        "pack": lambda f: ["pack", f, "--size", "60x60", "--out", "{OUT}"],
        "grow": lambda f: ["grow", f, "--count", "5", "--out", "{OUT}"],
        "synth": lambda f: ["synth", f, "--size", "60x60", "--out", "{OUT}"],
    }
    for cmd, make in exemplar_slots.items():
        table = dict(EXEMPLAR_BAD)
        if cmd not in ("render", "info"):
            table.update(EXEMPLAR_ONLY)
            if cmd == "grow":  # growth copies positions and neighbourhoods: any shape will do
                table["zeroarea.json"] = OK
            if cmd == "synth":  # handled, though the message blames the region (synth's own check)
                table["zeroarea.json"] = "no element fits"
        else:
            table["empty.json"] = OK  # an empty document is a valid document to convert or describe
        if cmd == "pack":  # a shape library needs shapes, not elements
            table["empty.json"] = OK
            for name in ("nan.json", "inf.json", "huge.json", "hugescale.json", "zeroscale.json", "negscale.json", "wrongshape.json"):
                table[name] = table[name].split("[")[0]
        for name, token in table.items():
            cases.append((f"{cmd}-input-{name}", make(f"IN/{name}"), token))
    region_slots = {
        "pack": lambda f: ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--region", f, "--out", "{OUT}"],
        "ornament": lambda f: ["ornament", "dots", "--region", f, "--out", "{OUT}"],
        "grow": lambda f: ["grow", str(EXAMPLES / "exemplars" / "scales.svg"), "--region", f, "--out", "{OUT}"],
        "synth": lambda f: ["synth", str(EXAMPLES / "synth" / "stones.json"), "--region", f, "--out", "{OUT}"],
    }
    for cmd, make in region_slots.items():
        for name, token in {**REGION_BAD, "region_tiny.json": "region"}.items():
            cases.append((f"{cmd}-region-{name}", make(f"IN/{name}"), token))
    # -- outputs -----------------------------------------------------------------------
    for cmd, argv in BASE.items():
        for out, token in OUT_BAD.items():
            cases.append((f"{cmd}-out-{out.replace('OUTPATH/', '').replace('/', '_')[:20]}", [a if a != "{OUT}" else out for a in argv], token))
        # several outputs, the last one unwritable: nothing at all is written
        i = argv.index("{OUT}")
        several = argv[:i] + ["{OUT}", "--out", "OUTPATH/b.svg", "--out", "/proc/strew-probe.png"] + argv[i + 1 :]
        cases.append((f"{cmd}-out-several", several, "--out"))
    # -- sizes, counts and other options -------------------------------------------------
    for cmd in ("pack", "ornament", "grow", "synth"):
        argv = BASE[cmd]
        i = argv.index("--size") if "--size" in argv else None
        for size, token in (("1e9x1e9", "--size"), ("0x10", "--size"), ("-5x10", "--size"), ("nanx10", "--size"),
                            ("infx10", "--size"), ("1e308x1e308", "--size"), ("10", "--size"), ("0.001x0.001", "region")):
            if i is None:
                new = argv[:-2] + ["--size", size] + argv[-2:]
            else:
                new = argv[: i + 1] + [size] + argv[i + 2 :]
            if cmd == "grow":
                new = [a for a in new]
                j = new.index("--count")
                del new[j : j + 2]
            cases.append((f"{cmd}-size-{size}", new, token))
    extra = [
        ("grow-count-1e9", ["grow", str(EXAMPLES / "exemplars" / "scales.svg"), "--count", "1000000000", "--out", "{OUT}"], "--count"),
        ("grow-count-0", ["grow", str(EXAMPLES / "exemplars" / "scales.svg"), "--count", "0", "--out", "{OUT}"], "--count"),
        ("grow-count--5", ["grow", str(EXAMPLES / "exemplars" / "scales.svg"), "--count", "-5", "--out", "{OUT}"], "--count"),
        ("grow-spray-radius-neg", ["grow", str(EXAMPLES / "exemplars" / "scales.svg"), "--count", "5", "--spray-radius", "-1", "--out", "{OUT}"], "--spray-radius"),
        ("ornament-min-radius-1e-9", ["ornament", "dots", "--size", "60x60", "--min-radius", "1e-9", "--out", "{OUT}"], "--min-radius"),
        ("ornament-min-radius-0", ["ornament", "dots", "--size", "60x60", "--min-radius", "0", "--out", "{OUT}"], "--min-radius"),
        ("ornament-min-radius-nan", ["ornament", "dots", "--size", "60x60", "--min-radius", "nan", "--out", "{OUT}"], "--min-radius"),
        ("ornament-cells-1e9", ["ornament", "dots", "--size", "60x60", "--cells", "1000000000", "--out", "{OUT}"], "--cells"),
        ("ornament-cells-0", ["ornament", "dots", "--size", "60x60", "--cells", "0", "--out", "{OUT}"], "--cells"),
        ("ornament-max-elements-neg", ["ornament", "dots", "--size", "60x60", "--max-elements", "-1", "--out", "{OUT}"], "--max-elements"),
        ("ornament-pattern-missing", ["ornament", "nosuchpattern", "--size", "60x60", "--out", "{OUT}"], "nosuchpattern"),
        ("ornament-rules-dir", ["ornament", "IN", "--size", "60x60", "--out", "{OUT}"], "pattern"),
        ("pack-candidates-1e9", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--candidates", "1000000000", "--out", "{OUT}"], "--candidates"),
        ("pack-candidates-0", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--candidates", "0", "--out", "{OUT}"], "--candidates"),
        ("pack-max-failures-1e12", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--max-failures", "1000000000000", "--out", "{OUT}"], "--max-failures"),
        ("pack-max-failures-neg", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--max-failures", "-1", "--out", "{OUT}"], "--max-failures"),
        ("pack-resolution-1e-9", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--resolution", "1e-9", "--out", "{OUT}"], "--resolution"),
        ("pack-resolution-0", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--resolution", "0", "--out", "{OUT}"], "--resolution"),
        ("pack-power-nan", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--power", "nan", "--out", "{OUT}"], "--power"),
        ("pack-scale-0", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--scale", "0:0", "--out", "{OUT}"], "--scale"),
        ("pack-scale-neg", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--scale", "-2:-1", "--out", "{OUT}"], "--scale"),
        ("pack-scale-1e-9", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--scale", "1e-9:1e-9", "--out", "{OUT}"], "--scale"),
        ("pack-margin-nan", ["pack", str(EXAMPLES / "pack" / "leaf.json"), "--size", "60x60", "--margin", "nan", "--out", "{OUT}"], "--margin"),
        ("synth-k-0", ["synth", str(EXAMPLES / "synth" / "stones.json"), "--size", "60x60", "--k", "0", "--out", "{OUT}"], "--k"),
        ("synth-c-nan", ["synth", str(EXAMPLES / "synth" / "stones.json"), "--size", "60x60", "--c", "nan", "--out", "{OUT}"], "--c"),
        ("synth-fill-nan", ["synth", str(EXAMPLES / "synth" / "stones.json"), "--size", "60x60", "--fill", "nan,5", "--out", "{OUT}"], "--fill"),
        ("synth-brush-radius-neg", ["synth", str(EXAMPLES / "synth" / "stones.json"), "--size", "60x60", "--brush", str(EXAMPLES / "synth" / "stroke.json"), "--brush-radius", "-3", "--out", "{OUT}"], "--brush-radius"),
        ("run-missing", ["run", "IN/missing.py", "--out", "{OUT}"], "missing.py"),
        ("run-dir", ["run", "IN", "--out", "{OUT}"], "SCRIPT"),
        ("run-bad-ext", ["run", "IN/script.txt", "--out", "{OUT}"], "script.txt"),
        ("run-size-0", ["run", str(EXAMPLES / "program" / "fig03_two_scales.py"), "--size", "0", "--out", "{OUT}"], "--size"),
        ("run-size-nan", ["run", str(EXAMPLES / "program" / "fig03_two_scales.py"), "--size", "nan", "--out", "{OUT}"], "--size"),
        ("run-size-1e308", ["run", str(EXAMPLES / "program" / "fig03_two_scales.py"), "--size", "1e308", "--out", "{OUT}"], "--size"),
        ("render-width-1e9", ["render", "IN/valid.json", "--width", "1000000000", "--out", "OUTPATH/a.png"], "--width"),
        ("demo-only-unknown", ["demo", "--only", "nosuchsection", "--out", "OUTPATH/gallery"], "nosuchsection"),
        ("info-missing", ["info", "IN/missing.json"], "no such file"),
    ]
    cases += extra
    return cases


CASES = _cases()


def make_inputs(folder: Path) -> None:
    for name, text in FILES.items():
        p = folder / name
        if isinstance(text, bytes):
            p.write_bytes(text)
        else:
            p.write_text(text)
    (folder / "DIR.json").mkdir()


def resolve(argv: list[str], inputs: Path, out_dir: Path) -> list[str]:
    long_name = "x" * 250 + ".json"
    out: list[str] = []
    for a in argv:
        if a == "{OUT}":
            a = str(out_dir / "out.json")
        elif a == "LONG":
            a = str(out_dir / long_name)
        elif a == "OUTDIR":
            a = str(out_dir / "adir.json")
        elif a == "IN":
            a = str(inputs)
        elif a.startswith("IN/"):
            a = str(inputs / a[3:])
        elif a.startswith("OUTPATH/"):
            a = str(out_dir / a[8:])
        out.append(a)
    return out


def judge(code: int, err: str, token: str | None, written: list[str]) -> str | None:
    """None when handled correctly, else what went wrong."""
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    if "Traceback" in err:
        return f"traceback (exit {code})"
    if token is OK:
        return None if code == 0 else f"exit {code} on valid input: {err.strip()[:200]}"
    if code != 2:
        return f"exit {code}, expected 2: {err.strip()[-200:]}"
    if len(lines) != 1 or not lines[0].startswith("strew: error:"):
        return f"not one line: {err.strip()[:200]}"
    # the library names its parameters without dashes (--min-radius -> min_radius)
    if token not in lines[0] and token.lstrip("-").replace("-", "_") not in lines[0]:
        return f"message does not name {token!r}: {lines[0][:200]}"
    if written:
        return f"wrote {written}"
    return None


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("inputs")
    make_inputs(folder)
    return folder


@pytest.mark.parametrize("case_id, argv, token", CASES, ids=[c[0] for c in CASES])
def test_bad_input(case_id, argv, token, inputs, tmp_path, capfd, monkeypatch):
    from strew.cli import main

    if "big." in case_id:
        monkeypatch.setenv("STREW_LIMIT_FILE_SIZE", str(OVERSIZE_LIMIT))
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    (out_dir / "adir.json").mkdir()
    before = {p.name for p in out_dir.iterdir()}
    code = main([*resolve(argv, inputs, out_dir), "-q"] if argv[0] != "info" else resolve(argv, inputs, out_dir))
    err = capfd.readouterr().err
    written = sorted({p.name for p in out_dir.iterdir()} - before)
    if token is OK:
        written = []
    problem = judge(code, err, token, written)
    assert problem is None, problem


def test_output_files_follow_the_umask(inputs, tmp_path):
    from strew.cli import main

    old = os.umask(0o022)
    try:
        assert main(["render", str(inputs / "valid.json"), "--out", str(tmp_path / "a.json"), "-q"]) == 0
    finally:
        os.umask(old)
    assert (tmp_path / "a.json").stat().st_mode & 0o777 == 0o644


def test_limits_can_be_raised(inputs, tmp_path, capfd, monkeypatch):
    """The message names the limit, and the option it names lets the same input through."""
    from strew.cli import main

    monkeypatch.setenv("STREW_LIMIT_FILE_SIZE", str(OVERSIZE_LIMIT))
    out = tmp_path / "a.json"
    assert main(["render", str(inputs / "big.json"), "--out", str(out), "-q"]) == 2
    assert "--limit-file-size" in capfd.readouterr().err and not out.exists()
    assert main(["--limit-file-size", "1MB", "render", str(inputs / "big.json"), "--out", str(out), "-q"]) == 0
    assert out.exists()
    # the option holds for one run only
    assert main(["render", str(inputs / "big.json"), "--out", str(out), "-q"]) == 2
    capfd.readouterr()
    # work limits: refused by default, accepted with the limit raised (checked, not run)
    from strew import Region, limits
    from strew._limits import check_work

    with pytest.raises(Exception, match="--limit-elements"):
        check_work("--count", count=1e9)
    with limits(elements=2e9):
        check_work("--count", count=1e9)
    assert main(["--limit-elements", "nonsense", "render", str(inputs / "valid.json"), "--out", str(out)]) == 2
    assert "--limit-elements" in capfd.readouterr().err
    with pytest.raises(Exception, match="--size/--region"):
        check_work("--size/--region", region=Region.rectangle(1e6, 1e6), per_element=1.0)


def _probe_subprocess(timeout: float = 30.0) -> None:  # pragma: no cover - a measurement, run by hand
    import subprocess
    import tempfile

    tried = handled = 0
    bad: list[tuple[str, str]] = []
    with tempfile.TemporaryDirectory() as d:
        inputs = Path(d) / "inputs"
        inputs.mkdir()
        make_inputs(inputs)
        only = sys.argv[1:]
        for case_id, argv, token in CASES:
            if only and not any(o in case_id for o in only):
                continue
            out_dir = Path(d) / f"out-{tried}"
            out_dir.mkdir()
            (out_dir / "adir.json").mkdir()
            before = {p.name for p in out_dir.iterdir()}
            args = resolve(argv, inputs, out_dir) + ([] if argv[0] == "info" else ["-q"])
            tried += 1
            try:
                env = {**os.environ, **({"STREW_LIMIT_FILE_SIZE": str(OVERSIZE_LIMIT)} if "big." in case_id else {})}
                r = subprocess.run([sys.executable, "-m", "strew", *args], capture_output=True, text=True, timeout=timeout, cwd=d, env=env)
                written = [] if token is OK else sorted({p.name for p in out_dir.iterdir()} - before)
                problem = judge(r.returncode, r.stderr, token, written)
            except subprocess.TimeoutExpired:
                problem = f"hang (over {timeout:g} s)"
            if problem is None:
                handled += 1
            else:
                bad.append((case_id, problem))
            print(f"{case_id}: {'ok' if problem is None else 'MISHANDLED ' + problem}", flush=True)
    print(f"\ntried {tried}, handled {handled}, mishandled {len(bad)}")
    for case_id, problem in bad:
        print(f"  {case_id}: {problem}")


if __name__ == "__main__":  # pragma: no cover
    _probe_subprocess(float(os.environ.get("PROBE_TIMEOUT", "30")))
