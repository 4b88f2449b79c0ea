"""The README's Python example, run as the README shows it (its ```python block under
"## Python"), in a temporary folder: it must run, write its figure, and its curve must end
at the classical limit it claims."""
import os
import re

import pytest

SOURCE = os.environ.get("RELCOL_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))


def readme_python_block():
    text = open(os.path.join(SOURCE, "README.md"), encoding="utf-8").read()
    section = text.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert len(blocks) == 1
    return blocks[0]


def test_readme_sweep_over_c(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.chdir(tmp_path)
    import matplotlib
    matplotlib.use("Agg")
    code = readme_python_block()
    assert len(code.strip().splitlines()) <= 10
    ns = {}
    exec(compile(code, "README.md", "exec"), ns)
    assert (tmp_path / "sweep-c.png").stat().st_size > 10000
    v0 = ns["v0"]
    # at c = 100 the relativistic correction is of order (v/c)^2 = 2.5e-5 of the velocity
    assert v0[-1] == pytest.approx(-1 / 6, rel=1e-4)
    # and at c = 0.55 (v = 0.91 c) it is large: the curve shows something
    assert abs(v0[0] + 1 / 6) > 0.02
