"""A long chain of RRR dyads as scene text, for drawing tests and timings.

The generator lives with the benchmark (``plans bench`` times drawing such
chains): :func:`plans.bench.cases.dyad_chain_toml`.
"""

from __future__ import annotations

from plans.bench.cases import dyad_chain_toml as chain_toml

__all__ = ["chain_toml"]
