"""The yardstick: the offset slider-crank in closed form, hand-written in numpy.

It solves one mechanism only and is used by the benchmark only, to put a
number on the cost of plans' generality: the general solver's time over this
one's, on the same positions.  Crank OA = r about O = 0 at angle φ, with ω
and ε; coupler AB = l; the pin B slides on the line y = e, to the right of A.
With θ the coupler angle::

    sin θ = (e − r sin φ)/l
    ω₃ = −r ω cos φ / (l cos θ)                         (d/dt of y_B = e)
    ε₃ = (r ω² sin φ − r ε cos φ + l ω₃² sin θ) / (l cos θ)
    x_B = r cos φ + l cos θ,   v_B = −r ω sin φ − l ω₃ sin θ,
    a_B = −r ε sin φ − r ω² cos φ − l ε₃ sin θ − l ω₃² cos θ
"""

from __future__ import annotations

import numpy as np

__all__ = ["offset_slider_crank"]


def offset_slider_crank(phi, r, l, e, omega, epsilon=0.0):
    """r, v, a of A and B (complex arrays) and θ, ω₃, ε₃ of the coupler, over crank angles *phi*."""
    c, s = np.cos(phi), np.sin(phi)
    sin_t = (e - r * s) / l
    cos_t = np.sqrt(1.0 - sin_t * sin_t)
    l_cos = l * cos_t
    w3 = -r * omega * c / l_cos
    e3 = (r * omega * omega * s - r * epsilon * c + l * w3 * w3 * sin_t) / l_cos
    A = np.empty((3, len(phi)), dtype=complex)  # r, v, a of A: r e^{iφ}, iω r e^{iφ}, (iε − ω²) r e^{iφ}
    A[0].real, A[0].imag = r * c, r * s
    A[1] = (1j * omega) * A[0]
    A[2] = (1j * epsilon - omega * omega) * A[0]
    B = np.zeros((3, len(phi)), dtype=complex)
    B[0].real, B[0].imag = r * c + l_cos, e
    B[1].real = -r * omega * s - l * w3 * sin_t
    B[2].real = -r * epsilon * s - r * omega * omega * c - l * e3 * sin_t - l * w3 * w3 * cos_t
    return {"A": A, "B": B}, (np.arctan2(sin_t, cos_t), w3, e3)
