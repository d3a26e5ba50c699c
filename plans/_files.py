"""All-or-none file output: every file of one command is written, or none is.

:func:`replace_all` is the one writer of plans.  It renders nothing: it takes
the finished bytes of every file and commits them together:

1. every target is checked first: it must be a regular file or absent (a
   symbolic link is followed to what it points at).  A directory, device,
   pipe or socket is refused with :class:`plans.errors.OutputError`, so
   ``-o /dev/null`` run as root never replaces the device node;
2. missing directories are created (only now, at commit time), each file is
   written in full and flushed to a temporary file in its own directory (a
   short name, ``.pl`` + 8 characters, so a target name near the file
   system's 255-byte limit still works);
3. the existing targets are kept under temporary names (a hard link, or a
   copy where links are not possible), and the temporary files are renamed
   onto the targets.

If anything fails on the way, everything is undone: the targets renamed so
far get their old content back (or are removed if they were new), the
temporary files are removed and so are the directories this commit created.
The output location is then as it was.  (A process killed during the renames
themselves can still leave some targets new and some old; it leaves no
half-written file.)

Inside ``with batch():`` the calls of :func:`replace_all` are collected and
committed together when the block ends without an exception, so a command
that writes a CSV and three diagrams through different modules writes all
four or none.

A writer that replaces a family of files (the sheets of a multi-position run)
may remove old members of the family, but only those plans itself wrote:
the names and SHA-256 digests of the members written are recorded in a
comment at the end of one file that is always written with them (the plan
of positions, ``positions.svg``), and a later run removes only members that
record lists and whose content is still what plans wrote.  A user's own
``sheet-99.svg``, or a sheet the user edited, is never removed, and no extra
file is left in the directory.
"""

from __future__ import annotations

import contextlib
import contextvars
import hashlib
import os
import re
import secrets
import shutil
import stat
from dataclasses import dataclass, field
from pathlib import Path

from .errors import OutputError

__all__ = ["write_atomic", "replace_all", "batch"]

#: First line of the record of a family of files, an XML comment at the end of the record file.
RECORD = "<!-- plans wrote these files with this one (name SHA-256); a later run removes only these, if unchanged"
#: Prefix of temporary names: ``.pl`` and 8 random characters (11 bytes).
_PREFIX = ".pl"


def write_atomic(path: str | Path, data: str | bytes) -> Path:
    """Write *data* to *path* through a temporary file and a rename; see :func:`replace_all`."""
    return replace_all({Path(path): data})[0]


def replace_all(contents: dict[Path, str | bytes], *, stale: tuple[str | Path, str, str] | None = None) -> list[Path]:
    """Write several files so that either all are replaced or none is.

    Parameters
    ----------
    contents : dict
        Target path -> its whole content (str is written as UTF-8).
    stale : (directory, pattern, record), optional
        A family of files: those of *directory* whose names match the
        regular expression *pattern* fully.  Members not among *contents*
        are removed if plans wrote them (the record at the end of the file
        *record* of *directory* lists them with the content they still
        have); the members written now are recorded at the end of *record*,
        an SVG or other XML file among *contents*.

    Returns
    -------
    list of pathlib.Path
        The targets, in the order given.

    Raises
    ------
    plans.errors.OutputError
        A target is not a regular file (a directory, a device, ...), or two
        outputs of one command are the same file.
    OSError
        A directory or file cannot be created or written; nothing is changed.
    """
    pending = _CURRENT.get()
    own = pending is None
    if own:
        pending = _Pending()
    paths = pending.add(contents, stale)
    if own:
        pending.commit()
    return paths


@contextlib.contextmanager
def batch():
    """Collect every :func:`replace_all` inside the block; commit them together at its end.

    An exception in the block discards them all (nothing is written).  A
    ``batch`` inside another joins the outer one.
    """
    if _CURRENT.get() is not None:
        yield
        return
    pending = _Pending()
    token = _CURRENT.set(pending)
    try:
        yield
    finally:
        _CURRENT.reset(token)
    pending.commit()  # reached only when the block ended normally


_CURRENT: contextvars.ContextVar["_Pending | None"] = contextvars.ContextVar("plans_files_batch", default=None)


@dataclass
class _Pending:
    """Files to write (resolved target -> bytes) and families to prune, not yet committed."""

    writes: dict[Path, bytes] = field(default_factory=dict)
    stale: list[tuple[Path, re.Pattern, Path]] = field(default_factory=list)

    def add(self, contents, stale) -> list[Path]:
        paths = []
        for path, data in contents.items():
            path = Path(path)
            target = _target(path)
            if target in self.writes:
                raise OutputError(f"cannot write {path}: two outputs of this command would be written to this one file")
            self.writes[target] = data.encode("utf-8") if isinstance(data, str) else bytes(data)
            paths.append(path)
        if stale is not None:
            directory, pattern, record = stale
            directory = _resolve(Path(directory))
            if directory / record not in self.writes:
                raise ValueError(f"the record {record!r} of a family of files must be written with it")
            self.stale.append((directory, re.compile(pattern), directory / record))
        return paths

    def commit(self) -> None:
        writes = dict(self.writes)
        removes: list[Path] = []
        for directory, pattern, record in self.stale:
            text, gone = _prune(directory, pattern, record, writes)
            removes += [path for path in gone if path not in removes]
            writes[record] = writes[record] + text
        _commit(writes, removes)


