"""The printed loop equations, read back as numbers, at every position of a cycle of every example.

Each mathtext line is turned back into arithmetic by a small reader written
here (it knows only the notation: ``e^{i\\,θ°}``, ``\\cdot``, ``i``, symbols
with subscripts), and then:

* the numbers after "⇒" (φ, ω, ε, s, ṡ, s̈) and the value of every point line
  are those of a separate ``plans.solve`` at that one position;
* the substituted loop closes: the two sides, with the results put in for
  the unknowns, agree to the printed digits;
* the substituted sum of a point line equals the value printed after it.
"""

from __future__ import annotations

import cmath
import math
import re

import numpy as np
import pytest

import plans
from plans.loops import loop_equations
from plans.positions import cycle_positions

_SYMBOL = {
    r"\varphi": "phi",
    r"\omega": "w",
    r"\varepsilon": "eps",
    r"\ddot{s}": "sdd",
    r"\dot{s}": "sd",
}


def _braced(text: str, start: int) -> int:
    """Index just past the brace group opening at text[start] == '{'."""
    depth = 0
    for k in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[k], 0)
        if depth == 0:
            return k + 1
    raise ValueError(text)


def _python(expr: str) -> str:
    """A mathtext expression of the loop equations as a Python expression over names and _e(degrees)."""
    out = ""
    k = 0
    while k < len(expr):
        if expr.startswith("e^{", k):
            end = _braced(expr, k + 2)
            inner = expr[k + 3 : end - 1].replace(r"\,", "").strip()
            assert inner.startswith("i"), expr
            out += f" _e({_python(inner[1:])}) "
            k = end
            continue
        out += expr[k]
        k += 1
    text = out.replace(r"^\circ", "")
    text = re.sub(r"\\cdot\s*10\^\{(-?\d+)\}", r"*10**(\1)", text)
    for mark, name in _SYMBOL.items():
        text = re.sub(re.escape(mark) + r"_\{([^}]*)\}", lambda m, n=name: f" {n}__{_ident(m.group(1))} ", text)
    text = re.sub(r"(?<![A-Za-z_])s_\{([^}]*)\}", lambda m: f" s__{_ident(m.group(1))} ", text)
    text = text.replace(r"\cdot", "*").replace(r"\,", " ").replace("^", "**")
    text = re.sub(r"(?<![A-Za-z_0-9])i(?=[0-9.(])", "i ", text)  # i0.25: the unit, then the number
    return _juxtapose(text)


def _ident(name: str) -> str:
    return re.sub(r"\W", "_", name.replace(r"\mathrm", "").replace("\\", ""))


_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][-+]?\d+)?)|([A-Za-z_][A-Za-z_0-9]*)|(\*\*|[-+*/()]))")


def _juxtapose(text: str) -> str:
    """Insert the multiplications that juxtaposition means; ``i`` is the imaginary unit."""
    tokens = []
    pos = 0
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        assert m and m.end() > pos, text[pos:]
        pos = m.end()
        number, name, op = m.groups()
        tokens.append(("n", number) if number else ("n", "1j") if name == "i" else ("v", name) if name else ("o", op))
    out = []
    for kind, value in tokens:
        if out:
            prev_kind, prev = out[-1]
            operand_before = prev_kind in ("n", "v") or prev == ")"
            operand_now = kind in ("n", "v") or value == "("
            if operand_before and operand_now and not (prev_kind == "v" and value == "("):
                out.append(("o", "*"))
        out.append((kind, value))
    return " ".join(v for _, v in out)


def _e(degrees) -> complex:
    return cmath.exp(1j * math.radians(degrees))


def _eval(expr: str, names: dict) -> complex:
    return complex(eval(_python(expr), {"__builtins__": {}, "_e": _e}, dict(names)))  # noqa: S307


def _strip(line: str) -> str:
    text = line.strip("$").replace(r"\quad", "").strip()
    return re.sub(r"\\ \\mathrm\{[^}]*\}", "", text)


def _terms(expr: str) -> list[str]:
    """The top-level terms of a sum (split at " + " and " - " outside parentheses and braces)."""
    terms, depth, start = [], 0, 0
    for k, c in enumerate(expr):
        depth += {"(": 1, "{": 1, ")": -1, "}": -1}.get(c, 0)
        if depth == 0 and expr[k : k + 3] in (" + ", " - "):
            terms.append(expr[start:k])
            start = k + 3
    return [t for t in terms + [expr[start:]] if t.strip()]


def _results(text: str) -> dict[str, float]:
    """``φ_4 = -49.95°, ω_4 = 0.2354, s_sleeve = -0.4208`` → names and numbers (angles in degrees)."""
    out = {}
    for item in text.split(r",\ "):
        symbol, value = item.split(" = ")
        name = _python(symbol).strip()
        out[name] = _eval(value, {}).real
    return out


