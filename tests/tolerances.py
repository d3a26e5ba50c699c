"""Tolerances of the test suite, in one place, with the reason for each.

Relative tolerances compare |computed − reference| with |reference| (or with
the named scale) so that they do not depend on the unit system.
"""

#: Double precision against an exact closed form worked by hand (a few
#: roundings of O(1e-16) each, amplified at most by a condition number ~10).
EXACT_REL = 1e-12

#: What the brief asks of the worked examples E1, E2 against domain.md.
WORKED_EXAMPLE_REL = 1e-9

#: Double precision against a 50-digit mpmath evaluation of the loop equations.
MPMATH_REL = 1e-12

#: Central finite differences of the position solution in time, with a
#: five-point stencil and a step h such that the driver moves by 1e-3 of its
#: natural scale (ω·h = 1e-3 rad, or v·h = 1e-3 × 0.1 m):
#:   truncation error  ~ (ωh)⁴/30 · (higher derivatives)  ≈ 1e-13 relative at
#:                       condition numbers below FD_MAX_CONDITION;
#:   rounding error    ~ ε_mach·|r| / (h·|v|)   ≈ 2e-13 for velocities,
#:                       ε_mach·|r| / (h²·|a|)  ≈ 2e-10 × stencil weights (~5)
#:                       for accelerations.
#: Measured worst cases: 4e-9 (velocities), 1.3e-7 (accelerations, a linear
#: driver whose accelerations are small beside its stroke).  The tolerances
#: below leave a margin of ~10 over those and are relative to the largest
#: magnitude of the quantity over the sweep (angular accelerations to
#: max|ε| + max|ω|², their natural scale).
FD_REL_VELOCITY = 1e-7
FD_REL_ACCELERATION = 2e-6
FD_MAX_CONDITION = 5.0

#: Invariants checked on random mechanisms (loop closure, v_BA ⟂ AB, …),
#: relative to the natural scale of each quantity (L, ωL, ω²L).
INVARIANT_REL = 1e-9
