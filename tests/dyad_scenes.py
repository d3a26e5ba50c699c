"""Scenes of one crank and one dyad of each kind, written from an assembled configuration.

The random-mechanism tests (hypothesis in test_random_dyads.py, seeded generators in
test_centres_kennedy.py and test_pages_random_handouts.py) choose the geometry; these
functions write it as a scene.  Every position is given in the configuration's own
coordinates (complex numbers, metres, before *scale*), so the scene assembles at the
crank's angle on the branch its ``[assembly]`` hint names.  ``sine`` is what the tests
use to stay away from dead centres: |sin| of the angle between two construction lines.
"""

from __future__ import annotations

import cmath
import math


def xy(z: complex) -> str:
    """A TOML point [x, y] with every digit of the float."""
    return f"[{z.real!r}, {z.imag!r}]"


def sine(u: complex, w: complex) -> float:
    """|sin| of the angle between directions *u* and *w*."""
    return abs((u.conjugate() * w).imag) / (abs(u) * abs(w))


def _deg(angle: float) -> str:
    return f'"{math.degrees(angle)!r} deg"'


def crank(r: float, phi: float, omega: float, epsilon: float | None = None, lines: str = "", scale: float = 1.0) -> str:
    """Crank 2 (O at the origin, A at r∠phi) as the driver; *lines* are crank 2's own lines."""
    eps = "" if epsilon is None else f"epsilon = {epsilon!r}\n"
    return f"""
[link.2]
points = {{ O = [0, 0], A = [{r * scale!r}, 0] }}
{lines}
[driver]
crank = "2"
angle = {_deg(phi)}
omega = {omega!r}
{eps}"""


def rrr(a: complex, c: complex, d: complex, m: str = "M", scale: float = 1.0) -> str:
    """Coupler 3 (A, C and a coupler point *m*) and rocker 4 about frame D, assembled at C."""
    ac = abs(c - a) * scale
    return f"""
[frame]
points = {{ O = [0, 0], D = {xy(d * scale)} }}
[link.3]
points = {{ A = [0, 0], C = [{ac!r}, 0], {m} = [{0.3 * ac!r}, {0.1 * scale!r}] }}
[link.4]
points = {{ D = [0, 0], C = [{abs(c - d) * scale!r}, 0] }}
[assembly]
C = {xy(c * scale)}
"""


def rrp(b: complex, c: complex, slot_origin: complex, alpha: float, r: float, phi: float, omega: float,
        epsilon: float | None = None, scale: float = 1.0) -> str:
    """Link 3 about frame B, its pin C in a slot of crank 2 (through *slot_origin* in the crank's
    coordinates, at *alpha* to the crank), assembled at C."""
    slot = f"lines = {{ slot = {{ through = {xy(slot_origin * scale)}, angle = {_deg(alpha)} }} }}"
    return f"""
[frame]
points = {{ O = [0, 0], B = {xy(b * scale)} }}
[link.3]
points = {{ B = [0, 0], C = [{abs(c - b) * scale!r}, 0] }}
[[slider]]
pin = "C"
on = "2.slot"
[assembly]
C = {xy(c * scale)}
""" + crank(r, phi, omega, epsilon, slot, scale)


def rpr(a: complex, e: complex, u: complex, offset: float, m: str = "M", scale: float = 1.0) -> str:
    """Rod 3 pinned at A, its line *offset* from A, through a sleeve pivoting at frame E;
    *u* the rod's direction (assembled by its point *m* at A + 1.2·u)."""
    return f"""
[frame]
points = {{ O = [0, 0], E = {xy(e * scale)} }}
[link.3]
points = {{ A = [0, 0], {m} = [{1.2 * scale!r}, 0] }}
lines = {{ rod = {{ through = [0, {offset * scale!r}], angle = 0 }} }}
[[slider]]
pin = "E"
on = "3.rod"
[assembly]
{m} = {xy((a + 1.2 * u) * scale)}
"""


def prp(g: complex, gamma: float, alpha: float, r: float, phi: float, omega: float,
        epsilon: float | None = None, scale: float = 1.0) -> str:
    """Block 3 on crank 2's slot (through O at *alpha* to the crank) and block 4 on a frame guide
    through *g* at *gamma*, pinned together at C."""
    slot = f'lines = {{ slot = {{ through = "O", angle = {_deg(alpha)} }} }}'
    return f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ guide = {{ through = {xy(g * scale)}, angle = {_deg(gamma)} }} }}
[[slider]]
pin = "C"
on = "2.slot"
name = "3"
[[slider]]
pin = "C"
on = "frame.guide"
name = "4"
""" + crank(r, phi, omega, epsilon, slot, scale)


def rpp(y: complex, gamma: float, alpha: float, beta: float, scale: float = 1.0) -> str:
    """Block 3 on crank pin A slides in yoke 4's slot (at *alpha* in the yoke); the yoke's rail (at
    *beta* in the yoke) slides on a frame line through *y* at *gamma*."""
    return f"""
[frame]
points = {{ O = [0, 0] }}
lines = {{ rail = {{ through = {xy(y * scale)}, angle = {_deg(gamma)} }} }}
[link.4]
points = {{ Y = [0, 0], R = [{0.3 * scale!r}, {0.1 * scale!r}] }}
lines = {{ slot = {{ through = "Y", angle = {_deg(alpha)} }}, rail = {{ through = "Y", angle = {_deg(beta)} }} }}
[[slider]]
pin = "A"
on = "4.slot"
name = "3"
[[prismatic]]
line = "4.rail"
on = "frame.rail"
"""


def unit(angle: float) -> complex:
    return cmath.exp(1j * angle)
