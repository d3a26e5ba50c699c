"""The lecture page: one self-contained HTML file that plays the mechanism and its plans over the cycle.

Everything is inside the file: the frames (one SVG per position, text in the
reader's language, fonts named, none loaded), the cycle diagrams with their
cursor, the legend, the values and a small script.  No server, no network,
no external script, style sheet or font: the page opens from a USB stick.

What the page does (:data:`SCRIPT`):

* a slider, play/pause, a step either way, and a speed;
* keys: ← and → (and ↑ ↓, Page Up/Down) step, space plays or pauses, Home and End
  go to the first and the last position;
* ``page.html#position=K`` opens position K, and the address follows the
  position shown (so a lecturer can link to a position);
* beside the drawings, the position's values (:mod:`plans.lecture.values`).

The element ids the script (and the tests) use: ``frame`` (the SVG of the
position shown), ``slider``, ``play``, ``previous``, ``next``, ``speed``,
``position`` (the position's words, ``data-position`` its number), ``values``
(the table), ``diagrams`` (with the cursors ``cursor-<quantity>``).
"""

from __future__ import annotations

import html
import json

from .._text import decimal_comma, user_text
from ..i18n import term

__all__ = ["lecture_html", "SCRIPT", "STYLE", "SECONDS_PER_CYCLE"]

#: One cycle takes this long when played at speed 1.
SECONDS_PER_CYCLE = 6.0
#: The speeds offered (× the speed at which one cycle takes :data:`SECONDS_PER_CYCLE`).
SPEEDS = (0.25, 0.5, 1.0, 2.0)

STYLE = """
*{box-sizing:border-box}
body{margin:0;padding:0.5rem 0.9rem;font-family:"DejaVu Sans","Segoe UI",Arial,sans-serif;color:#111;background:#f6f6f4}
h1{font-size:1.1rem;margin:0 0 0.1rem}
#subtitle{margin:0;color:#444;font-size:0.9rem;display:flex;flex-wrap:wrap;column-gap:0.9rem;row-gap:0.1rem}
#subtitle span{overflow-wrap:anywhere}
#top{margin-top:0.4rem}
#stage{background:#fff;border:1px solid #ccc;padding:0.3rem}
#frame svg{display:block;width:100%;height:auto;max-height:66vh}
#bar{display:flex;flex-wrap:wrap;gap:0.4rem 1.2rem;align-items:flex-start;justify-content:space-between}
#bar-left{flex:1 1 34rem;min-width:0}
#controls{display:flex;flex-wrap:wrap;align-items:center;gap:0.5rem;margin:0.4rem 0 0.2rem}
#controls button{font:inherit;font-size:1rem;min-width:2.6rem;padding:0.25rem 0.6rem;cursor:pointer}
#play{min-width:7.5rem}
#slider{flex:1 1 12rem;min-width:8rem}
#position{font-weight:bold;min-width:14rem}
#keys{color:#555;font-size:0.78rem;margin:0}
#side{flex:0 1 auto;display:flex;flex-direction:column;gap:0.5rem;min-width:0;max-width:100%}
#values-box{overflow-x:auto}
#legend-box{padding:0.2rem 0.5rem}
#lower{display:flex;flex-wrap:wrap;gap:0.8rem;align-items:flex-start;margin-top:0.5rem}
section{background:#fff;border:1px solid #ccc;padding:0.4rem 0.6rem}
h2{font-size:0.95rem;margin:0 0 0.3rem}

#values{border-collapse:collapse;font-size:0.85rem}
#values th,#values td{padding:0.08rem 0.5rem;border-bottom:1px solid #e4e4e4;text-align:right;white-space:nowrap}
#values th:first-child,#values td:first-child{text-align:left}
#values td.unit{text-align:left;color:#555}
#diagrams-box{flex:1 1 40rem;min-width:0}
#values-box .note{max-width:25rem}
#diagrams{display:grid;grid-template-columns:repeat(auto-fill,minmax(26rem,1fr));gap:0.2rem 0.6rem}
#diagrams svg{display:block;width:100%;height:auto}
#legend svg{display:block;max-width:100%;height:auto}
.note{color:#555;font-size:0.78rem;margin:0.2rem 0 0}
"""

