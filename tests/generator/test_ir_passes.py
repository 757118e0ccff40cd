"""generator/ir.py runs every pass of generator/passes/ (none forgotten), each with its tests."""

from pathlib import Path

from generator.ir import PASSES

PASSES_DIR = Path(__file__).resolve().parents[2] / "generator" / "passes"
TESTS_DIR = Path(__file__).resolve().parent / "passes"
HELPERS = {"__init__", "context", "params", "sizes", "time_sync"}  # parts of passes, not passes themselves


def test_every_pass_module_runs_in_order():
    names = [p.__name__.rsplit(".", 1)[1] for p in PASSES]
    modules = {p.stem for p in PASSES_DIR.glob("*.py")} - HELPERS
    assert sorted(names) == sorted(modules)
    assert names[0] == "collect_types" and names[-1] == "assemble"
    assert all(callable(p.run) for p in PASSES)


def test_every_pass_has_its_tests():
    names = [p.__name__.rsplit(".", 1)[1] for p in PASSES] + ["params"]
    assert [n for n in names if not (TESTS_DIR / f"test_{n}.py").exists()] == []
