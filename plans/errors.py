"""The one family of exceptions plans raises on purpose.

Every error a user can cause (a bad scene file, a mechanism that is not a
one-degree-of-freedom chain of dyads, a position where a group cannot be
assembled or is singular) is a :class:`PlansError`.  Each concrete class also
derives from the matching built-in, so ``except ValueError`` keeps working.
"""

__all__ = [
    "PlansError",
    "SceneError",
    "StructureError",
    "AssemblyError",
    "SingularPositionError",
    "OutputError",
]


class PlansError(Exception):
    """Base class of every error plans raises deliberately."""


class SceneError(PlansError, ValueError):
    """The scene file is malformed or refers to something that does not exist.

    Parameters
    ----------
    message : str
        What is wrong and what would be right.
    source : str, optional
        The file the scene came from.
    field : str, optional
        The key path inside the file, such as ``link.3.points.C``.
    """

    def __init__(self, message: str, source: str | None = None, field: str | None = None):
        self.source = source
        self.field = field
        self.detail = message
        where = ": ".join(part for part in (source, field) if part)
        super().__init__(f"{where}: {message}" if where else message)


class StructureError(PlansError, ValueError):
    """The mechanism is not a driver followed by class-II Assur groups (dyads)."""


class AssemblyError(PlansError, ArithmeticError):
    """A group cannot be assembled at the requested driver position."""


class SingularPositionError(PlansError, ArithmeticError):
    """A group sits exactly at a dead centre: its velocities do not exist."""


class OutputError(PlansError, ValueError):
    """An output path plans will not write: not a regular file (a directory, a device), or named twice."""
