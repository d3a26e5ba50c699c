"""A long chain of RRR dyads as scene text, for drawing tests and timings.

A crank OA (20 mm) drives dyad 1 (coupler A–P1, rocker D1–P1); dyad k hangs
on the previous rocker's tip P(k−1): coupler P(k−1)–Pk (100 mm), rocker
Dk–Pk (80 mm) with Dk = (100·k, 0) mm.  Every rocker tip sits near
(100·k, 80) mm, so each dyad assembles near the same shape.
"""

from __future__ import annotations

import math

__all__ = ["chain_toml"]


def chain_toml(dyads: int, angle_deg: float = 45.0) -> str:
    """TOML text of a crank followed by *dyads* RRR groups in a row."""
    frame = {"O": (0.0, 0.0)}
    lines = [f'title = "Chain of {dyads} RRR dyads"', ""]
    links = []
    a = 20.0 * complex(math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg)))
    links.append(("2", {"O": 0j, "A": complex(20.0, 0)}))
    prev, prev_at = "A", a
    hints = {}
    for k in range(1, dyads + 1):
        d = f"D{k}"
        p = f"P{k}"
        frame[d] = (100.0 * k, 0.0)
        at = complex(100.0 * k, 80.0)
        links.append((str(2 * k + 1), {prev: 0j, p: complex(abs(at - prev_at), 0)}))
        links.append((str(2 * k + 2), {d: 0j, p: complex(80.0, 0)}))
        hints[p] = at
        prev, prev_at = p, at
    pts = ", ".join(f'{n} = ["{x:g} mm", "{y:g} mm"]' for n, (x, y) in frame.items())
    lines += ["[frame]", f"points = {{ {pts} }}", ""]
    for name, points in links:
        pts = ", ".join(f'{n} = ["{z.real:.6g} mm", "{z.imag:.6g} mm"]' for n, z in points.items())
        lines += [f'[link.{name}]', f"points = {{ {pts} }}", ""]
    lines += ["[driver]", 'crank = "2"', f'angle = "{angle_deg:g} deg"', 'omega = "10 rad/s"', ""]
    lines += ["[assembly]"] + [f"{n} = [{z.real / 1000:.6g}, {z.imag / 1000:.6g}]" for n, z in hints.items()]
    return "\n".join(lines) + "\n"
