"""Colours, line styles, sizes and fonts of every drawing, in one place.

Sizes on paper are in millimetres (``*_MM``) or typographic points
(``*_PT``); a drawing is laid out in millimetres, so that what is stated as
1 mm of plan is 1 mm on the printed page.

The colours are the Okabe–Ito palette (safe for colour-blind readers and
distinct in greyscale through the line styles as well).
"""

from __future__ import annotations

__all__ = [
    "FONT_FAMILY",
    "RC",
    "MM_PER_PT",
    "LABEL_PT",
    "SMALL_PT",
    "CAPTION_PT",
    "TITLE_PT",
    "HEADING_PT",
    "VECTOR_STYLE",
    "FORCE_STYLE",
    "FORCE_HOLLOW",
    "HOLLOW_RATIO",
    "CONSTRUCTION_STYLE",
    "ARROW_RATIO",
    "FIGURE_STYLE",
    "LEADER_STYLE",
    "INK",
    "PLATE_FILL",
    "MARGIN_MM",
]

#: DejaVu Sans ships with matplotlib (no system font lookup can change the
#: output) and covers Latin, Greek and Cyrillic.
FONT_FAMILY = "DejaVu Sans"

#: rcParams every drawing is rendered under (see :mod:`plans.drawing.svg`).
#: ``svg.fonttype = "none"`` keeps text as <text> elements: small files, text
#: that can be searched, selected and edited in a report, and that tests can
#: read back.  The font is named in the SVG; DejaVu Sans is on practically
#: every system and has the Cyrillic and Greek glyphs the labels need.
RC = {
    "svg.fonttype": "none",
    "svg.hashsalt": "plans-drawing",
    "svg.id": None,
    "font.family": "sans-serif",
    "font.sans-serif": [FONT_FAMILY],
    "mathtext.fontset": "dejavusans",
    "mathtext.default": "it",
    "axes.unicode_minus": True,
    "path.simplify": False,
    "lines.solid_capstyle": "butt",
    "lines.dash_capstyle": "butt",
}

MM_PER_PT = 25.4 / 72.0

LABEL_PT = 10.0  # point and image labels
SMALL_PT = 7.5  # link numbers, construction-line labels, table
CAPTION_PT = 8.5  # scale statement, legend
HEADING_PT = 10.0  # drawing titles, section headings on the sheet
TITLE_PT = 15.0  # sheet title

INK = "#000000"
PLATE_FILL = "#dfe8f3"
A4 = (210.0, 297.0)  # mm, portrait: the page a figure of diagrams is drawn for
MARGIN_MM = 4.0  # white space around the content of a drawing

#: kind -> (colour, line width [pt], dash pattern or None, arrowhead length [mm]).
#: In greyscale the kinds differ by weight and pattern alone: absolute heavy
#: solid, relative light solid, normal dashed, tangential dash-dot, Coriolis
#: dotted and dark (not a light grey).
VECTOR_STYLE = {
    "absolute": ("#000000", 1.7, None, 3.6),
    "relative": ("#0072B2", 1.0, None, 3.0),
    "normal": ("#009E73", 1.1, (5.0, 2.0), 3.0),
    "tangential": ("#D55E00", 1.1, (6.0, 1.8, 1.2, 1.8), 3.0),
    "coriolis": ("#6A1B7A", 1.3, (1.2, 1.2), 3.0),
}

#: Force kind -> (colour, line width [pt], dash pattern or None, arrowhead length [mm]), on force
#: plans and free bodies: a reaction read off a plan heavy solid black (as an absolute vector),
#: its components as the acceleration components (normal dashed, tangential dash-dot), loads
#: light solid, each kind its own colour, the balancing force heavy orange.
FORCE_STYLE = {
    "reaction": ("#000000", 1.7, None, 3.6),
    "normal": ("#009E73", 1.1, (5.0, 2.0), 3.0),
    "tangential": ("#D55E00", 1.1, (6.0, 1.8, 1.2, 1.8), 3.0),
    "weight": ("#56B4E9", 1.1, None, 3.0),
    "inertia": ("#0072B2", 1.1, None, 3.0),
    "external": ("#CC79A7", 1.3, None, 3.0),
    "balancing": ("#E69F00", 1.7, None, 3.6),
}

#: The force kinds drawn with an open (hollow) arrowhead: the weight G, light blue, beside the inertia force Φ,
#: blue, would be one grey in black-and-white print; its open head tells it from Φ's filled one in any print
#: (on the force plans, the free bodies, Joukowski's lever and the legends alike).
FORCE_HOLLOW = frozenset({"weight"})

#: Arrowheads are slender: length : width = ARROW_RATIO : 1 (drafting practice, about 3:1).
ARROW_RATIO = 3.0
#: An open arrowhead is wider (length : width = HOLLOW_RATIO : 1), so that its white inside reads.
HOLLOW_RATIO = 1.8

#: Construction lines: thin, grey, dashed.
CONSTRUCTION_STYLE = ("#7f7f7f", 0.5, (4.0, 2.5))

#: The image of a link on a plan (the figure similar to the link: triangle a b c, segment b e₅ m):
#: (edge colour, line width [pt], fill).
FIGURE_STYLE = ("#404040", 0.6, "#eeeeee")

#: Leader lines from a label moved away from its point.
LEADER_STYLE = ("#404040", 0.4)
