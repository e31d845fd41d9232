"""The examples of docs/python.md run as they are, in order, in one namespace (as a notebook runs
its cells), from a directory where cases/ holds the shipped cases."""
import os
import re

from conftest import SOURCE_DIR


def python_blocks(path):
    with open(path) as f:
        return re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)


def test_the_examples_of_python_md_run(tmp_path, monkeypatch, capsys):
    blocks = python_blocks(os.path.join(SOURCE_DIR, "docs", "python.md"))
    assert len(blocks) >= 3
    os.symlink(os.path.join(SOURCE_DIR, "cases"), tmp_path / "cases")
    (tmp_path / "out").mkdir()
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for k, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md, example {k + 1}", "exec"), namespace)
    assert os.path.getsize(tmp_path / "out" / "slab" / "density.png") > 0
    printed = capsys.readouterr().out
    assert "A = " in printed and "theta (DSMC)" in printed
