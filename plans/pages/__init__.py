"""Pages: the typesetter's layer (Typst) — the handout as the course project's plate.

* :mod:`plans.pages.typesetting` — text, math and drawings into Typst source; compile to PDF/SVG/PNG;
* :mod:`plans.pages.equations` — the vector equations with the known parts underlined;
* :mod:`plans.pages.words` — the scene's title and names in the page's language, assembly in words, units;
* :mod:`plans.pages.handout` — the handout: data, plan of positions, velocity plans of every position at
  one k_v, acceleration plans of the chosen positions at one k_a, tables, loop equations, diagrams, centres.

Pages never draw vectors: they place drawings (:mod:`plans.drawing.svgblocks`, SVG of known size, at 100 %)
and set text.  Importing this package loads neither matplotlib nor Typst.
"""