SCRIPT = r"""
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("plans-data").textContent);
  var n = data.frames.length;
  var frame = document.getElementById("frame");
  var slider = document.getElementById("slider");
  var label = document.getElementById("position");
  var play = document.getElementById("play");
  var speed = document.getElementById("speed");
  var cells = [];
  var rows = document.querySelectorAll("#values tbody tr");
  for (var i = 0; i < rows.length; i++) {
    cells.push([rows[i].querySelector("td.graphical"), rows[i].querySelector("td.analytic")]);
  }
  var current = -1;
  var timer = null;

  function wrap(k) { return ((k % n) + n) % n; }

  function setHash(k) {
    var hash = "#position=" + k;
    if (location.hash === hash) { return; }
    // a page shown where its address cannot change (a notebook's inline frame, about:srcdoc) keeps its address
    try { history.replaceState(null, "", hash); } catch (e) { return; }
  }

  function hashPosition() {
    var match = /(?:^#|&)position=(\d+)/.exec(location.hash);
    return match ? Math.min(n - 1, parseInt(match[1], 10)) : null;
  }

  function show(k, keepHash) {
    k = wrap(k);
    if (k !== current) {
      frame.innerHTML = data.frames[k];
      current = k;
    }
    slider.value = String(k);
    label.textContent = data.labels[k];
    label.setAttribute("data-position", String(k));
    var values = data.values[k];
    for (var r = 0; r < cells.length; r++) {
      cells[r][0].textContent = values[r][0];
      cells[r][1].textContent = values[r][1];
    }
    for (var id in data.cursors) {
      var cursor = document.getElementById(id);
      if (!cursor) { continue; }
      var dx = data.cursors[id][k];
      if (dx === null) {
        cursor.setAttribute("visibility", "hidden");
      } else {
        cursor.setAttribute("visibility", "visible");
        cursor.setAttribute("transform", "translate(" + dx + " 0)");
      }
    }
    if (!keepHash) { setHash(k); }
  }

  function period() { return 1000 * data.secondsPerCycle / n / parseFloat(speed.value); }

  function stop() {
    if (timer !== null) { clearInterval(timer); timer = null; }
    play.textContent = data.words.play;
    play.setAttribute("aria-pressed", "false");
  }

  function start() {
    stop();
    timer = setInterval(function () { show(current + 1); }, period());
    play.textContent = data.words.pause;
    play.setAttribute("aria-pressed", "true");
  }

  function toggle() { if (timer === null) { start(); } else { stop(); } }

  function step(by) { stop(); show(current + by); }

  play.addEventListener("click", toggle);
  document.getElementById("previous").addEventListener("click", function () { step(-1); });
  document.getElementById("next").addEventListener("click", function () { step(1); });
  slider.addEventListener("input", function () { stop(); show(parseInt(slider.value, 10)); });
  speed.addEventListener("change", function () { if (timer !== null) { start(); } });
  window.addEventListener("hashchange", function () {
    var k = hashPosition();
    if (k !== null && k !== current) { stop(); show(k, true); }
  });
  document.addEventListener("keydown", function (event) {
    if (event.altKey || event.ctrlKey || event.metaKey) { return; }
    var tag = event.target && event.target.tagName;
    if (tag === "SELECT") { return; }
    if (tag === "BUTTON" && (event.key === " " || event.key === "Enter")) { return; }
    switch (event.key) {
      case "ArrowRight": case "ArrowDown": case "PageDown": step(1); break;
      case "ArrowLeft": case "ArrowUp": case "PageUp": step(-1); break;
      case "Home": stop(); show(0); break;
      case "End": stop(); show(n - 1); break;
      case " ": case "Spacebar": toggle(); break;
      default: return;
    }
    event.preventDefault();
  });

  var first = hashPosition();
  show(first === null ? 0 : first, first === null);
})();
"""


def _json_for_script(value) -> str:
    """JSON that can stand inside a <script> element: no ``</`` (which would end it) and no ``<!--``."""
    return json.dumps(value, ensure_ascii=False, separators=(",", ":")).replace("</", "<\\/").replace("<!--", "<\\u0021--")