def _resolve(path: Path) -> Path:
    """*path* made absolute, every symbolic link on it followed (the file a write replaces)."""
    return Path(os.path.realpath(path))


def _target(path: Path) -> Path:
    """The file a write to *path* replaces (see :func:`_resolve`); refused unless regular or absent."""
    target = _resolve(path)
    try:
        mode = os.lstat(target).st_mode
    except FileNotFoundError:
        return target
    except NotADirectoryError:
        raise OutputError(f"cannot write {path}: a part of this path is a file, not a directory") from None
    if not stat.S_ISREG(mode):
        kind = "Is a directory" if stat.S_ISDIR(mode) else "Not a regular file (a device, pipe or socket)"
        raise OutputError(f"cannot write {path}: {kind}; plans replaces only regular files")
    return target


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _read_record(path: Path, pattern: re.Pattern) -> dict[str, str]:
    """name -> SHA-256 of the family members listed at the end of *path* (empty if none or unreadable)."""
    try:
        if not stat.S_ISREG(os.lstat(path).st_mode):
            return {}
        text = path.read_bytes()[-200_000:].decode("utf-8", errors="replace")
    except OSError:
        return {}
    start = text.rfind(RECORD)
    if start < 0:
        return {}
    entries = {}
    for line in text[start + len(RECORD) :].splitlines():
        if line.startswith("-->"):
            break
        name, _, digest = line.partition(" ")
        if pattern.fullmatch(name) and "/" not in name and re.fullmatch(r"[0-9a-f]{64}", digest):
            entries[name] = digest
    return entries


def _current_digest(path: Path) -> str | None:
    try:
        if not stat.S_ISREG(os.lstat(path).st_mode):
            return None
        return _digest(path.read_bytes())
    except OSError:
        return None


def _prune(directory: Path, pattern: re.Pattern, record: Path, writes: dict[Path, bytes]) -> tuple[bytes, list[Path]]:
    """The record of the family's members written now, and the earlier members plans wrote to remove."""
    written = {
        target.name: _digest(data) for target, data in writes.items() if target.parent == directory and pattern.fullmatch(target.name)
    }
    removes = [
        directory / name
        for name, digest in _read_record(record, pattern).items()
        if name not in written and _current_digest(directory / name) == digest  # gone or changed: not ours any more
    ]
    text = RECORD + "\n" + "".join(f"{name} {digest}\n" for name, digest in sorted(written.items())) + "-->\n"
    return text.encode("utf-8"), removes


def _missing_directories(path: Path) -> list[Path]:
    """The ancestors of *path* that do not exist yet, outermost first."""
    missing = []
    parent = path.parent
    while not parent.exists() and parent != parent.parent:
        missing.append(parent)
        parent = parent.parent
    return missing[::-1]


def _side_name(directory: Path) -> Path:
    """An unused short name in *directory* (not created)."""
    while True:
        candidate = directory / f"{_PREFIX}{secrets.token_hex(4)}"
        if not os.path.lexists(candidate):
            return candidate


def _commit(writes: dict[Path, bytes], removes: list[Path]) -> None:
    created: list[Path] = []
    temps: dict[Path, Path] = {}  # target -> its new content under a temporary name
    backups: dict[Path, Path] = {}  # target -> its old content under a temporary name
    renamed: list[Path] = []
    removed: list[Path] = []
    try:
        for target in writes:
            for directory in _missing_directories(target):
                if not directory.exists():
                    directory.mkdir()
                    created.append(directory)
        for target, data in writes.items():
            temp = _side_name(target.parent)
            fd = os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0), 0o600)
            temps[target] = temp
            try:
                mode = os.stat(target).st_mode & 0o777
            except FileNotFoundError:
                mode = 0o644
            os.chmod(temp, mode)
            with os.fdopen(fd, "wb") as handle:
                handle.write(data)
                handle.flush()
                os.fsync(handle.fileno())
        for target in list(writes) + removes:
            if os.path.lexists(target):
                backups[target] = _keep_copy(target)
        for target in writes:
            os.replace(temps[target], target)
            del temps[target]
            renamed.append(target)
        for target in removes:
            os.unlink(target)
            removed.append(target)
    except BaseException:
        for target in reversed(renamed):
            with contextlib.suppress(OSError):
                if target in backups:
                    os.replace(backups[target], target)
                    del backups[target]
                else:
                    os.unlink(target)
        for target in reversed(removed):
            with contextlib.suppress(OSError):
                os.replace(backups[target], target)
                del backups[target]
        for temp in temps.values():
            with contextlib.suppress(OSError):
                os.unlink(temp)
        for backup in backups.values():
            with contextlib.suppress(OSError):
                os.unlink(backup)
        for directory in reversed(created):
            with contextlib.suppress(OSError):
                os.rmdir(directory)
        raise
    for backup in backups.values():
        with contextlib.suppress(OSError):
            os.unlink(backup)


def _keep_copy(target: Path) -> Path:
    """The current content of *target* under a temporary name beside it: a hard link, else a copy."""
    while True:
        side = _side_name(target.parent)
        try:
            os.link(target, side)
            return side
        except FileExistsError:
            continue
        except OSError:
            shutil.copy2(target, side)
            return side
