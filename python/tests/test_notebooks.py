"""The example notebooks (python/examples/*.ipynb) run from start to end in a fresh
kernel (nbclient, python3-ipykernel) and render to HTML (nbconvert); their own
assertions -- conservation to round-off, the order -2 of the classical limit, chi-squared
p-values of the speed distributions, H5MD equal to the run's final state -- fail the
test when they fail."""
import glob
import os

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

SOURCE = os.environ.get("RELCOL_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
NOTEBOOKS = sorted(glob.glob(os.path.join(SOURCE, "python", "examples", "*.ipynb")))


def test_there_are_notebooks():
    assert {os.path.basename(p) for p in NOTEBOOKS} >= {
        "elastic_collisions.ipynb", "sweep_c.ipynb", "h5md.ipynb"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=os.path.basename)
def test_notebook_runs_and_renders(path, tmp_path, monkeypatch):
    if os.path.basename(path) == "h5md.ipynb" and "RELCOL_SIM" not in os.environ:
        pytest.skip("relcol-sim not given")
    monkeypatch.chdir(tmp_path)
    nb = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(nb, timeout=240, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # (a failing cell raises CellExecutionError with its traceback)
    errors = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
              if o.get("output_type") == "error"]
    assert not errors
    nbconvert = pytest.importorskip("nbconvert")
    html, _ = nbconvert.HTMLExporter().from_notebook_node(nb)
    out = tmp_path / (os.path.basename(path)[:-6] + ".html")
    out.write_text(html, encoding="utf-8")
    assert "<html" in html and "image/png" in html