def lecture_html(
    *,
    title: str,
    subtitle: list[str],
    lang: str,
    frames: list[str],
    labels: list[str],
    rows: list,
    values: list,
    heads: list[str],
    diagrams: list[str],
    cursors: dict,
    legend: str | None,
    scales: list[tuple[str, str, str, str]] = (),
    notes: list[str] = (),
) -> str:
    """The page as text.

    *subtitle* is the header's parts (plain text, each kept whole when the line wraps), *scales* the
    scale factors as ``(letter, subscript, value, unit)`` (typeset k<sub>l</sub> = 0.005 m/mm), *notes* the
    table's footnotes (plain text).  *frames* are SVG texts (one per position), *labels* the words of each
    position, *rows* the table's rows (:func:`plans.lecture.values.value_rows`) and
    *values* their cells per position, *heads* the table's column heads,
    *diagrams* the SVGs of the cycle diagrams (one each) whose *cursors* move (gid → a
    shift per position, None where hidden), *legend* the SVG of the plans' legend.
    """
    words = {k: term(f"lecture_{k}", lang) for k in ("play", "pause")}
    data = {"frames": frames, "labels": labels, "values": values, "cursors": cursors, "words": words, "secondsPerCycle": SECONDS_PER_CYCLE}
    count = len(frames)
    esc = html.escape
    body_rows = "\n".join(
        f'<tr><td>{row.symbol}</td><td class="graphical"></td><td class="analytic"></td><td class="unit">{esc(row.unit)}</td></tr>' for row in rows
    )
    speeds = "".join(
        f'<option value="{s:g}"{" selected" if s == 1.0 else ""}>×{esc(_speed_text(s, lang))}</option>' for s in SPEEDS
    )
    diagrams_box = (
        f'<section id="diagrams-box"><h2>{esc(term("cycle_diagrams", lang))}</h2><div id="diagrams">{"".join(f"<div>{d}</div>" for d in diagrams)}</div>'
        f'<p class="note">{esc(term("lecture_cursor", lang))}</p></section>'
        if diagrams
        else ""
    )
    legend_box = f'<section id="legend-box"><h2>{esc(term("lecture_legend", lang))}</h2><div id="legend">{legend}</div></section>' if legend else ""
    head_parts = [esc(term("lecture_title", lang))] + [esc(part) for part in subtitle[:1]]
    head_parts += [f"{esc(letter)}<sub>{esc(sub)}</sub> = {esc(value)} {esc(unit)}" for letter, sub, value, unit in scales]
    head_parts += [esc(part) for part in subtitle[1:]]
    header_line = "".join(f"<span>{part}</span>" for part in head_parts)
    notes_html = "".join(f'<p class="note">{esc(note)}</p>' for note in notes)
    page_title = f"{user_text(title)} — {term('lecture_title', lang)}"
    return f"""<!DOCTYPE html>
<html lang="{esc(lang)}">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="plans animate">
<link rel="icon" href="data:,">
<title>{esc(page_title)}</title>
<style>{STYLE}</style>
</head>
<body>
<header>
<h1>{esc(user_text(title))}</h1>
<p id="subtitle">{header_line}</p>
</header>
<main>
<div id="top">
<div id="stage"><div id="frame" aria-live="off"></div></div>
<div id="bar">
<div id="bar-left">
<div id="controls">
<button id="previous" type="button" title="{esc(term("lecture_previous", lang))}" aria-label="{esc(term("lecture_previous", lang))}">◀</button>
<button id="play" type="button" aria-pressed="false">{esc(words["play"])}</button>
<button id="next" type="button" title="{esc(term("lecture_next", lang))}" aria-label="{esc(term("lecture_next", lang))}">▶</button>
<input id="slider" type="range" min="0" max="{count - 1}" step="1" value="0" aria-label="{esc(term("position", lang))}">
<output id="position" for="slider" data-position="0"></output>
<label>{esc(term("lecture_speed", lang))} <select id="speed">{speeds}</select></label>
</div>
<p id="keys">{esc(term("lecture_keys", lang))}</p>
</div>
</div>
</div>
<div id="lower">
{diagrams_box}
<div id="side">
{legend_box}
<section id="values-box"><h2>{esc(term("lecture_values", lang))}</h2>
<table id="values"><thead><tr>{"".join(f"<th>{esc(h)}</th>" for h in heads)}</tr></thead>
<tbody>
{body_rows}
</tbody></table>{notes_html}</section>
</div>
</div>
</main>
<script type="application/json" id="plans-data">{_json_for_script(data)}</script>
<script>{SCRIPT}</script>
</body>
</html>
"""


def _speed_text(speed: float, lang: str) -> str:
    return decimal_comma(f"{speed:g}", lang)
