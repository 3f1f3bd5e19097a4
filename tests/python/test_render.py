"""render() against `samplescope render` (the same files, byte for byte), from a path and
from RON text."""

import pathlib

import pytest

import samplescope
from compare import ROOT

SCENE = ROOT / "assets" / "scenes" / "kernel-box.ron"


def test_the_cli_files_byte_for_byte(cli, tmp_path):
    cli_out, py_out = tmp_path / "cli", tmp_path / "py"
    listed = cli("render", SCENE, "--out", cli_out, "--format", "png,csv").split()
    written = samplescope.render(SCENE, py_out, formats=["png", "csv"])
    assert [p.name for p in written] == [pathlib.Path(p).name for p in listed]
    assert written and all(isinstance(p, pathlib.Path) for p in written)
    for p in written:
        assert p.read_bytes() == (cli_out / p.name).read_bytes(), p.name


def test_scene_text_and_str_paths(tmp_path):
    from_text = samplescope.render(SCENE.read_text(), tmp_path / "t", formats=["csv"])
    from_str = samplescope.render(str(SCENE), tmp_path / "s", formats=["csv"])
    assert [p.name.replace("scene", "kernel-box") for p in from_text] == [p.name for p in from_str]
    for a, b in zip(from_text, from_str):
        assert a.read_bytes() == b.read_bytes()


def test_refused_as_the_cli_refuses(tmp_path):
    with pytest.raises(ValueError, match="no such file"):
        samplescope.render(tmp_path / "missing.ron", tmp_path / "o")
    with pytest.raises(ValueError, match="formats: gif: must be png, svg, pdf or csv"):
        samplescope.render(SCENE, tmp_path / "o", formats=["gif"])
    with pytest.raises(ValueError, match="--scale = 9"):
        samplescope.render(SCENE, tmp_path / "o", scale=9)
    (tmp_path / "file").write_text("")
    with pytest.raises(ValueError, match="not a directory"):
        samplescope.render(SCENE, tmp_path / "file")
    with pytest.raises(ValueError, match="scene.ron"):
        samplescope.render("(title: ", tmp_path / "o")
