"""The instant centres of a scene at its position from the analytic solution's velocities alone (nothing of Kennedy's
construction): P_jk is the point with the same velocity as a point of body j and of body k,
c_j + iω_j r = c_k + iω_k r (v(r) = c + iω r of each body); at infinity, perpendicular to c_j − c_k, where ω_j = ω_k."""

from __future__ import annotations

import numpy as np

from plans.analytic import solve
from plans.centres import instant_centres


def true_centres(scene) -> dict[str, tuple[complex | None, complex | None]]:
    """'P13' -> (point [m] or None, direction at infinity or None), from the analytic solution's velocities."""
    a = solve(scene)
    numbers = instant_centres(scene).numbers  # body -> its number in the labels
    field = {}  # body -> (ω, v at the scene's origin [m/s] of the body's velocity field)
    for body in scene.bodies:
        if body == "frame":
            field[body] = (0.0, 0j)
            continue
        omega = float(np.ravel(a.links[body].omega)[0])
        _, origin = a.poses[body]
        v_origin = complex(np.ravel(a.motion_of(body, 0j).v)[0])
        o = complex(np.ravel(origin)[0])
        field[body] = (omega, v_origin - 1j * omega * o)  # v(r) = c + iω r
    size = max(abs(complex(np.ravel(p.r)[0])) for p in a.points.values()) or 1.0
    out = {}
    bodies = list(scene.bodies)
    for n, i in enumerate(bodies):
        for j in bodies[n + 1:]:
            (wi, ci), (wj, cj) = field[i], field[j]
            label = "P" + "".join(sorted((numbers[i], numbers[j]), key=int))
            if abs(wi - wj) * size <= 1e-12 and abs(ci - cj) <= 1e-12:
                out[label] = (None, None)  # the two move alike (at rest): no centre to point at
            elif abs(wi - wj) * size <= 1e-9 * abs(ci - cj):  # the same ω: the relative motion a translation
                out[label] = (None, 1j * (ci - cj) / abs(ci - cj))
            else:
                out[label] = ((cj - ci) / (1j * (wi - wj)), None)
    return out
