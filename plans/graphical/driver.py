"""The driver: placed from its data, and its known velocity and acceleration drawn first.

Crank (link turning about the frame point O, angle φ, ω, ε)::

    O ●───────● A        v_A ⊥ OA, |v_A| = |ω|·OA, in the sense of ω
      \\ φ                a_A = aⁿ_AO + aᵗ_AO:  aⁿ_AO = ω²·OA from A towards O,
                                              aᵗ_AO ⊥ OA, |ε|·OA (drawn only if ε ≠ 0)

Linear driver (link translating along the frame line ``guide``): every point
moves with v = velocity·u and a = acceleration·u, u the guide's direction;
all its images coincide.
"""

from __future__ import annotations

import cmath

from ..scene import FRAME, Crank
from .state import Construction, Motion, body_label

__all__ = ["place_driver", "driver_velocity", "driver_acceleration"]


def _crank_points(ctx: Construction) -> list[str]:
    driver = ctx.scene.driver
    return [name for name in ctx.scene.bodies[driver.link].points if name != driver.pivot]


def _linear_points(ctx: Construction) -> list[str]:
    driver = ctx.scene.driver
    names = list(ctx.scene.bodies[driver.link].points)
    names.remove(driver.point)
    return [driver.point] + names


def place_driver(ctx: Construction) -> None:
    """Place the driver link: its pose (φ [rad], origin [m]) from the driver's data.

    Crank: the link's own x axis at φ, its pivot point on the frame point of
    the same name.  Linear driver: the link's own x axis along the frame line,
    its point ``point`` at ``line.origin + s·u``.
    """
    driver = ctx.scene.driver
    body = ctx.scene.bodies[driver.link]
    if isinstance(driver, Crank):
        pivot = ctx.scene.frame.points[driver.pivot]
        phi = driver.phi
        ctx.poses[driver.link] = (phi, pivot - cmath.exp(1j * phi) * body.points[driver.pivot])
        ctx.given[driver.link] = (driver.omega, driver.epsilon)
    else:
        line = ctx.scene.frame.lines[driver.guide]
        phi = line.angle
        at = line.origin + driver.s * line.direction
        ctx.poses[driver.link] = (phi, at - cmath.exp(1j * phi) * body.points[driver.point])
        ctx.given[driver.link] = (0.0, 0.0)


def driver_velocity(ctx: Construction) -> None:
    """Draw the driver's known velocity from the pole p.

    Crank: v_A = ω × OA, drawn ⊥ OA, |ω|·OA / k long, turned +90° from OA
    when ω > 0.  Linear driver: v_A = velocity·u.
    """
    plan = ctx.velocity
    driver = ctx.scene.driver
    link = driver.link
    if isinstance(driver, Crank):
        o = ctx.point(link, driver.pivot)
        names = _crank_points(ctx)
        # v_A ⊥ OA, |v_A| = |ω|·OA: OA turned by 90° in the sense of ω, scaled by |ω| / k
        turn = 1j * driver.omega / plan.k0
        ctx.v_motion[link] = Motion(o, 0j, turn)
        for name in names:
            plan.place(plan.label(name), turn * (ctx.point(link, name) - o), name)
        first = names[0] if names else driver.pivot
        known = [plan.absolute(first)] if names else []
        equations = (f"v_{first} = ω{body_label(link, ctx.scene.frame_number)} × {driver.pivot}{first}  (⊥ {driver.pivot}{first}, |ω{body_label(link, ctx.scene.frame_number)}|·{driver.pivot}{first})",)
        plan.step("driver", equations, known, [], [], plan.label(first))
    else:
        ctx.v_motion[link] = _translation(ctx, plan, driver.velocity, "v")


def driver_acceleration(ctx: Construction) -> None:
    """Draw the driver's known acceleration from the pole π.

    Crank: a_A = aⁿ_AO + aᵗ_AO; aⁿ_AO = −ω²·(A − O) (from A towards O, ω²·OA
    long), then aᵗ_AO = ε × OA (⊥ OA, |ε|·OA) from its tip, only when
    ε ≠ 0.  Linear driver: a_A = acceleration·u (nothing drawn if zero).
    """
    plan = ctx.acceleration
    driver = ctx.scene.driver
    link = driver.link
    if isinstance(driver, Crank):
        o = ctx.point(link, driver.pivot)
        omega, epsilon = driver.omega, driver.epsilon
        names = _crank_points(ctx)
        figure = (1j * epsilon - omega * omega) / plan.k0  # similarity ratio of the crank's image figure
        ctx.a_motion[link] = Motion(o, 0j, figure)
        known = []
        if names:
            first = names[0]
            oa = ctx.point(link, first) - o
            tip_n = -omega * omega * oa / plan.k0
            pivot = driver.pivot
            number = body_label(link, ctx.scene.frame_number)  # the driver's link number: ω₂²·OA, ε₂ = 0
            known.append(plan.component(0j, tip_n, "normal", f"a^n_{first}{pivot}"))
            tip = tip_n
            if epsilon != 0.0:
                tip = tip_n + 1j * epsilon * oa / plan.k0
                known.append(plan.component(tip_n, tip, "tangential", f"a^t_{first}{pivot}"))
                equations = [f"a_{first} = a^n_{first}{pivot} + a^t_{first}{pivot}  (a^n_{first}{pivot} ∥ {first}{pivot}, ω{number}²·{pivot}{first}; "
                             f"a^t_{first}{pivot} ⊥ {pivot}{first}, |ε{number}|·{pivot}{first})"]
            else:
                equations = [f"a_{first} = a^n_{first}{pivot}  (∥ {first}{pivot}, ω{number}²·{pivot}{first}; ε{number} = 0)"]
            plan.place(plan.label(first), tip, first)
        else:
            first = driver.pivot
            equations = []
        for name in names[1:]:
            plan.place(plan.label(name), figure * (ctx.point(link, name) - o), name)
        plan.step("driver", equations, known, [], [], plan.label(first))
    else:
        ctx.a_motion[link] = _translation(ctx, plan, driver.acceleration, "a")


def _translation(ctx: Construction, plan, value: float, symbol: str) -> Motion:
    """A translating driver's step: every point's image at value·u from the pole, u along its guide.

    *value* is the driver's velocity [m/s] or acceleration [m/s²] along the
    guide; *symbol* is ``"v"`` or ``"a"``.  Returns the link's motion on this plan.
    """
    driver = ctx.scene.driver
    line = ctx.scene.frame.lines[driver.guide]
    image = value * line.direction / plan.k0
    for name in _linear_points(ctx):
        plan.place(plan.label(name), image, name)
    # a zero (a constant-speed driver's acceleration) is said as it is: a_A = 0, no direction to give
    equation = f"{symbol}_{driver.point} = 0" if value == 0.0 else f"{symbol}_{driver.point} = {symbol} (∥ {FRAME}.{driver.guide})"
    plan.step(
        "driver",
        (equation,),
        [plan.absolute(driver.point)],
        [],
        [],
        plan.label(driver.point),
    )
    return Motion(ctx.point(driver.link, driver.point), image, 0j)
