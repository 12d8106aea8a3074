"""examples/first_design.ipynb runs from top to bottom (nbclient), and what it
shows is right: the verdicts and kf of design 3, bound (10), the files
written, the simulation within the limits, and the figures."""
import ast
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

pytestmark = pytest.mark.slow        # more than a few seconds: not in make test-fast

NOTEBOOK = Path(__file__).resolve().parent.parent / "examples" / "first_design.ipynb"


@pytest.fixture(scope="module")
def executed():
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nbclient.NotebookClient(nb, timeout=900, kernel_name="python3",
                            resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    return nb


def _tagged(nb, tag):
    return [c for c in nb.cells if tag in c.get("metadata", {}).get("tags", [])]


def _value(cell):
    """The cell's result (its text/plain output) as a Python literal."""
    [result] = [o for o in cell.outputs if o.output_type == "execute_result"]
    return ast.literal_eval(result.data["text/plain"])


def test_no_cell_failed(executed):
    errors = [o for c in executed.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert not errors, errors


def test_verdicts_and_kf_of_design_3(executed):
    [cell] = _tagged(executed, "verdicts")
    value = _value(cell)
    assert value == {**{f"P{i}": "proved" for i in range(1, 9)}, "kf": "2", "exit_status": 0}
    report_html = [o.data["text/html"] for c in executed.cells for o in c.get("outputs", [])
                   if o.output_type == "execute_result" and "text/html" in o.data and "P8" in o.data["text/html"]]
    assert report_html and report_html[0].count(">proved</b>") == 8


def test_bound_10_and_generated_files(executed):
    [cell] = _tagged(executed, "gains")
    # |W| <= 1 + 0.3 * 0.5 * 2 + 0.7 = 2 = Wmax: lam = 0.3 is the largest lam within bound (10)
    assert _value(cell) == {"W_bound": "2", "margin": "0", "lam_max": "3/10"}
    [cell] = _tagged(executed, "generate")
    assert _value(cell) == ["CMakeLists.txt", "design_3.c", "design_3.casadi", "design_3.h", "design_3.py",
                            "example_main.c"]


def test_simulation_and_figures(executed):
    [cell] = _tagged(executed, "simulation")
    runs = _value(cell)
    for kind in ("continuous", "digital"):
        assert runs[kind]["within limits"] and runs[kind]["converged"]
        assert runs[kind]["max|V|"] <= 0.75 and runs[kind]["max|W|"] <= 2.0
    assert not runs["baseline"]["within limits"]      # (38) exceeds the limits, as in the paper
    for cell in _tagged(executed, "plot") + _tagged(executed, "profile"):
        assert any("image/png" in o.get("data", {}) for o in cell.outputs), cell.source
