"""How results draw themselves: a table of functions, filled by :mod:`plans.notebook`.

The results of the methods (:mod:`plans.graphical.plan`) are data and never import
the drawing layer; their ``.plot``, ``.save`` and ``.sheet`` look their drawing
function up here.  ``import plans`` imports :mod:`plans.notebook`, which fills the
table, so the dependency runs one way: drawing → results.  This module imports
nothing.
"""

__all__ = ["DISPLAY", "display_function"]

#: ``"plot"``, ``"save"``, ``"sheet"``, ``"animate"``, ``"animate_run"`` → the function of :mod:`plans.notebook` that does it.
DISPLAY: dict = {}


def display_function(name: str):
    """The drawing function registered as *name* (a LookupError with what to do when none is)."""
    try:
        return DISPLAY[name]
    except KeyError:
        raise LookupError(f"no drawing function {name!r}: import plans (plans.notebook) to plot or save a result") from None
