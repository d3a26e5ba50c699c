"""Atomic file output: write to a temporary file beside the target, then rename.

A failed or interrupted run never leaves a half-written file and never
destroys a good one.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path

__all__ = ["write_atomic", "replace_all"]


def write_atomic(path: str | Path, data: str | bytes) -> Path:
    """Write *data* to *path* through a temporary file and :func:`os.replace`."""
    return replace_all({Path(path): data})[0]


def replace_all(contents: dict[Path, str | bytes]) -> list[Path]:
    """Write several files so that either all are replaced or none is.

    Every file is first written in full (and flushed to disk) to a temporary
    file in its own directory, with the mode of the file it replaces (0644
    for a new one); only when all are written are they renamed into place.
    If anything fails before the renames, the temporary files are removed and
    the targets are untouched.

    Returns
    -------
    list of pathlib.Path
        The targets, in the order given.
    """
    temps: list[tuple[str, Path]] = []
    try:
        for path, data in contents.items():
            path = Path(path)
            path.parent.mkdir(parents=True, exist_ok=True)
            fd, temp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
            temps.append((temp, path))
            try:
                mode = path.stat().st_mode & 0o777
            except FileNotFoundError:
                mode = 0o644
            os.chmod(temp, mode)
            with os.fdopen(fd, "wb") as handle:
                handle.write(data.encode("utf-8") if isinstance(data, str) else data)
                handle.flush()
                os.fsync(handle.fileno())
        for temp, path in temps:
            os.replace(temp, path)
        return [path for _, path in temps]
    finally:
        for temp, _ in temps:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(temp)
