"""The ``plans`` command: parse arguments, call the library, write files.

Every deliberate error is a :class:`plans.errors.PlansError`; it is printed as
one line on stderr and the exit status is 2.  Nothing is written unless the
whole job succeeded (files go through a temporary file and a rename).
Drawing modules (matplotlib) are imported by ``plans draw`` only, so
``plans solve`` starts fast.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from .errors import AssemblyError, OutputError, PlansError, SceneError, SingularPositionError
from .limits import WARN_CONDITION
from .scene import Crank, Scene, example_names, example_path, load
from .units import UnitError, parse_quantity

__all__ = ["main"]

EXIT_ERROR = 2


def _scene_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?", help="scene file (TOML)")
    parser.add_argument("--example", metavar="NAME", help="use a bundled example scene instead of a file (see: plans examples)")


def _position_argument(parser: argparse.ArgumentParser, *, several: bool = False) -> None:
    more = " or a list (\"0,30,55,90 deg\"): a sheet per position" if several else ""
    parser.add_argument(
        "--at",
        metavar="POSITION",
        help="driver position instead of the scene's: a crank angle (\"30 deg\", bare numbers are degrees) "
        f"or a linear driver's position (\"50 mm\", bare numbers are m){more}",
    )
    if several:
        parser.add_argument(
            "--positions",
            type=_count,
            metavar="N",
            help="N positions equally spaced over the driver's cycle (position 0 is the scene's own), a sheet each",
        )


def _count(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of positions, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected at least 1 position, got {text!r}")
    return value


def _language_argument(parser: argparse.ArgumentParser) -> None:
    from .i18n import LANGUAGES

    parser.add_argument(
        "--lang",
        choices=list(LANGUAGES),
        default="en",
        help="language of headings and legends: " + ", ".join(f"{k} ({v})" for k, v in LANGUAGES.items()),
    )


def _not_negative(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number of mm, or 0 for exact readings, got {text!r}") from None
    if not (math.isfinite(value) and value >= 0):
        raise argparse.ArgumentTypeError(f"expected a positive number of mm, or 0 for exact readings, got {text!r}")
    return value


def _positive(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}") from None
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}")
    return value


def _condition(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a condition number of at least 1 (or inf), got {text!r}") from None
    if not value >= 1:
        raise argparse.ArgumentTypeError(f"expected a condition number of at least 1 (or inf), got {text!r}")
    return value


def _warn_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--warn-condition",
        type=_condition,
        default=WARN_CONDITION,
        metavar="C",
        help=f"warn when a group's condition number exceeds C, i.e. near a dead centre (default {WARN_CONDITION:g}; "
        "the expected relative error there is about 9e-16 × C²; inf: never)",
    )


def _scale_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_argument_group("plan scales (default: the scene's [scales], else automatic round values)")
    group.add_argument("--k-l", type=_positive, metavar="K", help="mechanism scale, m per mm of drawing")
    group.add_argument("--k-v", type=_positive, metavar="K", help="velocity plan scale, (m/s) per mm")
    group.add_argument("--k-a", type=_positive, metavar="K", help="acceleration plan scale, (m/s²) per mm")
    group.add_argument("--precision", type=_not_negative, metavar="MM",
                       help="drafting precision: round every measured length to this many mm "
                            "(default: exact for solve, 0.1 for draw and handout; 0: exact)")


#: Where the scene format is described, at the end of every --help.
SCENE_FORMAT = (
    "Scene files (TOML) are described in the README, section \"Scene files\"; "
    "plans examples NAME prints a bundled scene to start from."
)

#: The end of each subcommand's --help: an example to copy.
EXAMPLES = {
    "solve": "plans solve --example slider-crank\n  plans examples four-bar > my.toml\n  plans solve my.toml --at \"10,25 deg\" --json",
    "sweep": "plans sweep --example four-bar --steps 360 -o four-bar.csv --plot diagrams",
    "draw": "plans draw --example six-bar -o drawings\n  plans draw --example six-bar --positions 12 -o sheets --format png",
    "handout": "plans handout --example four-bar --positions 4 -o four-bar.pdf --lang sr",
    "animate": "plans animate --example six-bar -o six-bar.html\n  plans animate --example four-bar --positions 72 -o four-bar.gif --lang sr",
    "centres": "plans centres --example six-bar -o drawings\n  plans centres my.toml --at \"30 deg\" --no-drawing\n  plans centres --example four-bar --lang sr -o drawings",
    "bench": "plans bench --quick -o /tmp/bench",
    "forces": "plans forces --example slider-crank-loads\n  plans forces --example four-bar-loads --at \"0,90 deg\" --json\n  plans examples --loads",
    "examples": "plans examples\n  plans examples six-bar > my.toml\n  plans examples --loads",
}

#: What each bundled example shows, in plain words, for ``plans examples``.
DESCRIPTIONS = {
    "ladder": "a rod sliding down a wall, its foot pushed along the floor at constant speed",
    "slider-crank": "an engine's crank, connecting rod and piston, the piston's line offset from the crank's centre",
    "four-bar": "a crank driving a rocker through a coupler, with a point on the coupler; the crank speeds up",
    "quick-return": "a shaper: the crank's pin slides in a swinging slotted lever that drives the ram (Coriolis)",
    "six-bar": "a four-bar whose coupler drives a rod sliding through a swinging sleeve",
    "linear-arm": "a slide carrying an arm; a rod in a sleeve welded to a rocker; a block on the moving rod",
    "wedge": "a wedge pushed along the floor lifts a follower sliding in a vertical guide",
    "scotch-yoke": "a crank whose pin slides in the slot of a yoke that moves straight back and forth",
    "rocker-limit": "a four-bar whose input cannot turn fully: it swings between its two limit positions",
}


def _law_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_argument_group("the driver's motion over the cycle (see plans.motion)")
    group.add_argument("--law", choices=["constant", "uniform", "harmonic"],
                       help="the driver's law over the cycle (default: the scene's [driver] law, else constant speed; "
                       "a harmonic swing for a crank that cannot turn fully); uniform: ω² = ω₀² + 2ε(φ − φ₀) from the scene's instant")
    group.add_argument("--start", choices=["output", "scene"], default="output",
                       help="position 0: the extreme position of the output link that starts its working stroke (default), "
                       "or the scene's own position")


def _add_command(commands, name: str, help: str, description: str | None = None, **kwargs) -> argparse.ArgumentParser:
    """A subcommand whose --help ends with an example and where the scene format is described."""
    import textwrap

    text = description or help[:1].upper() + help[1:] + "."
    text = "\n\n".join(textwrap.fill(paragraph, 79) for paragraph in text.split("\n\n"))
    return commands.add_parser(name, help=help, description=text,
                               epilog=_epilog(name), formatter_class=argparse.RawDescriptionHelpFormatter, **kwargs)


def _epilog(name: str) -> str:
    return f"example:\n  {EXAMPLES[name]}\n\n{SCENE_FORMAT}"


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(
        prog="plans",
        description="Velocity and acceleration plans of planar linkages: analytic (complex numbers) and graphical.",
        epilog="example:\n  plans solve --example six-bar\n\n" + SCENE_FORMAT + " plans COMMAND --help for each command.",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"plans {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    solve = _add_command(commands, "solve", "solve one position: analytic and graphical values with their differences")
    _scene_argument(solve)
    _position_argument(solve)
    solve.add_argument("--json", action="store_true", help="print the documented JSON schema instead of a table")
    solve.add_argument("--analytic-only", action="store_true", help="skip the graphical construction (and the instant centres)")
    solve.add_argument("--no-centres", action="store_true", help="skip the instant-centre method (ω and v from Kennedy's theorem)")
    _warn_argument(solve)
    _scale_arguments(solve)

    sweep = _add_command(commands, "sweep", "analytic solution over a whole driver cycle, as CSV")
    _scene_argument(sweep)
    sweep.add_argument("--steps", type=int, default=360, metavar="N", help="number of driver positions (default 360)")
    sweep.add_argument("-o", "--output", metavar="FILE", help="CSV file to write (default: standard output)")
    sweep.add_argument(
        "--plot",
        metavar="DIR",
        help="also draw the cycle diagrams (links.svg, points.svg, sliders.svg) and the output link's kinematic diagrams "
        "by graphical differentiation (kinematic.svg, at --positions positions, 12 by default) into DIR; "
        "a scene with masses or loads also the driving moment M_b(φ) (F_b(s)) and the polar diagram of the crank "
        "bearing's reaction on one page (forces.svg) "
        "(without -o the CSV still goes to standard output, the diagrams' names to standard error)",
    )
    sweep.add_argument("--components", action="store_true", help="with --plot: x and y components of v and a too")
    sweep.add_argument("--format", choices=["svg", "pdf", "png"], default="svg", help="with --plot: format of the diagrams (default svg)")
    sweep.add_argument("--positions", type=_count, metavar="N", help="with --plot: mark N equally spaced positions (those of plans draw --positions N); "
                       "the kinematic diagrams' positions (default 12)")
    _law_arguments(sweep)
    _language_argument(sweep)
    _warn_argument(sweep)

    draw = _add_command(
        commands,
        "draw",
        "draw mechanism.svg, velocity.svg, acceleration.svg and sheet.svg (or a sheet per position)",
    )
    _scene_argument(draw)
    _position_argument(draw, several=True)
    draw.add_argument(
        "-o", "--output", metavar="DIR", required=True,
        help="directory for the drawings; or, for one position, a file (page.svg, page.pdf, page.png) for the sheet alone",
    )
    draw.add_argument("--format", choices=["svg", "pdf", "png"], default="svg", help="format of the files written into DIR (default svg)")
    draw.add_argument("-q", "--quiet", action="store_true", help="with --positions: no progress on stderr (shown only when stderr is a terminal)")
    _law_arguments(draw)
    _language_argument(draw)
    _warn_argument(draw)
    _scale_arguments(draw)

    handout = _add_command(commands, "handout", "a printable handout: A4 pages of PDF (or SVG pages)")
    _scene_argument(handout)
    _position_argument(handout, several=True)
    handout.add_argument("-o", "--output", metavar="FILE", required=True, help="FILE.pdf, or FILE.svg / FILE.png for a file per page")
    handout.add_argument("--components", action="store_true", help="cycle diagrams with x and y components of v and a")
    handout.add_argument("--centres", action="store_true", help="a page more per position: the instant centres (Kennedy's theorem) and the velocities from them against analytic")
    handout.add_argument("--accelerations", type=_accelerations, metavar="WHICH",
                         help="the positions whose acceleration plans are drawn: 'all' or numbers such as 0,6 "
                              "(default: two, one of the working and one of the idle stroke, each nearest its middle where the plan does not collapse onto a line)")
    handout.add_argument("--scales", choices=("plate", "per-position"), default="plate",
                         help="plate (default): one k_l, k_v, k_a over the whole handout; per-position: k_v, k_a chosen for each position")
    handout.add_argument("--forces", action="store_true", help="the kinetostatic pages per position: free bodies, force plans, Joukowski's lever (the scene needs masses or loads)")
    handout.add_argument("-q", "--quiet", action="store_true", help="no progress on stderr (shown only when stderr is a terminal)")
    _law_arguments(handout)
    _language_argument(handout)
    _scale_arguments(handout)

    forces = _add_command(
        commands,
        "forces",
        "kinetostatics of one position: joint reactions and the balancing moment, analytic beside Joukowski's lever "
        "(and the force plans), with the power balance",
    )
    _scene_argument(forces)
    _position_argument(forces)
    forces.add_argument("--json", action="store_true", help="print the JSON document instead of a table")
    forces.add_argument("--analytic-only", action="store_true", help="skip the graphical methods (construction, lever, force plans)")
    forces.add_argument(
        "-o", "--output", metavar="DIR",
        help="also draw the free bodies, each group's force plan, the driver's and Joukowski's lever into DIR "
             "(DIR/position-K/ for each of an --at list), all or none; lengths read to 0.1 mm unless --precision says",
    )
    forces.add_argument("--format", choices=["svg", "pdf", "png"], default="svg", help="format of the drawings written into DIR (default svg)")
    _language_argument(forces)
    _warn_argument(forces)
    _scale_arguments(forces)
    animate = _add_command(
        commands,
        "animate",
        "plans that move: a lecture page (one self-contained HTML file) of the mechanism and its plans over the cycle, or a GIF or MP4 for slides",
    )
    _scene_argument(animate)
    animate.add_argument("--positions", type=_count, default=36, metavar="N", help="N positions of the driver's cycle under its law (default 36; see --law and --start)")
    animate.add_argument("-o", "--output", metavar="FILE", required=True, help="page.html (opens in a browser, no server or network), anim.gif or anim.mp4")
    _law_arguments(animate)
    _language_argument(animate)
    _scale_arguments(animate)

    centres = _add_command(
        commands, "centres", "every instant centre by Kennedy's theorem, ω and v from them; draws centres.svg",
        description="Every instant centre P_ij of the mechanism's bodies at one position (the frame is body 1, or 0 when a link is named 1): "
        "the pairs' own centres, the rest by Kennedy's theorem (the three centres of any three bodies lie on one "
        "line), each printed where it lies, or as its direction when it is at infinity, with the lines that gave it. "
        "Then ω of every link by the angular-velocity ratio theorem and v of every point as ω × (M − P_1j), "
        "beside the analytic values.\n\n"
        "Draws centres.svg into DIR: the mechanism with every centre marked, the Kennedy lines, and the circle "
        "diagram (--no-drawing: the table only).",
    )
    _scene_argument(centres)
    _position_argument(centres)
    centres.add_argument("-o", "--output", metavar="DIR", default=".", help="directory for centres.svg (default: the current directory)")
    centres.add_argument("--k-l", type=_positive, metavar="K", help="mechanism scale, m per mm of drawing (default: the scene's, else automatic)")
    centres.add_argument("--no-drawing", action="store_true", help="print the table only, write no file")
    _language_argument(centres)

    from . import bench

    bench_parser = bench.add_parser(commands)
    bench_parser.epilog = f"example:\n  {EXAMPLES['bench']}"
    bench_parser.formatter_class = argparse.RawDescriptionHelpFormatter
    examples = _add_command(commands, "examples", "list the bundled example scenes, or print one of them")
    examples.add_argument("name", nargs="?", metavar="NAME", help="print this example's scene file (TOML), to start a scene of your own from")
    examples.add_argument("--loads", action="store_true", help="list the scenes with masses and loads (for plans forces) instead")
    return parser


def _load(args) -> Scene:
    if args.example and args.scene:
        raise SceneError("give either a scene file or --example NAME, not both")
    if args.example:
        scene = load(example_path(args.example))
    elif args.scene:
        scene = load(args.scene)
    else:
        raise SceneError("no scene: give a scene file or --example NAME (plans examples lists them)")
    args.loaded_scene = scene  # for errors found later (main names the file)
    for doubt in scene.doubts:  # a bare driver number that looks meant in another unit
        _warn(f"{scene.source}: {doubt}")
    if any(not isinstance(hint, int) for hint in scene.assembly.values()):  # a location hint far from both assemblies
        from .analytic.solver import far_hints

        try:
            hints = far_hints(scene)
        except PlansError:  # a scene that cannot be solved: the command says why
            hints = ()
        for message in hints:
            _warn(f"{scene.source}: {message}")
    if getattr(args, "at", None) is not None and not _several(args):
        scene = _at(scene, args.at)
    return scene


def _several(args) -> bool:
    """True when the command asks for a run over several positions."""
    return getattr(args, "positions", None) is not None or "," in (getattr(args, "at", None) or "")


def _position_spec(args, scene: Scene):
    """What plans.positions.parse_positions takes: a count, or the --at list (checked, in rad or m)."""
    if getattr(args, "positions", None) is not None and getattr(args, "at", None) is not None:
        raise SceneError("give either --positions N or --at with a list of positions, not both")
    return args.positions if args.positions is not None else _listed_positions(scene, args.at)


def _at(scene: Scene, text: str) -> Scene:
    kind = "angle" if isinstance(scene.driver, Crank) else "length"
    try:
        value = parse_quantity(_number(text), kind)
    except UnitError as exc:
        raise SceneError(str(exc), scene.source, "--at") from None
    return scene.at(_sane_position(scene, value, text))


#: A crank angle given with --at must lie within this many turns of 0 (beyond
#: it, the angle's own round-off passes a thousandth of a degree).
MAX_TURNS = 100
#: Positions of the sweep the cycle diagrams of ``plans sweep --plot`` are drawn from (at least; the CSV keeps --steps).
DRAWN_STEPS = 360
#: A linear driver's position given with --at must lie within this many times
#: the scene's size (the largest distance between two of its points).
MAX_TRAVEL = 1000


def _sane_position(scene: Scene, value: float, text: str) -> float:
    """*value* (rad or m) if it is a driver position plans can report; else a SceneError saying the range."""
    if isinstance(scene.driver, Crank):
        if math.isfinite(value) and abs(value) <= MAX_TURNS * 2 * math.pi:
            return value
        raise SceneError(
            f"{text!r} is not a crank angle plans can use: give an angle within ±{360 * MAX_TURNS}° "
            f"({MAX_TURNS} turns), such as \"30 deg\" (angles are the same every 360°)",
            scene.source,
            "--at",
        )
    points = [z for body in scene.bodies.values() for z in body.points.values()]
    size = max((abs(a - b) for a in points for b in points), default=0.0) or 1.0
    limit = MAX_TRAVEL * size
    if math.isfinite(value) and abs(value) <= limit:
        return value
    raise SceneError(
        f"{text!r} is not a position plans can use for the linear driver: give a position within ±{limit:.3g} m "
        f"({MAX_TRAVEL} times the scene's size, {size:.3g} m)",
        scene.source,
        "--at",
    )


def _listed_positions(scene: Scene, text: str) -> list[float]:
    """The positions of an --at list (\"10,25 deg\"), each checked as a single --at is."""
    from .positions import parse_positions

    values = parse_positions(text, scene)
    return [_sane_position(scene, v, text) for v in values]


def _number(text: str) -> float | str:
    try:
        return float(text)
    except ValueError:
        return text


def _construct(scene: Scene, args, scales: dict | None = None):
    """The graphical solution at the factors given (--k-l …, else the scene's, else automatic), or at *scales*
    (chosen by plans for a sheet: not checked again)."""
    from dataclasses import replace

    from .graphical import construct

    if args.precision == 0:  # exact readings, whatever the scene's [scales] say
        scene = replace(scene, scales=replace(scene.scales, precision=None))
        args.precision = None
    if scales is not None:
        return construct(
            scene, k_l=scales["k_l"], k_v=scales["k_v"], k_a=scales.get("k_a"), precision=args.precision,
            warn_condition=args.warn_condition, check_scales=False,
        )
    return construct(
        scene, k_l=args.k_l, k_v=args.k_v, k_a=args.k_a, precision=args.precision, warn_condition=args.warn_condition
    )


def _given_scales(args, scene: Scene) -> dict:
    """The factors the user gave (--k-l …, else the scene's [scales]): a sheet keeps them exactly."""
    return {key: getattr(args, key) if getattr(args, key) is not None else getattr(scene.scales, key) for key in ("k_l", "k_v", "k_a")}


def _one_line(text: str) -> str:
    """*text* as one line of a message: control characters (a newline in a file's name) written as escapes (``\\n``).

    >>> print(_one_line("my\\nscene.toml: bad"))
    my\\nscene.toml: bad
    """
    import unicodedata

    out = []
    for ch in text:
        if unicodedata.category(ch) in ("Cc", "Zl", "Zp"):
            out.append(repr(ch)[1:-1] if ch.isascii() else f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return "".join(out)


def _warn(message: str) -> None:
    print(f"plans: warning: {_one_line(message)}", file=sys.stderr)


def _warn_solution(analytic, graphical=None) -> None:
    """Near-dead-centre warnings on stderr: the analytic ones, then graphical ones for other groups."""
    warned = set()
    for warning in analytic.warnings:
        _warn(str(warning))
        warned.add(warning.group)
    if graphical is not None:
        for warning in graphical.warnings:
            if warning.group not in warned:
                _warn(f"{warning} (on the graphical plan)")


def _solve(args) -> int:
    from .analytic import solve
    from .report import format_json, solution_json, solution_table

    scene = _load(args)
    if _several(args):  # --at "10,25 deg": each position solved on its own, a table each, or a JSON list
        scenes = [scene.at(value) for value in _listed_positions(scene, args.at)]
    else:
        scenes = [scene]
    documents, tables, solutions = [], [], []
    cycle: dict = {}  # the law, Grashof classes, strokes: the scene file's, the same at every position asked for (filled below)
    for k, one in enumerate(scenes):
        analytic = solve(one, warn_condition=args.warn_condition)
        if not cycle:  # after the scene's own errors (solve's): what the cycle says of the scene file
            from .motion import cycle_summary

            cycle.update(cycle_summary(args.loaded_scene))
        graphical = comparisons = None
        if not args.analytic_only:
            from .compare import compare

            graphical = _construct(one, args)
            comparisons = compare(analytic, graphical)
        centres = _solve_centres(one, analytic, args)
        if args.json:
            doc = solution_json(analytic, graphical, comparisons)
            doc["cycle"] = cycle
            if centres is not None:
                from .report import add_centres_json

                add_centres_json(doc, *centres)
            documents.append(doc)
        else:
            table = solution_table(analytic, graphical, comparisons)
            if centres is not None:
                from .report import centres_comparison_table

                table += centres_comparison_table(centres[1])
            if len(scenes) > 1:
                table = f"position {k} of {len(scenes)}: {_position_words(one)}\n{table}"
            tables.append(table)
        solutions.append((analytic, graphical))
    if args.json:
        text = format_json(documents[0] if len(scenes) == 1 else documents)
    else:
        from .motion import cycle_text

        text = "\n".join(tables) + cycle_text(cycle)
    for analytic, graphical in solutions:
        _warn_solution(analytic, graphical)
    sys.stdout.write(text)
    return 0


def _solve_centres(scene: Scene, analytic, args):
    """The instant-centre method beside the others: (result, comparisons), or None when skipped or undetermined."""
    if args.no_centres or args.analytic_only:
        return None
    from .centres import CentreError, instant_centres
    from .compare import compare_centres

    try:
        result = instant_centres(scene, analytic.structure)
    except CentreError as exc:
        _warn(f"instant centres left out: {exc}")
        return None
    _warn_undetermined(result)
    return result, compare_centres(analytic, result)


def _warn_undetermined(result) -> None:
    for centre in result.centres:
        if not centre.determined:
            _warn(f"instant centre {centre.label} is {centre.describe()} (the velocities did not need it)")


def _centres(args) -> int:
    from .centres import instant_centres
    from .report import centres_table

    if not args.no_drawing:
        _check_directory(args.output, "plans centres -o")
    scene = _load(args)
    result = instant_centres(scene)
    text = centres_table(result)
    _warn_undetermined(result)
    if not args.no_drawing:
        from ._files import replace_all
        from .drawing.centres import centres_svg

        path = Path(args.output) / "centres.svg"
        data = centres_svg(result, args.k_l, args.lang)
        replace_all({path: data})
        text += f"\n{path}\n"
    sys.stdout.write(text)
    return 0


def _forces(args) -> int:
    """``plans forces``: the kinetostatics of one position (or of each of an --at list), as a table or JSON."""
    from .forces.compare import kinetostatics
    from .forces.report import forces_json, forces_table
    from .report import format_json

    if args.output is not None and args.analytic_only:
        raise SceneError("-o draws the graphical methods (force plans, Joukowski's lever): leave out --analytic-only")
    scene = _load(args)
    scenes = [scene.at(value) for value in _listed_positions(scene, args.at)] if _several(args) else [scene]
    if not scene.has_forces:
        _warn("the scene has no masses and no loads: every reaction and the balancing moment are zero "
              "(give mass, centre, inertia on the links, [gravity] and [[load]]; plans examples --loads lists scenes that do)")
    runs = []
    for one in scenes:
        if args.precision == 0:
            from dataclasses import replace

            one = replace(one, scales=replace(one.scales, precision=None))
        runs.append(kinetostatics(
            one, graphical=not args.analytic_only, k_l=args.k_l, k_v=args.k_v, k_a=args.k_a,
            precision=args.precision or None, warn_condition=args.warn_condition,
        ))
    if args.json:
        documents = [forces_json(run) for run in runs]
        text = format_json(documents[0] if len(runs) == 1 else documents)
    else:
        tables = []
        for k, run in enumerate(runs):
            table = forces_table(run, args.lang)
            if len(runs) > 1:
                table = f"position {k} of {len(runs)}: {_position_words(run.scene)}\n{table}"
            tables.append(table)
        text = "\n".join(tables)
    if args.output is not None:
        _force_drawings(args, runs)
    for run in runs:
        _warn_solution(run.analytic.kinematics, run.graphical)
        for note in run.notes:
            _warn(note)
    sys.stdout.write(text)
    return 0


def _force_drawings(args, runs) -> None:
    """``plans forces -o DIR``: every position's kinetostatic drawings and its pages (set by Typst: ``pages.pdf``, or
    ``page-N.svg`` / ``.png``), written together or not at all."""
    from dataclasses import replace

    from ._files import replace_all
    from .drawing.force_drawing import force_drawing_files

    from .forces.force_plans import force_plans
    from .forces.lever import LeverError, joukowski_lever
    from .graphical import construct
    from .pages.forces import drawn_group_names, force_document
    from .pages.typesetting import compile_document
    from .positions import at_page_precision

    directory = Path(args.output)
    contents: dict = {}
    for k, run in enumerate(runs):
        graphical, plans, lever = run.graphical, run.force_plans, run.lever
        if graphical.precision is None and args.precision != 0:
            # a drawing reads its lengths to 0.1 mm unless told (as plans draw's sheets): drawn again at that precision
            scene = at_page_precision(run.scene, None)
            graphical = construct(scene, k_l=graphical.scales["k_l"], k_v=graphical.scales["k_v"], k_a=graphical.scales.get("k_a"), check_scales=False)
            plans = force_plans(graphical)
            try:
                lever = joukowski_lever(graphical)
            except LeverError:
                lever = None
        where = directory if len(runs) == 1 else directory / f"position-{k}"
        names = drawn_group_names(plans.plans, args.lang)
        contents.update(force_drawing_files(plans, where, lang=args.lang, formats=(args.format,), lever=lever, names=names))
        doc, _ = force_document(replace(run, graphical=graphical, lever=lever), args.lang)
        pages = compile_document(doc.source(), doc.images, args.format)
        if args.format == "pdf":
            contents[where / "pages.pdf"] = pages
        else:
            for n, page in enumerate(pages, start=1):
                contents[where / f"page-{n}.{args.format}"] = page
    for path in replace_all(contents):
        print(path, file=sys.stderr)


def _position_words(scene: Scene) -> str:
    from .limits import position_text

    driver = scene.driver
    return position_text(isinstance(driver, Crank), driver.phi if isinstance(driver, Crank) else driver.s)


def _sweep(args) -> int:
    import numpy as np

    from ._files import batch, write_atomic
    from .report import sweep_csv
    from .sweep import analyse_sweep

    if args.plot:
        _check_directory(args.plot, "plans sweep --plot")
    scene = _load(args)
    if args.steps < 2:
        raise SceneError("--steps must be at least 2")
    driver = scene.driver
    if not isinstance(driver, Crank) and driver.stroke is None:
        raise SceneError("a sweep of a linear driver needs its stroke: add stroke = [start, end] to [driver]", scene.source, "driver.stroke")
    from .motion import driver_cycle, strokes

    # in the sense of ω, from the output's extreme position, under the driver's law (plans.motion)
    cycle = driver_cycle(scene, args.steps, law=args.law, start=args.start)
    positions = cycle.positions
    analytic = cycle.solve(warn_condition=math.inf)
    forces = None
    if scene.has_forces:  # M_b and every |R_ij| beside the kinematics
        if scene.accelerations:
            from .forces.analytic import forces_from

            forces = forces_from(analytic)
        else:
            _warn("the scene has masses or loads but asks for velocities only (accelerations = false): no force columns")
    text = sweep_csv(analytic, cycle.t, forces)
    lost = int(np.count_nonzero(~np.asarray(analytic.valid)))
    if lost == len(positions):
        raise _nowhere(scene, positions)
    if lost:
        _warn(f"the mechanism is not solved at {lost} of {args.steps} positions; their rows have assembled = 0 and empty cells")
    report = analyse_sweep(analytic, args.warn_condition)
    crossed = report.crossed
    if cycle.law.kind == "harmonic":  # a swing turns back at its limit positions, where its limiting group lines up
        limits = cycle.law.limits
        step = 2 * math.pi * max(limits.swing, 1e-9) / len(positions)  # (a grid step of the swing, in crank angle, generously)
        crossed = tuple(c for c in crossed if not (c.group == limits.group and min(
            abs(math.remainder(c.nearest - x, 2 * math.pi)) for x in (limits.lo, limits.hi)) <= step))
    for message in [str(x) for x in report.lost] + [str(x) for x in crossed]:
        _warn(message)
    stated = [cycle.law.describe(args.lang, driver.link, **({"phase": float(cycle.phase[0])} if cycle.law.kind == "harmonic" else {}))]
    if cycle.law.given_note(args.lang, driver.link):  # the scene's own ε (a), not the cycle's: said so beside the law
        stated[0] += "; " + cycle.law.given_note(args.lang, driver.link)
    found = strokes(scene, args.law, analytic.structure)
    if found is not None:
        stated += found.summary(args.lang)
    drawn, drawn_cycle = analytic, cycle
    if args.plot and cycle.law.kind in ("constant", "harmonic") and cycle.law.crank:
        # the diagrams' curves from a denser sweep (a magnitude's minimum not cut off between samples), a swing's
        # limit positions at their times (the input's ω = 0 there): the CSV keeps the steps asked for
        drawn_cycle = driver_cycle(scene, max(args.steps, DRAWN_STEPS), law=args.law, start=args.start, limits=True)
        drawn = drawn_cycle.solve(warn_condition=math.inf)
    marked = None
    if args.plot and args.positions:
        marked = driver_cycle(scene, args.positions, law=args.law, start=args.start)
    paths = []
    with batch():  # the CSV and the diagrams: all written, or none
        if args.output:
            write_atomic(args.output, text)
        if args.plot:
            if args.format == "svg":
                from .drawing.diagrams import write_cycle_diagrams

                paths = write_cycle_diagrams(drawn, args.plot, marked=marked, lang=args.lang, components=args.components, cycle=drawn_cycle, extremes=found)
            else:
                from ._files import replace_all
                from .drawing.diagrams import draw_cycle_diagrams
                from .drawing.formats import render

                figures = draw_cycle_diagrams(drawn, marked=marked, lang=args.lang, components=args.components, cycle=drawn_cycle, extremes=found)
                paths = replace_all({Path(args.plot) / f"{name}.{args.format}": render(fig, args.format) for name, fig in figures})
            paths = list(paths) + _kinematic_diagrams(scene, args)
            if forces is not None:
                paths.append(_force_diagrams(scene, args, forces, cycle))
    if not args.output:
        sys.stdout.write(text)
    for line in stated:  # the law and the strokes, once everything is written: on stdout beside the files, on stderr beside the CSV
        print(line, file=sys.stdout if args.output else sys.stderr)
    for path in paths:
        print(path, file=sys.stderr if not args.output else sys.stdout)
    return 0


def _kinematic_diagrams(scene: Scene, args) -> list:
    """``plans sweep --plot DIR``: the output link's kinematic diagrams by graphical differentiation, at
    ``--positions`` positions (12 by default), as one drawing DIR/kinematic.FORMAT (the three diagrams with the
    chord construction under a short caption); a mechanism without an output slider or rocker is said so on
    standard error."""
    from .differentiation import kinematic_diagrams

    try:
        diagrams = kinematic_diagrams(scene, args.positions or 12, law=args.law, start=args.start)
    except PlansError as exc:
        _warn(f"no kinematic diagrams of the output link: {exc}")
        return []
    return diagrams.save(Path(args.plot) / f"kinematic.{args.format}", lang=args.lang, title=scene.title_in(args.lang))


def _force_diagrams(scene: Scene, args, forces, cycle) -> Path:
    """``plans sweep --plot DIR`` of a scene with masses or loads: M_b(φ) (a linear driver: F_b(s)) and the polar
    diagram of the crank bearing's reaction on one page, DIR/forces.FORMAT, numbered at ``--positions`` positions
    (12 by default) from position 0 of the sweep."""
    from ._files import replace_all
    from .drawing.force_diagrams import draw_force_diagrams
    from .drawing.formats import render
    from .forces.analytic import forces_from
    from .forces.cycle import cycle_forces
    from .motion import driver_cycle

    marked_cycle = driver_cycle(scene, args.positions or 12, law=args.law, start=args.start)
    marked = forces_from(marked_cycle.solve(warn_condition=math.inf))
    page = draw_force_diagrams(cycle_forces(forces, cycle, marked, marked_cycle), lang=args.lang)
    path = Path(args.plot) / f"forces.{args.format}"
    return replace_all({path: render(page, args.format)})[0]


def _nowhere(scene: Scene, positions) -> PlansError:
    """The error for a sweep that solves no position at all: the first position's own error."""
    from .analytic import solve

    try:
        solve(scene, positions[:1])
    except PlansError as exc:
        return type(exc)(f"{exc}; the mechanism is not solved at any of the {len(positions)} positions of the sweep")
    return PlansError(f"{scene.source}: the mechanism is not solved at any of the {len(positions)} positions of the sweep")


def _draw(args) -> int:
    from dataclasses import replace

    from ._files import batch
    from .analytic import solve
    from .pages.sheet import fitted_sheet, write_drawings, write_position_sheets
    from .positions import at_page_precision, cycle_poses, cycle_sweep
    from .sweep import line_travel

    _check_directory(args.output, "plans draw -o", () if _several(args) else (".svg", ".pdf", ".png"))
    scene = _load(args)
    scene = at_page_precision(scene, args.precision)  # a sheet prints lengths to 0.1 mm unless told
    args.precision = None  # the scene's, set just above
    if _several(args):
        from .positions import run_positions

        if _is_file(args.output):
            raise SceneError(f"{args.output}: several positions give several sheets: give a directory (and --format {Path(args.output).suffix[1:]})")
        run = run_positions(scene, _position_spec(args, scene), k_l=args.k_l, k_v=args.k_v, k_a=args.k_a, precision=args.precision,
                            law=args.law, start=args.start)
        for message in run.skipped_messages():
            _warn(message)
        with batch():
            paths = write_position_sheets(run, Path(args.output), lang=args.lang, format=args.format, given=_given_scales(args, scene),
                                          progress=_progress(args))
        _progress_done(args)
    else:
        analytic = solve(scene, warn_condition=args.warn_condition)
        cycle = cycle_sweep(scene, analytic.structure)
        travel = line_travel(cycle)  # slots and guides drawn over the cycle's travel
        poses = cycle_poses(cycle)  # the frame (guides' hatching, supports) chosen over the cycle
        sheet = fitted_sheet(
            scene,
            replace(_construct(scene, args), travel=travel, cycle_poses=poses),
            analytic,
            lambda scales: replace(_construct(scene, args, scales), travel=travel, cycle_poses=poses),
            lang=args.lang,
            given=_given_scales(args, scene),
        )
        _warn_solution(analytic, sheet.graphical)
        with batch():
            if _is_file(args.output):  # -o page.png: the sheet alone, in the format of the suffix
                paths = [sheet.save(args.output)]
            else:
                paths = write_drawings(sheet, Path(args.output), lang=args.lang, format=args.format)
    for path in paths:
        print(path)
    return 0


_FILE_SUFFIXES = frozenset(
    ".jpg .jpeg .jpe .gif .bmp .tif .tiff .webp .eps .ps .svgz .pgf .raw .rgba .emf .wmf .ico .heic .avif "
    ".svg .pdf .png .csv .txt .json .toml .html .htm .md .tex .doc .docx .odt .xls .xlsx .zip .gz".split()
)


def _check_directory(output: str, what: str, files: tuple[str, ...] = ()) -> None:
    """Refuse a directory name that names a file format (``-o x.jpg``) unless it is already a directory.

    *files* are the suffixes that name a file this command writes instead of a directory.
    """
    path = Path(output)
    suffix = path.suffix.lower()
    if suffix in files or suffix not in _FILE_SUFFIXES or path.is_dir():
        return
    where = f"a directory or a {', '.join(files[:-1])} or {files[-1]} file" if files else "a directory"
    why = f"not a {suffix} file" if suffix in (".svg", ".pdf", ".png") else f"plans does not write {suffix}"
    raise OutputError(f"{output}: {what} takes {where}; {why} (give a directory name without {suffix}, or an existing directory)")


def _is_file(output: str) -> bool:
    """True when -o names a drawing file (page.svg, page.pdf, page.png) rather than a directory."""
    return Path(output).suffix.lower() in (".svg", ".pdf", ".png") and not Path(output).is_dir()


def _accelerations(text: str):
    """``all`` or position numbers ``0,6`` (for --accelerations)."""
    if text.strip().lower() == "all":
        return "all"
    try:
        numbers = [int(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected 'all' or position numbers such as 0,6, got {text!r}") from None
    if not numbers or any(n < 0 for n in numbers):
        raise argparse.ArgumentTypeError(f"expected 'all' or position numbers such as 0,6, got {text!r}")
    return numbers


def _handout(args) -> int:
    from ._files import batch
    from .handout import write_handout

    scene = _load(args)
    positions = _position_spec(args, scene) if _several(args) else None
    if positions is not None:
        from .positions import skipped_message, unsolved_positions

        for index, value, error in unsolved_positions(scene, positions):
            _warn(skipped_message(index, scene, value, str(error)))
    with batch():  # directories are created only when every page has been rendered
        paths = write_handout(
            scene,
            Path(args.output),
            positions=positions,
            lang=args.lang,
            k_l=args.k_l,
            k_v=args.k_v,
            k_a=args.k_a,
            precision=args.precision,
            components=args.components,
            centres=args.centres,
            forces=args.forces,
            progress=_progress(args),
            law=args.law,
            start=args.start,
            accelerations=args.accelerations,
            scales=args.scales,
        )
    _progress_done(args)
    for path in paths:
        print(path)
    return 0


def _progress(args):
    """A function that shows ``"page 5/28"`` on stderr, in place, when stderr is a terminal (and not --quiet); else None."""
    if getattr(args, "quiet", False) or not sys.stderr.isatty():
        return None

    def show(text: str) -> None:
        print(f"\rplans: {text}\033[K", end="", file=sys.stderr, flush=True)

    return show


def _progress_done(args) -> None:
    if _progress(args) is not None:
        print("\r\033[K", end="", file=sys.stderr, flush=True)


def _animate(args) -> int:
    from .lecture import animate, check_suffix

    check_suffix(args.output)  # before any work
    animation = animate(_load(args), args.positions, lang=args.lang, k_l=args.k_l, k_v=args.k_v, k_a=args.k_a,
                        precision=args.precision, law=args.law, start=args.start)
    for message in animation.run.skipped_messages():
        _warn(message)
    print(animation.save(args.output))
    return 0


def _bench(args) -> int:
    from . import bench

    return bench.run_command(args)


def _examples(args) -> int:
    if args.name:
        sys.stdout.write(example_path(args.name).read_text(encoding="utf-8"))
        return 0
    if args.loads:
        for name in example_names(loads=True):
            print(f"{name:20} {load(example_path(name)).title}")
        return 0
    for name in example_names():
        words = DESCRIPTIONS.get(name) or load(example_path(name)).title
        print(f"{name:14} {words}")
    return 0


_COMMANDS = {
    "solve": _solve,
    "sweep": _sweep,
    "draw": _draw,
    "handout": _handout,
    "animate": _animate,
    "bench": _bench,
    "centres": _centres,
    "forces": _forces,
    "examples": _examples,
}


def _error_text(exc: PlansError, scene: Scene | None) -> str:
    """The message of an error, naming the scene file (assembly, dead centre, structure) and with its notes."""
    text = str(exc)
    if scene is None or isinstance(exc, (SceneError, OutputError)):  # an output is not the scene's fault
        return text
    if not text.startswith(scene.source):
        text = f"{scene.source}: {text}"
    if isinstance(exc, (AssemblyError, SingularPositionError)) and scene.notes:
        text += "; note: " + "; ".join(scene.notes)
    return text


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit status (0, or 2 on an error)."""
    from ._startup import lighter_matplotlib

    lighter_matplotlib()  # a command does not need matplotlib's generated help texts
    args = build_parser().parse_args(argv)
    try:
        return _COMMANDS[args.command](args)
    except PlansError as exc:
        print(f"plans: error: {_one_line(_error_text(exc, getattr(args, 'loaded_scene', None)))}", file=sys.stderr)
        return EXIT_ERROR
    except BrokenPipeError:  # plans solve ... | head
        return 0
    except KeyboardInterrupt:  # Ctrl-C: files are written all at once at the end, so none is half written
        print("\nplans: interrupted; nothing written", file=sys.stderr)
        return 130
    except OSError as exc:  # an output file or directory that cannot be written
        target = getattr(exc, "filename2", None) or exc.filename  # a rename names the temporary file first
        where = f" {target}" if target else ""
        print(_one_line(f"plans: error: cannot write{where}: {exc.strerror or exc}"), file=sys.stderr)
        return EXIT_ERROR
