"""strew demo: the gallery is written, complete and repeatable (the whole gallery, built
once, is checked in test_gallery.py)."""

from __future__ import annotations

from strew.cli import main


def test_basics_section_writes_svg_png_json_and_index(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["demo", "--out", "g", "--only", "basics", "-q"]) == 0
    out = tmp_path / "g"
    svgs = sorted(out.glob("*.svg"))
    assert svgs, "the basics section must show the exemplars in examples/exemplars"
    for svg in svgs:
        assert (out / f"{svg.stem}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert (out / f"{svg.stem}.json").exists()
    index = (out / "index.html").read_text()
    for svg in svgs:
        assert f'href="{svg.name}"' in index and f'src="{svg.stem}.png"' in index


def test_gallery_is_deterministic(tmp_path, monkeypatch):
    for d in ("a", "b"):
        monkeypatch.chdir(tmp_path)
        assert main(["demo", "--out", d, "--only", "basics", "-q"]) == 0
    for f in (tmp_path / "a").glob("*.json"):
        assert f.read_bytes() == (tmp_path / "b" / f.name).read_bytes()


def test_unknown_section_is_a_usage_error(tmp_path, capsys):
    assert main(["demo", "--out", str(tmp_path / "g"), "--only", "nosuchsection"]) == 2
    assert "no gallery section matches" in capsys.readouterr().err


def test_demo_reports_each_section_when_stderr_is_not_a_terminal(tmp_path, capsys):
    # a log or CI: no progress bar, so one line per section tells the gallery is moving
    assert main(["demo", "--out", str(tmp_path / "g"), "--only", "basics"]) == 0
    err = capsys.readouterr().err
    assert "gallery 1/1: Basics" in err
    assert main(["demo", "--out", str(tmp_path / "h"), "--only", "basics", "-q"]) == 0
    assert capsys.readouterr().err == ""
