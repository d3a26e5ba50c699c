"""scripts/bench_pages.py times plans as installed: a copy of the package with its bytecode compiled."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _bench_module():
    spec = importlib.util.spec_from_file_location("bench_pages", ROOT / "scripts" / "bench_pages.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_benchmark_runs_a_compiled_copy_of_the_package(tmp_path):
    site = _bench_module()._installed(tmp_path)
    sources = sorted(p.relative_to(site) for p in (site / "plans").rglob("*.py"))
    assert sources == sorted(p.relative_to(ROOT) for p in (ROOT / "plans").rglob("*.py"))  # every module copied
    for source in (site / "plans").rglob("*.py"):  # and compiled beside it, as pip leaves it
        assert list((source.parent / "__pycache__").glob(source.stem + ".*.pyc")), source
    env = {**os.environ, "PYTHONPATH": str(site), "PYTHONDONTWRITEBYTECODE": "1"}
    out = subprocess.run([sys.executable, "-c", "import plans.cli, sys; print(plans.cli.__file__); print(plans.cli.__cached__)"],
                         capture_output=True, text=True, check=True, cwd=tmp_path, env=env).stdout.split()
    assert Path(out[0]).parent.parent == site and Path(out[1]).exists()  # the copy is what runs, from its bytecode