def _expected(solution, name: str) -> float:
    kind, key = name.split("__")
    if kind == "phi":
        return math.degrees(float(solution.links[key].phi[0]))
    if kind in ("w", "eps"):
        return float(getattr(solution.links[key], {"w": "omega", "eps": "epsilon"}[kind])[0])
    # a pair named in words is written with its coincident points: rod 3 through F in sleeve 4, the yoke's Y on frame 1
    slider = solution.sliders[{"F3F4": "sleeve", "Y4Y1": "yoke"}.get(key, key)]
    return float({"s": slider.s, "sd": slider.v_rel, "sdd": slider.a_rel}[kind][0])


def _close(value: complex, expected: complex, scale: float, name: str) -> None:
    assert abs(value - expected) <= 2e-3 * max(scale, 1e-300), (name, value, expected)


def _cases():
    for name in plans.example_names():
        scene = plans.load(plans.example_path(name))
        if isinstance(scene.driver, plans.scene.Crank) or scene.driver.stroke is not None:
            yield name


@pytest.mark.parametrize("name", list(_cases()))
def test_every_printed_number_of_every_position_is_the_solvers_and_every_loop_closes(name):
    scene = plans.load(plans.example_path(name))
    positions = cycle_positions(scene, 12)
    sweep = plans.solve(scene, np.asarray(positions), allow_partial=True)
    checked_points = checked_loops = 0
    for k, value in enumerate(positions):
        if not sweep.valid[k]:
            continue
        alone = plans.solve(scene, [value])  # a separate solve at this one position
        blocks = loop_equations(sweep, k)
        # the driver's own line
        head = _strip(blocks[0].lines[0])
        if not isinstance(scene.driver, plans.scene.Crank):
            s = _eval(re.match(r"s = ([^,]+),", head).group(1), {}).real
            assert s == pytest.approx(value, rel=1e-3, abs=1e-12), (name, k, head)
        else:
            phi = float(re.match(r"\\varphi_\{\w+\} = (-?[\d.]+)", head).group(1))
            assert math.remainder(math.radians(phi) - value, 2 * math.pi) == pytest.approx(0, abs=1e-4), (name, k, head)
        for block in blocks:
            lines = [_strip(line) for line in block.lines]
            for n, text in enumerate(lines):
                point = re.match(r"([zva])_\{(\w+)\} = ", text)
                if point and len(text.split(" = ")) >= 4:  # z_X = symbols = numbers = value
                    letter, label = point.groups()
                    parts = text.split(" = ")
                    numeric, printed = parts[-2], parts[-1]
                    got = _eval(printed, {})
                    motion = alone.points[label]
                    expected = complex({"z": motion.r, "v": motion.v, "a": motion.a}[letter][0])
                    _close(got, expected, abs(expected) + 1e-9 * (1 + abs(expected)), f"{name} #{k} {text}")
                    summed = _eval(numeric, {})
                    _close(summed, got, abs(got) + 1e-6, f"{name} #{k} {text}")
                    checked_points += 1
                if r"\Rightarrow" in text:
                    equation, found = text.split(r"\ \Rightarrow\ ")
                    results = _results(found)
                    for symbol, number in results.items():
                        expected = _expected(alone, symbol)
                        if symbol.startswith("phi"):
                            assert math.remainder(math.radians(number - expected), 2 * math.pi) == pytest.approx(0, abs=2e-4), (name, k, symbol)
                        else:
                            _close(number, expected, abs(expected) + 1e-9, f"{name} #{k} {symbol}")
                    left, right = equation.split(" = ")
                    names = dict(results)
                    lhs, rhs = _eval(left, names), _eval(right, names)
                    magnitude = sum(abs(_eval(t, names)) for t in _terms(left) + _terms(right))
                    _close(lhs, rhs, magnitude, f"{name} #{k} {text}")
                    checked_loops += 1
    assert checked_points >= 3 and checked_loops >= 1


def test_the_linear_drivers_travel_and_guide_point_are_the_positions():
    """linear-arm at s = -100 mm: z_A = z_O + s u, with the position's s (the scene's own is 0)."""
    scene = plans.load(plans.example_path("linear-arm"))
    solution = plans.solve(scene, np.array([0.0, -0.1]))
    lines = [_strip(line) for line in loop_equations(solution, 1)[0].lines]
    assert lines[0].startswith("s = -0.1,")
    assert lines[1].startswith(r"z_{A} = z_{O} + s\,u = (-0.1)\,e^{i\,0.00^\circ} = -0.1")
    # the slide translates (no ω₂, no φ₂): v_F = v_A, and no zero term is printed
    v_f = next(line for line in lines if line.startswith("v_{F}"))
    assert v_f == "v_{F} = v_{A} = 0.5" and r"i0\cdot" not in v_f


def test_the_reader_reads_what_it_should():
    assert _eval(r"(0.5 + 0.25i) + 2\,e^{i\,90.00^\circ}", {}) == pytest.approx(0.5 + 2.25j)
    assert _eval(r"i\omega_{3}\cdot0.5\,e^{i\,0.00^\circ}", {"w__3": 2.0}) == pytest.approx(1j)
    assert _eval(r"2i\cdot(-1.5)\cdot2\,e^{i\,(\varphi_{4} + 60^\circ)}", {"phi__4": 30.0}) == pytest.approx(-6j * 1j)
    assert _eval(r"1.5\cdot10^{-3}", {}) == pytest.approx(1.5e-3)
