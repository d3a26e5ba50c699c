"""The words of a solution's construction as plain lines: its vector equations, the guides as the scene names
them, the results table's header in the page's language and the groups' assembly branches.

The sheets themselves are set by Typst (:mod:`plans.pages.sheet`); these lines serve the command line's
output and the pages (the handout's tables, :mod:`plans.pages.equations`).
"""

from __future__ import annotations

import re

from ..i18n import branch_text, term

__all__ = ["branch_lines", "sheet_equations", "guide_names", "translate_table", "label_driver"]

#: a guide as the construction names it, ``frame.ram`` or ``4.slot``: the body's key before the scene's name
_GUIDE_KEY = re.compile(r"(?<![\w.])(?:frame|\d+)\.([^\W\d]\w*)")


def guide_names(line: str) -> str:
    """*line* with each guide named as the scene names it: ``∥ frame.ram`` → ``∥ ram``, ``∥ 4.slot`` → ``∥ slot``.

    >>> guide_names("v_E = v_E4 + v_EE4  (v_EE4 ∥ 4.slot);  a = 0.5 m")
    'v_E = v_E4 + v_EE4  (v_EE4 ∥ slot);  a = 0.5 m'
    """
    return _GUIDE_KEY.sub(r"\1", line)


def sheet_equations(solution, driver_label: str | None = None, plans=("velocity", "acceleration")) -> list[str]:
    """One line per construction step: ``"RRP(3,4):  v_B = v_A + v_BA;  v_B = …"``, velocity plan first.

    With *driver_label* (such as ``"I(1,2)"``) the driver's steps are headed
    with it instead of the English word ``driver`` (see :func:`label_driver`);
    *plans* says of which plans (both by default).
    """
    lines = []
    for plan in (solution.velocity_plan, solution.acceleration_plan):
        if plan is None or plan.kind not in plans:
            continue
        for step in plan.steps:
            if step.equations:
                lines.append(guide_names(f"{step.group}:  " + ";   ".join(step.equations)))
    return lines if driver_label is None else label_driver(lines, driver_label)


def label_driver(lines: list[str], label: str) -> list[str]:
    """Equation lines with a leading ``driver:`` replaced by ``label:`` (``"I(1,2):"``, the structural notation)."""
    return [f"{label}:" + line[len("driver:"):] if line.startswith("driver:") else line for line in lines]


_TABLE_HEADER = ["quantity", "graphical", "analytic", "rel. error"]


def translate_table(table: list[list[str]], lang: str) -> list[list[str]]:
    """The sheet table with its header row and the words link/slider in *lang*."""
    if lang == "en" or not table or list(table[0]) != _TABLE_HEADER:
        return table
    header = [term(k, lang) for k in ("quantity", "by_plan", "analytic", "rel_error")]  # "по плану", not an adverb
    words = {" link ": f" {term('link', lang)} ", " slider ": f" {term('slider', lang)} "}
    rows = [header]
    for row in table[1:]:
        cell = row[0]
        for a, b in words.items():
            cell = cell.replace(a, b)
        rows.append([cell] + list(row[1:]))
    return rows


def branch_lines(branches, lang: str = "en") -> list[str]:
    """The assembly branch of each group with two, one line each, from :class:`plans.structure.Branch` records.

    ``"RRR(3,4): C to the left of B→D (+1)"``; in the other languages in
    their words (:func:`plans.i18n.branch_text`), or the group and its sign
    alone for a form of words not known there.
    """
    out = []
    for b in branches or ():
        if not b.sign:
            continue
        sign = f"{b.sign:+d}".replace("-", "\u2212")
        words = branch_text(guide_names(b.words), lang)
        out.append(f"{b.group}: {words} ({sign})" if words else f"{b.group}: {sign}")
    return out
