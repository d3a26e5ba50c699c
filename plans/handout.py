"""Handouts: the course project of one mechanism as a plate of A4 pages, PDF (or SVG/PNG pages).

Orchestration only: :func:`write_handout` asks :mod:`plans.pages.handout` for
the document (the positions solved by :mod:`plans.positions`, the drawings by
:mod:`plans.drawing.svgblocks`, the pages set by Typst) and writes its files.
Importing this module loads neither matplotlib nor Typst.

What a handout holds, in the plate's order (domain.md §10): the data and the
plan of positions at one k_l; the vector equations with the known parts
underlined; the velocity plans of every position at one k_v; the
acceleration plans of the chosen positions (two unless asked: one of the
working, one of the idle stroke) at one k_a; the tables of graphical against
analytic values; the complex-number loop equations; the kinematic diagrams;
with ``centres``, a page of instant centres per position.  One position
(``positions=None``): the mechanism, its plans, the tables and the loop
equations.  Every page has a frame, a binding margin and a title block.
"""

from __future__ import annotations

from pathlib import Path

from .errors import PlansError
from .i18n import check_language, term
from .pages.words import cycle_lines, scene_data_lines  # noqa: F401 (the handout API)
from .scene import Scene

__all__ = ["HandoutError", "write_handout", "handout", "scene_data_lines", "cycle_lines"]

class HandoutError(PlansError, ValueError):
    """A handout that cannot be written as asked (such as several pages into one SVG)."""


# --- words ------------------------------------------------------------------------------


def handout(
    scene: Scene,
    *,
    positions=None,
    lang: str = "en",
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    components: bool = False,
    progress=None,
    centres: bool = False,
    accelerations=None,
    scales: str = "plate",
    forces: bool = False,
    law: str | None = None,
    start: str = "output",
):
    """The handout of *scene* as a :class:`plans.pages.handout.Handout` (Typst source and drawings; ``.pdf()``).

    Arguments as :func:`write_handout`.
    """
    from .pages.handout import build_handout

    try:
        check_language(lang)
    except ValueError as exc:
        raise HandoutError(str(exc)) from None
    if forces and not scene.has_forces:
        from .errors import SceneError

        raise SceneError("--forces: the scene has no masses and no loads, so there is no kinetostatics to draw "
                         "(give mass, centre, inertia on the links, [gravity] and [[load]]; plans examples --loads lists scenes that do)", scene.source)
    if scales not in SCALES:
        raise HandoutError(f"scales: {scales!r} is not one of {', '.join(SCALES)}")
    return build_handout(scene, positions=positions, lang=lang, k_l=k_l, k_v=k_v, k_a=k_a, precision=precision, components=components,
                         progress=progress, centres=centres, accelerations=accelerations, scales=scales, forces=forces, law=law, start=start)


#: ``"plate"``: one k_l, k_v, k_a over the whole handout; ``"per-position"``: k_v, k_a chosen for each position.
SCALES = ("plate", "per-position")


def write_handout(
    scene: Scene,
    path,
    *,
    positions=None,
    lang: str = "en",
    k_l: float | None = None,
    k_v: float | None = None,
    k_a: float | None = None,
    precision: float | None = None,
    components: bool = False,
    progress=None,
    centres: bool = False,
    accelerations=None,
    scales: str = "plate",
    forces: bool = False,
    law: str | None = None,
    start: str = "output",
) -> list[Path]:
    """Write the handout of a scene: a PDF of A4 pages, or SVG/PNG pages.

    Parameters
    ----------
    scene : Scene
    path : str or pathlib.Path
        ``FILE.pdf``: every page in one file.  ``FILE.svg`` or ``FILE.png``:
        one file per page, ``FILE-01.svg``, ``FILE-02.svg``, … (numbers
        zero-padded, so they sort in page order).
    positions : None, int, str or sequence
        None: the scene's own position.  Otherwise anything
        :func:`plans.positions.parse_positions` takes (``12``,
        ``"0,30,55,90 deg"``): the plate of every position.
    lang : str
        ``"en"`` (default), ``"sr"``, ``"ru"``, ``"bg"`` or ``"sl"``: every
        word on the pages; the scene's title and names as it gives them in that
        language (else as written).
    k_l, k_v, k_a : float, optional
        Scale factors; by default the round values with which the largest
        drawing of each kind fills its room on the page — one of each for the
        whole handout.
    precision : float, optional
        Drafting precision [mm] of the graphical readings (default: the
        scene's ``[scales] precision``, else 0.1 mm; 0 gives exact readings).
    components : bool
        Cycle diagrams of the x and y components of every point's v and a too.
    progress : callable, optional
        Called with a short text (``"position 3/12"``) as the work goes on.
    centres : bool
        A page of instant centres (Kennedy's theorem) for every position.
    accelerations : None, "all" or list of int
        The positions whose acceleration plans are drawn: by default two, one
        of the working and one of the idle stroke (each the position nearest
        the stroke's middle whose plan does not collapse onto a line).
    scales : str
        ``"plate"`` (default): one k_v and one k_a for the whole handout;
        ``"per-position"``: each position's own (and the pages say so).
    forces : bool
        The kinetostatic pages of the positions whose acceleration plans are
        drawn (the scene must have masses or loads): the free bodies of the
        groups with their loads and reactions, each group's force plan and the
        driver's with the reactions read off them and M_b, and Joukowski's
        lever, the three methods side by side (:mod:`plans.pages.forces`).
    law : str, optional
        The driver's law over the cycle (``"constant"``, ``"uniform"``,
        ``"harmonic"``; :func:`plans.motion.driver_law`); None: the scene's
        ``[driver] law`` or the default.  Stated with the data and on the diagrams.
    start : {"output", "scene"}
        Position 0 of a count: the extreme position of the output link that
        starts its working stroke (default), or the scene's own position.

    Returns
    -------
    list of pathlib.Path
        The files written (one for a PDF).

    Raises
    ------
    HandoutError
        For a file that is neither .pdf, .svg nor .png, an unknown language or scales.
    StructureError, SceneError, AssemblyError, SingularPositionError
        For a scene that cannot be solved (a single position that cannot be
        assembled included; in a multi-position run such a position gets a
        line that says why).
    """
    from ._files import replace_all

    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".pdf", ".svg", ".png"):
        raise HandoutError(f"{path}: a handout is written as .pdf (or .svg or .png, one file per page), not {path.suffix or 'a file without a suffix'}")
    try:
        check_language(lang)
    except ValueError as exc:
        raise HandoutError(str(exc)) from None
    if positions is None:
        _check_solvable(scene)
    document = handout(scene, positions=positions, lang=lang, k_l=k_l, k_v=k_v, k_a=k_a, precision=precision, components=components,
                       progress=progress, centres=centres, accelerations=accelerations, scales=scales, forces=forces, law=law, start=start)
    say = progress or (lambda text: None)
    say(term("page", lang) + " …")
    if suffix == ".pdf":
        return replace_all({path: document.pdf()})
    pages = document.pages(suffix[1:])
    digits = max(2, len(str(len(pages))))
    return replace_all({path.with_name(f"{path.stem}-{number:0{digits}d}{path.suffix}"): data for number, data in enumerate(pages, start=1)})


def _check_solvable(scene: Scene) -> None:
    """A one-position handout of a position that cannot be solved is an error, with the solver's message."""
    from .analytic import solve

    solve(scene)
