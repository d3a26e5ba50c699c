"""The test processes of one run share the handouts and sheets they build (tests/review_handouts.py)."""

from __future__ import annotations

import pytest

import review_handouts


@pytest.fixture(scope="session", autouse=True)
def _builds_shared_by_the_runs_workers(request, tmp_path_factory):
    """Under pytest-xdist, each worker's temporary directory lies in the run's own (removed as pytest removes old
    runs): the workers share their builds there. A single process keeps its own."""
    if hasattr(request.config, "workerinput"):
        review_handouts.share_in(tmp_path_factory.getbasetemp().parent / "shared-builds")
    yield
