"""The scene: a planar linkage as its kinematic scheme shows it.

Loading a scene only parses and validates; units are converted once, here, and
everything inside plans is SI (m, rad, s).  Angles are measured from the +x
axis, counter-clockwise positive.

Model
-----
* A :class:`Body` is the frame or a moving link.  It lists its points in its
  own coordinates (for the frame, those are the global coordinates) and may
  carry guide :class:`Line` s.  The pose of a moving body is its angle φ (the
  angle its own x axis makes with the frame's x axis) and the global position
  of its own origin.
* A revolute joint is a point name shared by two bodies.  A name shared by
  k bodies is k − 1 revolute joints (a multiple joint).
* A :class:`Prismatic` joint makes a line of one body (the *slider*) slide on a
  line of another (the *guide*).  The two lines coincide and point the same
  way, so both bodies turn together.  The short form ``[[slider]]`` makes a
  slider block: an implicit body pinned at a point and sliding on a line.
* The driver is a :class:`Crank` (turning about a frame point) or a
  :class:`LinearDriver` (translating along a frame line).
* For the kinetostatics (optional; a scene without them solves its
  kinematics exactly as before): a :class:`Mass` per link (mass, centre of
  mass S in the link's own frame, moment of inertia J_S), the
  :class:`Gravity`, and external :class:`Load` s (a force at a point of a
  link, a resistance against the velocity of its point, or a couple).
"""

from __future__ import annotations

import cmath
import difflib
import math
import re
import tomllib
from dataclasses import astuple, dataclass, field, replace
from importlib import resources
from pathlib import Path

from .errors import SceneError
from .limits import COINCIDENT, MAX_MAGNITUDE, MIN_SCALE
from .units import UnitError, parse_quantity

__all__ = [
    "FRAME",
    "Line",
    "Body",
    "Prismatic",
    "NAME_FORMS",
    "Crank",
    "LinearDriver",
    "Scales",
    "Mass",
    "Gravity",
    "Load",
    "Scene",
    "load",
    "loads",
    "from_mapping",
    "body_words",
    "example_names",
    "example_path",
    "diameter",
]

#: The name of the fixed body.  Structural formulas print it as 0.
FRAME = "frame"


@dataclass(frozen=True)
class Line:
    """A straight guide line carried by a body, in that body's own coordinates.

    Attributes
    ----------
    body : str
        Name of the body that carries the line.
    name : str
        Name of the line within the body (``"rod"``, ``"slot"``).
    origin : complex
        A point of the line, body coordinates [m] (its ``through`` point).
    angle : float
        Direction of the line in the body's frame [rad], counter-clockwise.
    through : str or None
        The named point the line passes through, if it was given by name.
    """

    body: str
    name: str
    origin: complex
    angle: float
    through: str | None = None

    @property
    def key(self) -> str:
        """``"BODY.LINE"``, the way a scene file refers to the line."""
        return f"{self.body}.{self.name}"

    @property
    def direction(self) -> complex:
        """Unit vector of the line in body coordinates."""
        return cmath.exp(1j * self.angle)


@dataclass(frozen=True)
class Body:
    """The frame or one moving link.

    Attributes
    ----------
    name : str
        ``"frame"``, or the link's name (``"3"``, ``"coupler"``).
    points : dict[str, complex]
        Named points in the body's own coordinates [m].
    lines : dict[str, Line]
        Guide lines carried by the body.
    block : bool
        True for a slider block made by a ``[[slider]]`` entry.
    """

    name: str
    points: dict[str, complex]
    lines: dict[str, Line] = field(default_factory=dict)
    block: bool = False

    @property
    def is_frame(self) -> bool:
        return self.name == FRAME


#: The forms of a name a page needs (``[names]``): itself, as it reads after ∥, after "along the" / "direction of the".
NAME_FORMS = ("name", "parallel", "of")


@dataclass(frozen=True)
class Prismatic:
    """Line ``slider_line`` of body ``slider`` slides on line ``guide_line`` of body ``guide``.

    The relative travel is ``s = (Q_s − Q_g) · u_g``, where Q_s and Q_g are the
    origins (through points) of the two lines and u_g the guide's unit
    direction; ``v_rel = ds/dt`` and ``a_rel = d²s/dt²`` are the motion of the
    slider relative to the guide, and the Coriolis acceleration of the slider's
    point relative to the guide is ``2 ω_g × v_rel``.
    """

    name: str
    slider: str
    slider_line: str
    guide: str
    guide_line: str


@dataclass(frozen=True)
class Crank:
    """A link turning about a frame point: angle φ [rad], ω [rad/s], ε [rad/s²].

    φ is the angle of the crank's own x axis (so with ``O = [0, 0]`` and
    ``A = [r, 0]``, it is the direction of OA).
    """

    link: str
    pivot: str
    phi: float
    omega: float
    epsilon: float = 0.0
    #: The law over a cycle (``[driver] law``): ``"constant"``, ``"uniform"``, ``"harmonic"`` or None (not given:
    #: constant ω, or a harmonic swing for a crank that cannot turn fully); see :mod:`plans.motion`.
    law: str | None = None


@dataclass(frozen=True)
class LinearDriver:
    """A link translating along a frame line: position s [m], velocity [m/s], acceleration [m/s²].

    The link's own x axis lies along the guide, and its point ``point`` sits
    at ``origin + s · u`` of the guide.  ``stroke`` is the interval a sweep
    covers [m].
    """

    link: str
    point: str
    guide: str  # line name on the frame
    s: float
    velocity: float
    acceleration: float = 0.0
    stroke: tuple[float, float] | None = None
    #: The law over the stroke (``[driver] law``): ``"constant"``, ``"uniform"`` or None (constant); see :mod:`plans.motion`.
    law: str | None = None


@dataclass(frozen=True)
class Scales:
    """Drawing scale factors (physical = k × drawn length in mm); None means automatic."""

    k_l: float | None = None  # m/mm
    k_v: float | None = None  # (m/s)/mm
    k_a: float | None = None  # (m/s²)/mm
    precision: float | None = None  # drafting precision of a measured length, mm


@dataclass(frozen=True)
class Mass:
    """Mass and inertia of one moving body (``mass``, ``centre``, ``inertia`` of a ``[link.N]`` or ``[[slider]]``).

    Attributes
    ----------
    body : str
        The body's name.
    mass : float
        m [kg], not negative.
    centre : complex
        The centre of mass S in the body's own coordinates [m].
    inertia : float
        J_S, the moment of inertia about S [kg·m²], not negative.
    point : str or None
        The named point S is, if it was given by name (a block's default: its pin).
    """

    body: str
    mass: float
    centre: complex
    inertia: float = 0.0
    point: str | None = None


@dataclass(frozen=True)
class Gravity:
    """The weights G = m·g, acting at each centre of mass.

    Attributes
    ----------
    g : float
        |g| [m/s²], not negative.
    angle : float
        The direction g points in [rad], from +x counter-clockwise (−π/2: down, the default).
    """

    g: float
    angle: float = -math.pi / 2

    @property
    def vector(self) -> complex:
        """g as a vector [m/s²] (a component that is round-off of cos 90° is 0: straight down is (0, −g))."""
        x, y = math.cos(self.angle), math.sin(self.angle)
        return complex(self.g * (x if abs(x) > 1e-15 else 0.0), self.g * (y if abs(y) > 1e-15 else 0.0))


#: The kinds of :class:`Load`.
LOAD_KINDS = ("force", "resistance", "moment")


@dataclass(frozen=True)
class Load:
    """An external load on a moving body (a ``[[load]]`` of the scene).

    Attributes
    ----------
    name : str
        Its label (``name = "F_c"``; default ``F1``, ``F2``, … or ``M1``, … in file order).
    body : str
        The body it acts on.
    kind : str
        ``"force"``: a given force vector at ``at``; ``"resistance"``: a force of
        magnitude ``magnitude`` against the velocity of ``at`` (zero where that
        velocity is zero); ``"moment"``: a couple ``moment`` on the body.
    at : complex
        Point of application in the body's own coordinates [m] (0 for a couple).
    point : str or None
        The named point it acts at, if given by name.
    force : complex
        The force [N] (x + iy, frame axes) of a ``"force"``; 0 otherwise.
    magnitude : float
        |F| [N] of a ``"resistance"``.
    moment : float
        The couple [N·m], counter-clockwise positive, of a ``"moment"``.
    working : complex or None
        Unit vector: the load acts only while ``at`` moves along it (v·working > 0),
        the working stroke; None: always.
    """

    name: str
    body: str
    kind: str
    at: complex = 0j
    point: str | None = None
    force: complex = 0j
    magnitude: float = 0.0
    moment: float = 0.0
    working: complex | None = None


@dataclass(frozen=True)
class Scene:
    """A validated linkage, all in SI units.

    Attributes
    ----------
    title : str
    bodies : dict[str, Body]
        The frame first, then the links in file order, then slider blocks.
    prismatics : tuple[Prismatic, ...]
        All prismatic joints (slider blocks included; not the linear driver's).
    driver : Crank or LinearDriver
    assembly : dict[str, complex | int]
        Branch of each group: a point name mapped to where it lies near
        (complex, m), or to a branch sign (+1 or −1).
    accelerations : bool
        False when only velocities are asked for.
    report : tuple[str, ...]
        The points to report and draw, in order.
    scales : Scales
    source : str
        The file the scene came from (for messages).
    masses : dict[str, Mass]
        Body name -> its :class:`Mass`, for the bodies that have one.
    gravity : Gravity or None
        None: no weights.
    loads : tuple[Load, ...]
        External loads, in file order.
    """

    title: str
    bodies: dict[str, Body]
    prismatics: tuple[Prismatic, ...]
    driver: Crank | LinearDriver
    assembly: dict[str, complex | int]
    accelerations: bool
    report: tuple[str, ...]
    scales: Scales
    source: str = "<scene>"
    #: The output link (``[output] link``) whose extreme positions start a cycle; None: the last group's slider or rocker.
    output: str | None = None
    #: Line numbers of keys in the scene file, such as ``{"assembly.C": 31}``,
    #: for messages about them found after loading.
    key_lines: dict[str, int] = field(default_factory=dict, compare=False, repr=False)
    #: Advice for errors found after loading: a bare length (metres) far larger than the
    #: scene's other lengths, written by someone who meant millimetres.
    notes: tuple[str, ...] = field(default=(), compare=False, repr=False)
    #: How each bare (unit-less) non-zero number of the driver was read, such as
    #: ``"omega = 1850 → 1850 rad/s"``: bare numbers are SI and degrees.
    readings: tuple[str, ...] = field(default=(), compare=False, repr=False)
    #: Warnings about bare driver numbers that look meant in another unit (``omega = 1850`` is
    #: 17 666 rpm, ``angle = 2.396`` is 2.396°): every command prints them.
    doubts: tuple[str, ...] = field(default=(), compare=False, repr=False)
    #: The title in each language the scene gives it in (``title = { en = "…", sr = "…" }``);
    #: empty for a plain ``title = "…"``, which is printed as written in every language.
    titles: dict[str, str] = field(default_factory=dict, compare=False)
    #: Names used in words on a page (a guide, a point, a link), per language:
    #: ``[names] slot = { en = "slot", sr = "кулиса" }`` → ``{"slot": {"en": "slot", "sr": "кулиса"}}``;
    names: dict[str, dict[str, str]] = field(default_factory=dict, compare=False)
    #: A name's other forms per language (:data:`NAME_FORMS`, read by :meth:`name_in`):
    #: ``ru = { name = "кулиса", parallel = "кулисе" }`` → ``{"slot": {"ru.parallel": "кулисе"}}``.
    name_forms: dict[str, dict[str, str]] = field(default_factory=dict, compare=False)

    def title_in(self, lang: str) -> str:
        """The title in *lang*: as the scene gives it there, else as written (the English, else the first given)."""
        return self.titles.get(lang) or self.title

    def name_in(self, name: str, lang: str, form: str = "name") -> str:
        """A name (a guide's, a point's) in *lang* as the scene's ``[names]`` give it, else as written; *form* one of
        :data:`NAME_FORMS` (``"parallel"``: as it reads after ∥, ``"of"``: after "along the"), the name itself where
        the scene gives no such form."""
        other = self.name_forms.get(name, {}).get(f"{lang}.{form}") if form != "name" else None
        return other or self.names.get(name, {}).get(lang) or name
    masses: dict[str, Mass] = field(default_factory=dict)
    gravity: Gravity | None = None
    loads: tuple[Load, ...] = ()

    @property
    def has_forces(self) -> bool:
        """True when the scene has masses or loads: the kinetostatics has something to find."""
        return bool(self.loads) or any(m.mass > 0 or m.inertia > 0 for m in self.masses.values())

    # --- derived views, for solvers and drawings -----------------------------

    @property
    def frame(self) -> Body:
        return self.bodies[FRAME]

    @property
    def links(self) -> list[str]:
        """Names of the moving bodies (driver, links, blocks), in scene order."""
        return [name for name in self.bodies if name != FRAME]

    def pair_label(self, name: str) -> str:
        """The subscript a page writes prismatic pair *name*'s relative motion with (s, v^r, a^r, a^k): the pair's
        name where it is a point's label (``H``, ``C3``), else the two coincident points of the slider's line (its
        through point) on the slider and on the guide, the slider's first as s is the slider's travel along the
        guide: ``F3F4`` for rod 3 sliding in sleeve 4 (never a word such as ``s_sleeve``)."""
        if re.fullmatch(r"(?:[A-Z][0-9]*′?)+", name):
            return name
        pair = next((p for p in self.prismatics if p.name == name), None)
        if pair is None:
            return name
        point = self.bodies[pair.slider].lines[pair.slider_line].through
        if not point:
            return name
        label = {FRAME: self.frame_number}
        return f"{point}{label.get(pair.slider, pair.slider)}{point}{label.get(pair.guide, pair.guide)}"

    @property
    def frame_number(self) -> str:
        """The number the frame goes by on every page, in every formula and label.

        It follows the scene's numbering: ``"1"`` where the links start at 2
        (the crank is 2, as in the Serbian workbook), ``"0"`` where a link is
        already called 1 (the crank is 1, as in the Russian and Bulgarian
        courses); ``"frame"`` only if both 0 and 1 are taken.
        """
        links = self.links
        return "1" if "1" not in links else ("0" if "0" not in links else FRAME)

    def line(self, key: str) -> Line:
        """The line ``"BODY.LINE"``."""
        body, _, name = key.rpartition(".")
        return self.bodies[body].lines[name]

    def bodies_with(self, point: str) -> list[str]:
        """Names of the bodies that carry the point (frame first if it does)."""
        return [name for name, body in self.bodies.items() if point in body.points]

    @property
    def point_names(self) -> list[str]:
        """Every named point once, in scene order."""
        seen: dict[str, None] = {}
        for body in self.bodies.values():
            for name in body.points:
                seen.setdefault(name, None)
        return list(seen)

    def at(self, position: float) -> "Scene":
        """The same scene with its driver moved to *position*: a crank angle [rad] or a linear driver's s [m]."""
        driver = self.driver
        if isinstance(driver, Crank):
            return replace(self, driver=replace(driver, phi=float(position)))
        return replace(self, driver=replace(driver, s=float(position)))

    def home_of(self, point: str) -> str:
        """The body whose motion defines the point: a moving body if any carries it, else the frame."""
        names = self.bodies_with(point)
        moving = [n for n in names if n != FRAME]
        return moving[0] if moving else names[0]


# ---------------------------------------------------------------------------
# loading

_EXAMPLES = "plans.examples"


#: The sub-directory of the bundled scenes with masses and loads (``plans forces``).
_LOADED = "loaded"


def example_names(loads: bool = False) -> list[str]:
    """Names of the bundled example scenes (``plans examples``).

    *loads*: the scenes with masses and loads for the kinetostatics instead
    (``plans examples --loads``): ``"slider-crank-loads"`` (domain.md §11) and
    a loaded variant of each kinematic example that can carry loads.
    """
    folder = resources.files(_EXAMPLES)
    if loads:
        folder = folder / _LOADED
    return sorted(p.name[: -len(".toml")] for p in folder.iterdir() if p.name.endswith(".toml"))


def example_path(name: str) -> Path:
    """Path of a bundled example scene by name (``"six-bar"``, ``"slider-crank-loads"``)."""
    names = example_names()
    if name in names:
        return Path(str(resources.files(_EXAMPLES) / f"{name}.toml"))
    loaded = example_names(loads=True)
    if name in loaded:
        return Path(str(resources.files(_EXAMPLES) / _LOADED / f"{name}.toml"))
    close = difflib.get_close_matches(name, names + loaded, n=1)
    hint = f"; did you mean {close[0]!r}?" if close else ""
    raise SceneError(f"no bundled example {name!r}{hint} (plans examples lists them; plans examples --loads those with loads)")


def load(path: str | Path) -> Scene:
    """Read and validate a scene file (TOML).

    Parameters
    ----------
    path : str or pathlib.Path

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        Naming the file, the key and what is wrong.
    """
    path = Path(path)
    return loads(_read_scene_text(path), source=str(path))


#: Largest scene file plans reads [bytes]: far above any real scene (the bundled ones are ~1 kB).
MAX_SCENE_BYTES = 1_000_000
#: Deepest nesting of TOML arrays and tables a scene may have (a real scene nests 5 deep).
MAX_NESTING = 32
#: Most points (named points of all bodies, frame included) a scene may have.
MAX_POINTS = 2_000
#: Most bodies (moving links and slider blocks) a scene may have.
MAX_LINKS = 200
_MB = f"{MAX_SCENE_BYTES / 1e6:g} MB ({MAX_SCENE_BYTES:,} bytes)"


def _read_scene_text(path: Path) -> str:
    """The text of a scene file: a regular file of at most MAX_SCENE_BYTES, UTF-8.

    Devices, pipes and directories are refused without reading from them
    (``/dev/zero`` would never end); the file is opened non-blocking so that a
    FIFO with no writer is refused at once instead of hanging.
    """
    import os
    import stat

    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_CLOEXEC", 0))
    except OSError as exc:
        raise SceneError(f"cannot read the scene file: {exc.strerror or exc}", str(path)) from None
    mode = os.fstat(fd).st_mode
    if not stat.S_ISREG(mode):
        os.close(fd)
        kind = "a directory" if stat.S_ISDIR(mode) else "not a regular file (a device, pipe or socket)"
        raise SceneError(f"cannot read the scene file: it is {kind}; a scene is a TOML text file", str(path))
    with os.fdopen(fd, "rb") as handle:
        try:
            data = handle.read(MAX_SCENE_BYTES + 1)
        except OSError as exc:
            raise SceneError(f"cannot read the scene file: {exc.strerror or exc}", str(path)) from None
    if len(data) > MAX_SCENE_BYTES:
        raise SceneError(
            f"the scene file is larger than {_MB}, the most plans reads (a scene of a real mechanism is a few kB)",
            str(path),
        )
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise SceneError("the scene file is not UTF-8 text", str(path)) from None


_TOML_AT = re.compile(r"\s*\(at line (\d+), column (\d+)\)$")
_TOML_KEY = re.compile(r"""([A-Za-z0-9_\-]+|"[^"]*"|'[^']*')\s*=\s*\{""")


def _toml_error(message: str, text: str) -> str:
    """The parser's complaint in the scene's words: a key given twice named with its table and line.

    ``Cannot mutate immutable namespace ('B',) (at line 14, column 53)`` becomes
    ``link.3.points (line 14): the point B is given twice; give each point once``.
    Other complaints keep the parser's words.
    """
    at = _TOML_AT.search(message)
    if not at:
        return f"not valid TOML: {message}"
    line, column = int(at.group(1)), int(at.group(2))
    what = message[: at.start()]
    lines = text.splitlines()
    code = lines[line - 1] if 0 < line <= len(lines) else ""
    section = ""
    for previous in lines[: line - 1][::-1] + ([code] if code.lstrip().startswith("[") else []):
        header = previous.split("#", 1)[0].strip()
        if header.startswith("["):
            section = header.strip("[]").strip()
            break
    twice = None
    inline = _TOML_KEY.findall(code[: max(column - 1, 0)])
    if m := re.match(r"Duplicate inline table key '([^']*)'", what):
        twice = m.group(1)
    elif m := re.match(r"Cannot mutate immutable namespace \((.*)\)$", what):
        parts = re.findall(r"'([^']*)'", m.group(1))
        twice = parts[-1] if parts and inline else None
    elif what.startswith("Cannot overwrite a value"):
        key = code.split("=", 1)[0].strip() if "=" in code else ""
        if key:
            where = f"{section} (line {line})" if section else f"line {line}"
            return f"{where}: {key} is given twice; give each key once (not valid TOML: {what})"
    elif m := re.match(r"Cannot declare \((.*)\) twice", what):
        table = ".".join(re.findall(r"'([^']*)'", m.group(1)))
        return f"line {line}: the table [{table}] is declared twice; give it once, with all its keys (not valid TOML: {what})"
    if twice is None or not inline:
        return f"not valid TOML: {message}"
    owner = inline[-1].strip("\"'")
    field = f"{section}.{owner}" if section else owner
    noun = {"points": "point", "lines": "line"}.get(owner, "key")
    return f"{field} (line {line}): the {noun} {twice} is given twice; give each {noun} once (not valid TOML: {what})"


def loads(text: str, source: str = "<scene>") -> Scene:
    """Validate a scene given as TOML text; see :func:`load`."""
    if len(text) > MAX_SCENE_BYTES:
        raise SceneError(f"the scene is larger than {_MB}, the most plans reads", source)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(_toml_error(str(exc), text), source) from None
    except RecursionError:  # the parser recurses once per level of nested arrays or inline tables
        raise SceneError(_too_deep(), source) from None
    _check_nesting(data, source)
    return _SceneReader(data, source, text).scene()


def _too_deep() -> str:
    return (
        f"arrays or tables are nested more than {MAX_NESTING} deep; "
        "a scene nests a few levels (link.2.points.A = [x, y])"
    )


def _check_nesting(data: object, source: str) -> None:
    """Refuse values nested deeper than MAX_NESTING (checked without recursion)."""
    stack = [(data, 0)]
    while stack:
        value, depth = stack.pop()
        if depth > MAX_NESTING:
            raise SceneError(_too_deep(), source)
        if isinstance(value, dict):
            stack.extend((v, depth + 1) for v in value.values())
        elif isinstance(value, list):
            stack.extend((v, depth + 1) for v in value)


def from_mapping(data: dict, source: str = "<scene>") -> Scene:
    """Validate a scene given as the mapping TOML would parse to (for programs that build scenes)."""
    if not isinstance(data, dict):
        raise SceneError(f"a scene is a table of sections, got {_describe(data)}", source)
    _check_nesting(data, source)
    return _SceneReader(data, source, "").scene()


_TOP_KEYS = ("title", "names", "frame", "link", "slider", "prismatic", "driver", "assembly", "compute", "scales", "output", "gravity", "load")
_MASS_KEYS = ("mass", "centre", "inertia")
_BODY_KEYS = ("points", "lines") + _MASS_KEYS
_LINE_KEYS = ("through", "angle", "direction")
_SLIDER_KEYS = ("pin", "on", "name", "points") + _MASS_KEYS
_GRAVITY_KEYS = ("g", "angle")
_LOAD_KEYS = ("name", "link", "at", "force", "moment", "working")
_PRISMATIC_KEYS = ("line", "on", "name")
_CRANK_KEYS = ("crank", "pivot", "angle", "omega", "epsilon", "law")
_LINEAR_KEYS = ("slider", "on", "point", "position", "velocity", "acceleration", "stroke", "law")
_OUTPUT_KEYS = ("link",)
#: The driver laws a scene may name (see :mod:`plans.motion`); a linear driver has no swing.
CRANK_LAWS = ("constant", "uniform", "harmonic")
LINEAR_LAWS = ("constant", "uniform")
_COMPUTE_KEYS = ("accelerations", "points")
_SCALE_KEYS = ("k_l", "k_v", "k_a", "precision")
_NAME = re.compile(r"^[A-Za-z0-9_]+$")
_SI_UNITS = {
    "length": "m",
    "angle": "rad",
    "angular velocity": "rad/s",
    "angular acceleration": "rad/s^2",
    "velocity": "m/s",
    "acceleration": "m/s^2",
    "mass": "kg",
    "moment of inertia": "kg·m²",
    "force": "N",
    "moment": "N·m",
}


class _SceneReader:
    """Turns parsed TOML into a :class:`Scene`, naming the key path in every error."""

    def __init__(self, data: dict, source: str, text: str):
        self.data = data
        self.source = source
        self.text = text
        self.lengths: list[tuple[str, object, float]] = []  # (field, as written, m) of every length read
        self.bare_driver: list[tuple[str, float, float, str]] = []  # (field, as written, SI, kind) of bare driver numbers

    #: A bare length this many times the median of the scene's lengths is implausible.
    IMPLAUSIBLE = 20.0

    def length_notes(self) -> tuple[str, ...]:
        """Bare lengths (metres) implausibly large next to the others: the hint that bare lengths are metres."""
        sizes = sorted(abs(m) for _, _, m in self.lengths if m != 0)
        if not sizes:
            return ()
        median = sizes[len(sizes) // 2]
        notes = []
        for key, written, metres in self.lengths:
            if isinstance(written, (int, float)) and not isinstance(written, bool) and abs(metres) >= 1 and abs(metres) >= self.IMPLAUSIBLE * median:
                line = self._line_of(key)
                where = f"{key} (line {line})" if line else key
                notes.append(
                    f"bare lengths are metres: {where} = {written:g} is {abs(metres):g} m, next to lengths of about "
                    f"{median:.3g} m in the rest of the scene; write \"{written:g} mm\" if millimetres were meant"
                )
        return tuple(notes[:1])

    #: A bare angular velocity at least this large [rad/s] (4 775 rpm) looks meant as rpm.
    DOUBTFUL_OMEGA = 500.0
    #: A bare linear velocity at least this large [m/s] looks meant as mm/s.
    DOUBTFUL_VELOCITY = 50.0

    def driver_readings(self) -> tuple[tuple[str, ...], tuple[str, ...]]:
        """How each bare driver number was read, and warnings about those that look meant in another unit."""
        readings, doubts = [], []
        sizes = sorted(abs(m) for _, _, m in self.lengths if m != 0)
        median = sizes[len(sizes) // 2] if sizes else 0.0
        for key, written, si, kind in self.bare_driver:
            name = key.split(".", 1)[1]
            line = self._line_of(key.split("[")[0])
            where = f"{key} (line {line})" if line else key
            if kind == "angle":
                shown = f"{math.degrees(si):.6g}°"
            else:
                shown = f"{si:.6g} {_SI_UNITS[kind].replace('^2', '²')}"
            readings.append(f"{name} = {written:g} → {shown}")
            doubt = None
            if kind == "angle" and 0 < abs(written) <= 2 * math.pi and (2 * written) != int(2 * written):
                doubt = (f"is read as {written:g}° (bare angles are degrees); write \"{written:g} rad\" if radians were "
                         f"meant ({math.degrees(written):.4g}°)")
            elif kind == "angular velocity" and abs(si) >= self.DOUBTFUL_OMEGA:
                doubt = (f"is read as {written:g} rad/s = {abs(si) * 30 / math.pi:,.0f} rpm (bare angular velocities are "
                         f"rad/s); write \"{written:g} rpm\" if revolutions per minute were meant ({abs(written) * math.pi / 30:.4g} rad/s)")
            elif kind == "velocity" and abs(si) >= self.DOUBTFUL_VELOCITY:
                doubt = (f"is read as {written:g} m/s = {abs(si) * 3.6:,.0f} km/h (bare velocities are m/s); write "
                         f"\"{written:g} mm/s\" if millimetres per second were meant")
            elif kind == "length" and median and abs(si) >= 1 and abs(si) >= self.IMPLAUSIBLE * median:
                doubt = (f"is read as {written:g} m (bare lengths are metres), next to lengths of about {median:.3g} m in "
                         f"the rest of the scene; write \"{written:g} mm\" if millimetres were meant")
            if doubt:
                doubts.append(f"{where} = {written:g} {doubt}")
        return tuple(readings), tuple(doubts)

    # -- helpers ---------------------------------------------------------------

    def fail(self, field: str, message: str) -> SceneError:
        line = self._line_of(field)
        where = f"{field} (line {line})" if line else field
        return SceneError(message, self.source, where)

    def _line_of(self, field: str) -> int | None:
        """Line number of a key path in the TOML text (best effort).

        The key is looked for inside its own section: the ``[link.3]`` header
        (trailing comments allowed), the k-th ``[[slider]]`` for ``slider.k``,
        up to the next header; a key path no header names (a point inside an
        inline table) is looked for from its nearest enclosing header.
        """
        parts = re.sub(r"\[\d+\]", "", field).split(".")
        lines = self.text.splitlines()
        headers: list[tuple[int, str]] = []
        counts: dict[str, int] = {}
        for i, text in enumerate(lines):
            code = text.split("#", 1)[0].strip()
            if code.startswith("[[") and code.endswith("]]"):
                name = code[2:-2].strip()
                headers.append((i, f"{name}.{counts.get(name, 0)}"))
                counts[name] = counts.get(name, 0) + 1
            elif code.startswith("[") and code.endswith("]"):
                headers.append((i, code[1:-1].strip()))
        # the longest prefix of the key path that a header names
        section, depth = None, 0
        for k in range(len(parts), 0, -1):
            prefix = ".".join(parts[:k])
            match = [(i, h) for i, h in headers if h.replace('"', "") == prefix]
            if match:
                section, depth = match[0][0], k
                break
        if section is None:
            first, last = 0, (headers[0][0] if headers else len(lines))
        else:
            first = section
            later = [i for i, _ in headers if i > section]
            last = later[0] if later else len(lines)
            if depth == len(parts):
                return section + 1
        for key in reversed(parts[depth:]):
            if key.isdigit():
                continue
            pattern = re.compile(rf'(^|[\s{{,.\[])"?{re.escape(key)}"?\s*(=|\]|\.)')
            for i in range(first, last):
                if pattern.search(lines[i].split("#", 1)[0]):
                    return i + 1
        return section + 1 if section is not None else None

    def check_keys(self, table: dict, allowed: tuple[str, ...], field: str) -> None:
        for key in table:
            if key not in allowed:
                close = difflib.get_close_matches(key, allowed, n=1)
                hint = f"did you mean {close[0]!r}?" if close else f"allowed keys: {', '.join(allowed)}"
                path = f"{field}.{key}" if field else key
                raise self.fail(path, f"unknown key {key!r}; {hint}")

    def table(self, value: object, field: str) -> dict:
        if not isinstance(value, dict):
            raise self.fail(field, f"expected a table, got {_describe(value)}")
        return value

    def quantity(self, value: object, kind: str, field: str) -> float:
        try:
            number = parse_quantity(value, kind)
        except UnitError as exc:
            raise self.fail(field, str(exc)) from None
        if kind == "length" and field.split(".")[0] in ("frame", "link", "slider"):
            self.lengths.append((field, value, number))
        if field.startswith("driver.") and isinstance(value, (int, float)) and not isinstance(value, bool) and value != 0:
            self.bare_driver.append((field, value, number, kind))
        if abs(number) > MAX_MAGNITUDE:
            unit = _SI_UNITS[kind]
            raise self.fail(
                field,
                f"{value!r} is {number:.3g} {unit}, beyond the range plans computes in: a {kind} must be at most "
                f"{MAX_MAGNITUDE:g} {unit} in size, so that its squares and products stay finite",
            )
        return number

    def point(self, value: object, field: str) -> complex:
        if isinstance(value, dict) and set(value) == {"r", "angle"}:  # polar: a length at an angle
            r = self.quantity(value["r"], "length", f"{field}.r")
            angle = self.quantity(value["angle"], "angle", f"{field}.angle")
            if r < 0:
                raise self.fail(f"{field}.r", f"a distance r is not negative (got {value['r']!r}); turn the angle by 180° instead")
            return complex(r * math.cos(angle), r * math.sin(angle))
        if isinstance(value, dict):
            raise self.fail(
                field,
                "expected coordinates [x, y] in m (or [\"300 mm\", 0]), or a length at an angle "
                f"{{ r = \"260 mm\", angle = \"50 deg\" }}; got a table with keys {', '.join(map(str, value)) or 'none'}",
            )
        if not (isinstance(value, list) and len(value) == 2):
            raise self.fail(field, f"expected coordinates [x, y] in m (or [\"300 mm\", 0]), or {{ r = \"260 mm\", angle = \"50 deg\" }}; got {_describe(value)}")
        x = self.quantity(value[0], "length", f"{field}[0]")
        y = self.quantity(value[1], "length", f"{field}[1]")
        return complex(x, y)

    def triangulated(self, value: dict, points: dict[str, complex], field: str) -> complex:
        """A point given by its distances from two points listed before it on the same body.

        ``C = { distances = { A = "600 mm", B = "150 mm" } }``: the corner of the
        triangle ABC, to the left of A→B (``side = "right"`` for the other one).
        """
        self.check_keys(value, ("distances", "side"), field)
        raw = self.table(value["distances"], f"{field}.distances")
        if len(raw) != 2:
            raise self.fail(f"{field}.distances", "give the distances from two points, such as distances = { A = \"600 mm\", B = \"150 mm\" }")
        (a, ra), (b, rb) = raw.items()
        for name in (a, b):
            if name not in points:
                raise self.fail(f"{field}.distances.{name}", f"{name} is not a point listed before it on this body{_suggest(name, points)}")
        ra = self.quantity(ra, "length", f"{field}.distances.{a}")
        rb = self.quantity(rb, "length", f"{field}.distances.{b}")
        side = value.get("side", "left")
        if side not in ("left", "right"):
            raise self.fail(f"{field}.side", f"expected \"left\" or \"right\" (of the line {a}→{b}), got {_describe(side)}")
        A, B = points[a], points[b]
        d = abs(B - A)
        if ra <= 0 or rb <= 0 or d == 0 or ra + rb < d or abs(ra - rb) > d:
            raise self.fail(
                f"{field}.distances",
                f"no triangle has sides {a}{b} = {d:.6g} m, {ra:.6g} m and {rb:.6g} m (each side must be shorter than the other two together)",
            )
        x = (ra * ra - rb * rb + d * d) / (2 * d)
        h = math.sqrt(max(ra * ra - x * x, 0.0))
        return A + (x + 1j * (h if side == "left" else -h)) * (B - A) / d

    def direction(self, value: object, field: str) -> float:
        """The angle [rad] of a direction vector [dx, dy] (bare numbers or lengths, only the ratio counts)."""
        if not (isinstance(value, list) and len(value) == 2):
            raise self.fail(field, f"expected a direction [dx, dy], such as [1, 0] or [0.6, 0.8], got {_describe(value)}")
        z = complex(self.quantity(value[0], "length", f"{field}[0]"), self.quantity(value[1], "length", f"{field}[1]"))
        if abs(z) == 0 or not math.isfinite(abs(z)):
            raise self.fail(
                field,
                f"the direction [{z.real:g}, {z.imag:g}] has zero length and points nowhere; give a non-zero [dx, dy] "
                "(such as [1, 0] along x) or an angle",
            )
        return cmath.phase(z)

    def name(self, value: object, field: str, what: str) -> str:
        if isinstance(value, int) and not isinstance(value, bool):
            value = str(value)
        if not isinstance(value, str) or not _NAME.match(value):
            raise self.fail(field, f"expected the name of a {what} (letters, digits, _), got {_describe(value)}")
        return value

    def per_language(self, table: dict, field: str) -> dict[str, str]:
        """A table of texts by language (``{ en = "…", sr = "…" }``): every key a language, every value text."""
        from .i18n import LANGUAGES

        if not table:
            raise self.fail(field, "an empty table: give the text in at least one language (en = \"…\")")
        out = {}
        for lang, text in table.items():
            if lang not in LANGUAGES:
                raise self.fail(f"{field}.{lang}", f"unknown language {lang!r}; languages: {', '.join(LANGUAGES)}")
            if not isinstance(text, str) or not text.strip():
                raise self.fail(f"{field}.{lang}", f"expected text, got {_describe(text)}")
            out[lang] = text
        return out

    def name_forms(self, table: dict, field: str) -> dict[str, str]:
        """A ``[names]`` entry: per language the name as text, or its forms as a sentence needs them,
        ``ru = { name = "направляющая ползуна", parallel = "направляющей ползуна", of = "направляющей ползуна" }``
        (``parallel``: after ∥; ``of``: after "along the", "direction of the"; each defaults to ``name``).
        Returned as ``{"ru": name, "ru.parallel": …, "ru.of": …}``."""
        plain = {lang: text for lang, text in table.items() if not isinstance(text, dict)}
        out = self.per_language(plain, field) if plain else {}
        for lang, forms in table.items():
            if not isinstance(forms, dict):
                continue
            self.per_language({lang: "·"}, field)  # the language itself checked
            for form, text in forms.items():
                if form not in NAME_FORMS:
                    raise self.fail(f"{field}.{lang}.{form}", f"unknown form {form!r}; forms: {', '.join(NAME_FORMS)}")
                if not isinstance(text, str) or not text.strip():
                    raise self.fail(f"{field}.{lang}.{form}", f"expected text, got {_describe(text)}")
            if "name" not in forms:
                raise self.fail(f"{field}.{lang}", "give the name itself (name = \"…\") beside its other forms")
            out[lang] = forms["name"]
            out.update({f"{lang}.{form}": text for form, text in forms.items() if form != "name"})
        return out

    # -- sections --------------------------------------------------------------

    def scene(self) -> Scene:
        data = self.data
        self.check_keys(data, _TOP_KEYS, "")
        title = data.get("title", Path(self.source).stem)
        titles = {}
        if isinstance(title, dict):
            titles = self.per_language(title, "title")
            title = titles.get("en") or next(iter(titles.values()))
        if not isinstance(title, str):
            raise self.fail("title", f"expected text or a table of languages (en = \"…\", sr = \"…\"), got {_describe(title)}")
        page_names, page_forms = {}, {}
        for key, value in self.table(data.get("names", {}), "names").items():
            if not isinstance(value, dict):
                raise self.fail(f"names.{key}", f"expected a table of languages (en = \"…\", sr = \"…\"), got {_describe(value)}")
            forms = self.name_forms(value, f"names.{key}")
            page_names[key] = {k: v for k, v in forms.items() if "." not in k}
            page_forms[key] = {k: v for k, v in forms.items() if "." in k}

        bodies: dict[str, Body] = {}
        frame = self.table(data.get("frame", {}), "frame")
        bodies[FRAME] = self.body(FRAME, frame, "frame")
        links = self.table(data.get("link", {}), "link")
        if not links:
            raise self.fail("link", "a scene needs at least one moving link: add [link.2] with its points")
        for raw_name, table in links.items():
            name = self.name(raw_name, f"link.{raw_name}", "link")
            if name == FRAME or name == "0":
                raise self.fail(f"link.{raw_name}", "the frame is described under [frame], not as a link")
            bodies[name] = self.body(name, self.table(table, f"link.{name}"), f"link.{name}")

        prismatics = []
        sliders = data.get("slider", [])
        if not isinstance(sliders, list):
            raise self.fail("slider", "write slider blocks as [[slider]] tables")
        for k, table in enumerate(sliders):
            prismatics.append(self.slider(k, self.table(table, f"slider.{k}"), bodies))
        extra = data.get("prismatic", [])
        if not isinstance(extra, list):
            raise self.fail("prismatic", "write prismatic joints as [[prismatic]] tables")
        for k, table in enumerate(extra):
            prismatics.append(self.prismatic(k, self.table(table, f"prismatic.{k}"), bodies))
        for k, prismatic in enumerate(prismatics[: len(sliders)]):
            pin = prismatic.name
            if sum(pin in body.points for body in bodies.values()) < 2:
                raise self.fail(
                    f"slider.{k}.pin",
                    f"no link or frame has a point {pin!r} for block {prismatic.slider} to be pinned to"
                    f"{_suggest(pin, _all_points({n: b for n, b in bodies.items() if n != prismatic.slider}))}",
                )
        pins = [p.name for p in prismatics[: len(sliders)]]
        for k, prismatic in enumerate(prismatics[: len(sliders)]):
            if pins.count(prismatic.name) > 1:  # two blocks on one pin: name them C3, C4
                prismatics[k] = Prismatic(f"{prismatic.name}{prismatic.slider}", *astuple(prismatic)[1:])
        names = [p.name for p in prismatics]
        for name in names:
            if names.count(name) > 1:
                raise self.fail("slider", f"two prismatic joints are both named {name!r}; give one a name = \"...\"")

        self.check_size(bodies)
        self.check_coincident(bodies)
        if "driver" not in data:
            raise self.fail("driver", "missing [driver]: say which link is driven (crank = \"2\" or slider = \"2\")")
        driver = self.driver(self.table(data["driver"], "driver"), bodies)
        assembly = self.assembly(self.table(data.get("assembly", {}), "assembly"), bodies)
        accelerations, report = self.compute(self.table(data.get("compute", {}), "compute"), bodies)
        scales = self.scales(self.table(data.get("scales", {}), "scales"))
        masses = self.masses(links, sliders, prismatics, bodies)
        gravity = self.gravity(self.table(data["gravity"], "gravity")) if "gravity" in data else None
        raw_loads = data.get("load", [])
        if not isinstance(raw_loads, list):
            raise self.fail("load", "write loads as [[load]] tables")
        loads = tuple(self.load(k, self.table(table, f"load.{k}"), bodies) for k, table in enumerate(raw_loads))
        names = [load.name for load in loads]
        for k, name in enumerate(names):
            if names.index(name) != k:
                raise self.fail(f"load.{k}.name", f"two loads are both named {name!r} (also load.{names.index(name)}); give each its own name")
        output = self.output(self.table(data.get("output", {}), "output"), bodies)
        readings, doubts = self.driver_readings()
        return Scene(
            title=title,
            bodies=bodies,
            prismatics=tuple(prismatics),
            driver=driver,
            assembly=assembly,
            accelerations=accelerations,
            report=report,
            scales=scales,
            source=self.source,
            titles=titles,
            names=page_names,
            name_forms=page_forms,
            output=output,
            notes=self.length_notes(),
            readings=readings,
            doubts=doubts,
            key_lines={f"assembly.{name}": self._line_of(f"assembly.{name}") for name in assembly if self._line_of(f"assembly.{name}")},
            masses=masses,
            gravity=gravity,
            loads=loads,
        )

    # -- kinetostatics: masses, gravity, loads ----------------------------------

    def masses(self, links: dict, sliders: list, prismatics: list, bodies: dict[str, Body]) -> dict[str, Mass]:
        """The :class:`Mass` of every link and block that gives ``mass``, ``centre`` or ``inertia``."""
        out: dict[str, Mass] = {}
        for raw_name, table in links.items():
            name = str(raw_name)
            if any(key in table for key in _MASS_KEYS):
                out[name] = self.mass(table, f"link.{name}", bodies[name], default=None)
        for k, table in enumerate(sliders):
            if not any(key in table for key in _MASS_KEYS):
                continue
            block = prismatics[k].slider
            if str(block) in {str(n) for n in links}:
                raise self.fail(
                    f"slider.{k}.mass" if "mass" in table else f"slider.{k}",
                    f"the block is link {block}, described under [link.{block}]: give its mass, centre and inertia there",
                )
            pin = table["pin"]
            out[block] = self.mass(table, f"slider.{k}", bodies[block], default=pin)
        return dict(sorted(out.items(), key=lambda item: list(bodies).index(item[0])))

    def mass(self, table: dict, field: str, body: Body, default: str | None) -> Mass:
        """One body's mass, centre and inertia (a block's centre defaults to its pin, *default*)."""
        words = body_words(body.name) if not body.block else f"block {body.name}"
        mass = self.quantity(table.get("mass", 0.0), "mass", f"{field}.mass")
        if mass < 0:
            raise self.fail(f"{field}.mass", f"a mass is not negative (got {table['mass']!r})")
        inertia = self.quantity(table.get("inertia", 0.0), "moment of inertia", f"{field}.inertia")
        if inertia < 0:
            raise self.fail(f"{field}.inertia", f"a moment of inertia is not negative (got {table['inertia']!r})")
        if "centre" in table:
            centre, point = self.body_point(table["centre"], f"{field}.centre", body)
        elif default is not None:
            centre, point = body.points[default], default
        else:
            given = " and ".join(key for key in ("mass", "inertia") if key in table)
            raise self.fail(
                f"{field}.{'mass' if 'mass' in table else 'inertia'}",
                f"{words} has a {given} but no centre of mass: give centre = \"S\" (a point of {words}, "
                f"such as {', '.join(body.points)}) or centre = [x, y] in its own frame",
            )
        if "mass" not in table and "inertia" not in table:
            raise self.fail(f"{field}.centre", f"{words} has a centre but no mass or inertia: give mass = \"2 kg\" (and inertia), or leave the centre out")
        return Mass(body.name, mass, centre, inertia, point)

    def body_point(self, value: object, field: str, body: Body) -> tuple[complex, str | None]:
        """A point of *body*: its name, or coordinates [x, y] in the body's own frame; (coordinates, name or None)."""
        if isinstance(value, str):
            name = self.name(value, field, "point")
            if name not in body.points:
                words = body_words(body.name) if not body.block else f"block {body.name}"
                raise self.fail(field, f"{words} has no point {name!r}{_suggest(name, body.points)} (its points: {', '.join(body.points)}); or give [x, y] in its own frame")
            return body.points[name], name
        return self.point(value, field), None

    def gravity(self, table: dict) -> Gravity:
        self.check_keys(table, _GRAVITY_KEYS, "gravity")
        if "g" not in table:
            raise self.fail("gravity", "give g = \"9.81 m/s^2\" (and its direction angle, default -90 deg: down)")
        g = self.quantity(table["g"], "acceleration", "gravity.g")
        if g < 0:
            raise self.fail("gravity.g", f"g is its magnitude, not negative (got {table['g']!r}); turn its angle instead")
        angle = self.quantity(table.get("angle", -90.0), "angle", "gravity.angle")
        return Gravity(g, angle)

    def load(self, k: int, table: dict, bodies: dict[str, Body]) -> Load:
        field = f"load.{k}"
        self.check_keys(table, _LOAD_KEYS, field)
        if "link" not in table:
            raise self.fail(field, "a load needs link = \"N\", the link it acts on")
        link = self.name(table["link"], f"{field}.link", "link")
        if link == FRAME or link == "0":
            raise self.fail(f"{field}.link", "a load on the frame is taken by the frame: it loads no link; put it on a moving link")
        if link not in bodies:
            raise self.fail(f"{field}.link", f"there is no link {link!r}{_suggest(link, [n for n in bodies if n != FRAME])}")
        body = bodies[link]
        if ("force" in table) == ("moment" in table):
            raise self.fail(field, "a load is either force = ... at a point (at = \"B\") or a couple moment = \"20 N*m\"; give one of them")
        default = ("F" if "force" in table else "M") + str(k + 1)
        name = table.get("name", default)
        if not isinstance(name, str) or not name.strip():
            raise self.fail(f"{field}.name", f"expected text, got {_describe(name)}")
        if "moment" in table:
            for key in ("at", "working"):
                if key in table:
                    raise self.fail(f"{field}.{key}", f"a couple acts on the whole link, not at a point: leave {key} out (or give a force)")
            moment = self.quantity(table["moment"], "moment", f"{field}.moment")
            return Load(name, link, "moment", moment=moment)
        if "at" not in table:
            raise self.fail(field, f"a force needs the point it acts at: at = \"P\", a point of link {link} ({', '.join(body.points)})")
        at_value = table["at"]
        if isinstance(at_value, str) and self.name(at_value, f"{field}.at", "point") not in body.points:
            owners = [body_words(n) for n, b in bodies.items() if at_value in b.points]
            where = f"; {at_value} is a point of {' and '.join(owners)}" if owners else _suggest(at_value, body.points)
            raise self.fail(f"{field}.at", f"{at_value!r} is not a point of link {link} (its points: {', '.join(body.points)}){where}")
        at, point = self.body_point(at_value, f"{field}.at", body)
        working = None
        if "working" in table:
            working = cmath.exp(1j * self.direction(table["working"], f"{field}.working"))
        force = table["force"]
        if isinstance(force, list):
            if len(force) != 2:
                raise self.fail(f"{field}.force", f"expected [Fx, Fy], such as [\"1500 N\", 0], got {_describe(force)}")
            vector = complex(self.quantity(force[0], "force", f"{field}.force[0]"), self.quantity(force[1], "force", f"{field}.force[1]"))
            return Load(name, link, "force", at, point, force=vector, working=working)
        if not isinstance(force, dict):
            raise self.fail(f"{field}.force", f"expected [Fx, Fy], {{ magnitude, angle }} or {{ magnitude, against = \"velocity\" }}, got {_describe(force)}")
        if "magnitude" not in force:
            raise self.fail(f"{field}.force", "give the force's magnitude = \"1500 N\" with its angle, or with against = \"velocity\"")
        if "angle" in force and "against" in force:
            raise self.fail(f"{field}.force", "give the force's angle or against = \"velocity\", not both")
        self.check_keys(force, ("magnitude", "angle", "against"), f"{field}.force")
        magnitude = self.quantity(force["magnitude"], "force", f"{field}.force.magnitude")
        if magnitude < 0:
            raise self.fail(f"{field}.force.magnitude", f"a magnitude is not negative (got {force['magnitude']!r}); turn the force's angle instead")
        if "against" in force:
            if force["against"] != "velocity":
                raise self.fail(f"{field}.force.against", f"a resistance acts against = \"velocity\" (of its point), got {_describe(force['against'])}")
            return Load(name, link, "resistance", at, point, magnitude=magnitude, working=working)
        if "angle" not in force:
            raise self.fail(f"{field}.force", "give the force's angle (from +x, counter-clockwise), or against = \"velocity\"")
        angle = self.quantity(force["angle"], "angle", f"{field}.force.angle")
        return Load(name, link, "force", at, point, force=magnitude * cmath.exp(1j * angle), working=working)

    def body(self, name: str, table: dict, field: str) -> Body:
        self.check_keys(table, _BODY_KEYS, field)
        if name == FRAME:
            for key in _MASS_KEYS:
                if key in table:
                    raise self.fail(f"frame.{key}", f"the frame does not move: its {key} takes no part; give {', '.join(_MASS_KEYS)} on the links")
        raw_points = self.table(table.get("points", {}), f"{field}.points")
        points: dict[str, complex] = {}
        for pname, value in raw_points.items():
            pname = self.name(pname, f"{field}.points", "point")
            if isinstance(value, dict) and "distances" in value:
                points[pname] = self.triangulated(value, points, f"{field}.points.{pname}")
            else:
                points[pname] = self.point(value, f"{field}.points.{pname}")
        if name != FRAME and not points:
            raise self.fail(f"{field}.points", "a link needs its points, such as points = { A = [0, 0], B = [0.3, 0] }")
        raw_lines = self.table(table.get("lines", {}), f"{field}.lines")
        lines = {}
        for lname, spec in raw_lines.items():
            lname = self.name(lname, f"{field}.lines", "line")
            spec = self.table(spec, f"{field}.lines.{lname}")
            self.check_keys(spec, _LINE_KEYS, f"{field}.lines.{lname}")
            if "through" not in spec:
                raise self.fail(f"{field}.lines.{lname}", "a line needs through = \"POINT\" (or [x, y]) and angle (or direction = [dx, dy])")
            through = spec["through"]
            if "direction" in spec:
                if "angle" in spec:
                    raise self.fail(f"{field}.lines.{lname}", "give the line's angle or its direction = [dx, dy], not both")
                angle = self.direction(spec["direction"], f"{field}.lines.{lname}.direction")
            else:
                angle = self.quantity(spec.get("angle", 0.0), "angle", f"{field}.lines.{lname}.angle")
            if isinstance(through, str):
                pname = self.name(through, f"{field}.lines.{lname}.through", "point")
                if pname not in points:
                    raise self.fail(
                        f"{field}.lines.{lname}.through",
                        f"{body_words(name)} has no point {pname!r}{_suggest(pname, points)}",
                    )
                lines[lname] = Line(name, lname, points[pname], angle, pname)
            else:
                lines[lname] = Line(name, lname, self.point(through, f"{field}.lines.{lname}.through"), angle)
        return Body(name, points, lines)

    def line_ref(self, value: object, field: str, bodies: dict[str, Body]) -> tuple[str, str]:
        if not isinstance(value, str) or "." not in value:
            raise self.fail(field, f"expected a line as \"LINK.LINE\" (or \"frame.LINE\"), got {_describe(value)}")
        body, _, line = value.rpartition(".")
        if body == "0":
            body = FRAME
        if body not in bodies:
            raise self.fail(field, f"there is no link {body!r}{_suggest(body, bodies)}")
        if line not in bodies[body].lines:
            lines = bodies[body].lines
            known = f"; its lines are: {', '.join(lines)}" if lines else f"; {body_words(body)} has no lines (add lines = {{ {line} = {{ through = \"P\", angle = 0 }} }})"
            raise self.fail(field, f"{body_words(body)} has no line {line!r}{_suggest(line, lines) or known}")
        return body, line

    def slider(self, k: int, table: dict, bodies: dict[str, Body]) -> Prismatic:
        field = f"slider.{k}"
        self.check_keys(table, _SLIDER_KEYS, field)
        for key in ("pin", "on"):
            if key not in table:
                raise self.fail(field, f"a slider block needs pin = \"POINT\" and on = \"LINK.LINE\" (missing {key})")
        pin = self.name(table["pin"], f"{field}.pin", "point")
        guide, guide_line = self.line_ref(table["on"], f"{field}.on", bodies)
        if pin in bodies[guide].points:
            raise self.fail(f"{field}.pin", f"the block is pinned at {pin}, which is a point of its own guide's {body_words(guide)}: it could not slide")
        name = self.name(table.get("name", self.next_link_name(bodies)), f"{field}.name", "link")
        own: dict[str, complex] = {}
        if "points" in table:  # points of the block's own: its pin at (0, 0), its x axis along the guide
            for pname, value in self.table(table["points"], f"{field}.points").items():
                pname = self.name(pname, f"{field}.points", "point")
                if pname == pin:
                    raise self.fail(f"{field}.points.{pname}", f"the pin {pin} is the block's own (0, 0); list only its other points")
                own[pname] = self.point(value, f"{field}.points.{pname}")
        if name in bodies:
            body = bodies[name]
            if body.block or name == FRAME:
                raise self.fail(f"{field}.name", f"there is already a block named {name!r}")
            if pin not in body.points or not any(pin in b.points for n, b in bodies.items() if n != name):
                raise self.fail(
                    f"{field}.name",
                    f"there is already a link named {name!r}; to make it the block, give it the pin {pin} among its "
                    "points, pinned to another link or the frame there (the block's guide then runs through the pin "
                    "along the link's own x axis), or name the block otherwise",
                )
            if own:
                raise self.fail(f"{field}.points", f"link {name} lists its points under [link.{name}]; give them there")
            if "guide" in body.lines:
                raise self.fail(f"{field}.name", f"link {name} already has a line named 'guide'; rename it")
            lines = dict(body.lines)
            lines["guide"] = Line(name, "guide", body.points[pin], 0.0, pin)
            bodies[name] = Body(name, body.points, lines, block=True)
        else:
            bodies[name] = Body(name, {pin: 0j, **own}, {"guide": Line(name, "guide", 0j, 0.0, pin)}, block=True)
        return Prismatic(pin, name, "guide", guide, guide_line)

    def prismatic(self, k: int, table: dict, bodies: dict[str, Body]) -> Prismatic:
        field = f"prismatic.{k}"
        self.check_keys(table, _PRISMATIC_KEYS, field)
        for key in ("line", "on"):
            if key not in table:
                raise self.fail(field, f"a prismatic joint needs line = \"LINK.LINE\" and on = \"LINK.LINE\" (missing {key})")
        slider, slider_line = self.line_ref(table["line"], f"{field}.line", bodies)
        guide, guide_line = self.line_ref(table["on"], f"{field}.on", bodies)
        if slider == guide:
            raise self.fail(field, f"line and guide are both on {body_words(slider)}")
        if slider == FRAME:
            raise self.fail(f"{field}.line", "the frame cannot be the sliding part; swap line and on")
        name = table.get("name", f"{slider}.{slider_line}:{guide}.{guide_line}")
        if not isinstance(name, str):
            raise self.fail(f"{field}.name", f"expected text, got {_describe(name)}")
        return Prismatic(name, slider, slider_line, guide, guide_line)

    @staticmethod
    def next_link_name(bodies: dict[str, Body]) -> str:
        numbers = [int(n) for n in bodies if n.isdigit()]
        return str(max(numbers, default=1) + 1)

    def check_coincident(self, bodies: dict[str, Body]) -> None:
        """Points of one body at one place, or closer than COINCIDENT × the scene's size (one point to double precision).

        The scene's size is the largest distance between two of its points
        (:func:`diameter`, O(n log n)); close pairs are found on a grid of
        cells twice the tolerance wide (:func:`_close_pair`), so a scene of
        MAX_POINTS points is checked in well under a second.
        """
        size = diameter([z for body in bodies.values() for z in body.points.values()])
        tolerance = COINCIDENT * size
        for body in bodies.values():
            items = list(body.points.items())
            pair = _close_pair([z for _, z in items], tolerance)
            if pair is None:
                continue
            (a_name, a), (b_name, b) = items[pair[0]], items[pair[1]]
            field = "frame" if body.is_frame else f"link.{body.name}"
            if a == b:
                raise self.fail(
                    f"{field}.points.{b_name}",
                    f"points {a_name} and {b_name} of {body_words(body.name)} coincide at ({a.real:g}, {a.imag:g}) m; "
                    "one point name per location",
                )
            raise self.fail(
                f"{field}.points.{b_name}",
                f"points {a_name} and {b_name} of {body_words(body.name)} are {abs(a - b):.3g} m apart, "
                f"less than {COINCIDENT:g} of the scene's size ({size:.3g} m): they coincide to double "
                "precision; one point name per location, or a link long enough to compute with",
            )

    def check_size(self, bodies: dict[str, Body]) -> None:
        """Refuse scenes beyond MAX_POINTS points or MAX_LINKS bodies (time and memory stay bounded)."""
        points = sum(len(body.points) for body in bodies.values())
        if points > MAX_POINTS:
            raise self.fail("link", f"the scene has {points:,} points; plans takes at most {MAX_POINTS:,} (frame and links together)")
        if len(bodies) - 1 > MAX_LINKS:
            raise self.fail("link", f"the scene has {len(bodies) - 1:,} links and blocks; plans takes at most {MAX_LINKS:,}")

    def driver(self, table: dict, bodies: dict[str, Body]) -> Crank | LinearDriver:
        if "crank" in table and "slider" in table:
            raise self.fail("driver", "a driver is either crank = \"LINK\" or slider = \"LINK\", not both")
        if "crank" in table:
            self.check_keys(table, _CRANK_KEYS, "driver")
            link = self.name(table["crank"], "driver.crank", "link")
            if link not in bodies or link == FRAME:
                raise self.fail("driver.crank", f"there is no link {link!r}{_suggest(link, bodies)}")
            shared = [p for p in bodies[link].points if p in bodies[FRAME].points]
            if "pivot" in table:
                pivot = self.name(table["pivot"], "driver.pivot", "point")
                if pivot not in shared:
                    raise self.fail("driver.pivot", f"the crank turns about a frame point of link {link}; {pivot!r} is not one (candidates: {', '.join(shared) or 'none'})")
            elif len(shared) == 1:
                pivot = shared[0]
            elif not shared:
                raise self.fail("driver.crank", f"crank {link} shares no point with the frame: give the frame its pivot point (for example O = [0, 0]) and name it on link {link} too")
            else:
                raise self.fail("driver.pivot", f"crank {link} shares several points with the frame ({', '.join(shared)}); say which is the pivot = \"...\"")
            for key in ("angle", "omega"):
                if key not in table:
                    raise self.fail("driver", f"a crank needs angle and omega (missing {key}), such as angle = \"55 deg\", omega = \"10 rad/s\"")
            return Crank(
                link=link,
                pivot=pivot,
                phi=self.quantity(table["angle"], "angle", "driver.angle"),
                omega=self.quantity(table["omega"], "angular velocity", "driver.omega"),
                epsilon=self.quantity(table.get("epsilon", 0.0), "angular acceleration", "driver.epsilon"),
                law=self.law(table, CRANK_LAWS),
            )
        if "slider" in table:
            self.check_keys(table, _LINEAR_KEYS, "driver")
            link = self.name(table["slider"], "driver.slider", "link")
            if link not in bodies or link == FRAME:
                raise self.fail("driver.slider", f"there is no link {link!r}{_suggest(link, bodies)}")
            for key in ("on", "point", "position", "velocity"):
                if key not in table:
                    raise self.fail("driver", f"a linear driver needs on = \"frame.LINE\", point, position and velocity (missing {key})")
            guide_body, guide = self.line_ref(table["on"], "driver.on", bodies)
            if guide_body != FRAME:
                raise self.fail("driver.on", "a linear driver slides on a line of the frame")
            point = self.name(table["point"], "driver.point", "point")
            if point not in bodies[link].points:
                raise self.fail("driver.point", f"link {link} has no point {point!r}{_suggest(point, bodies[link].points)}")
            stroke = None
            if "stroke" in table:
                raw = table["stroke"]
                if not (isinstance(raw, list) and len(raw) == 2):
                    raise self.fail("driver.stroke", "expected [start, end], such as [\"0 mm\", \"200 mm\"]")
                stroke = (self.quantity(raw[0], "length", "driver.stroke[0]"), self.quantity(raw[1], "length", "driver.stroke[1]"))
                if stroke[0] == stroke[1]:
                    raise self.fail("driver.stroke", "the stroke has zero length")
            return LinearDriver(
                link=link,
                point=point,
                guide=guide,
                s=self.quantity(table["position"], "length", "driver.position"),
                velocity=self.quantity(table["velocity"], "velocity", "driver.velocity"),
                acceleration=self.quantity(table.get("acceleration", 0.0), "acceleration", "driver.acceleration"),
                stroke=stroke,
                law=self.law(table, LINEAR_LAWS),
            )
        raise self.fail("driver", "say which link is driven: crank = \"2\" (turning) or slider = \"2\" (translating)")

    def law(self, table: dict, laws: tuple[str, ...]) -> str | None:
        """``[driver] law``: one of *laws*, or None when not given."""
        if "law" not in table:
            return None
        law = table["law"]
        if law not in laws:
            raise self.fail("driver.law", f"expected one of {', '.join(repr(x) for x in laws)}, got {_describe(law)}")
        return law

    def output(self, table: dict, bodies: dict[str, Body]) -> str | None:
        """``[output] link``: the link whose extreme positions start a cycle, or None."""
        self.check_keys(table, _OUTPUT_KEYS, "output")
        if "link" not in table:
            return None
        link = table["link"]
        if not isinstance(link, (str, int)) or isinstance(link, bool) or str(link) not in bodies or str(link) == FRAME:
            raise self.fail("output.link", f"expected the name of a moving link, got {_describe(link)}{_suggest(str(link), bodies)}")
        return str(link)

    def assembly(self, table: dict, bodies: dict[str, Body]) -> dict[str, complex | int]:
        points = _all_points(bodies)
        out: dict[str, complex | int] = {}
        for name, value in table.items():
            if name not in points:
                raise self.fail(f"assembly.{name}", f"no link has a point {name!r}{_suggest(name, points)}")
            if isinstance(value, int) and not isinstance(value, bool) and value in (1, -1):
                out[name] = int(value)
            else:
                if not isinstance(value, list):
                    raise self.fail(f"assembly.{name}", f"expected where {name} lies near, [x, y] in m, or a branch sign +1 / -1; got {_describe(value)}")
                out[name] = self.point(value, f"assembly.{name}")
        return out

    def compute(self, table: dict, bodies: dict[str, Body]) -> tuple[bool, tuple[str, ...]]:
        self.check_keys(table, _COMPUTE_KEYS, "compute")
        accelerations = table.get("accelerations", True)
        if not isinstance(accelerations, bool):
            raise self.fail("compute.accelerations", f"expected true or false, got {_describe(accelerations)}")
        points = _all_points(bodies)
        if "points" in table:
            raw = table["points"]
            if not isinstance(raw, list) or not raw:
                raise self.fail("compute.points", "expected a list of point names, such as [\"A\", \"B\", \"M\"]")
            report = []
            for k, name in enumerate(raw):
                name = self.name(name, f"compute.points[{k}]", "point")
                if name not in points:
                    raise self.fail(f"compute.points[{k}]", f"no link has a point {name!r}{_suggest(name, points)}")
                if name in report:
                    raise self.fail(
                        f"compute.points[{k}]",
                        f"point {name!r} is listed twice (also as compute.points[{report.index(name)}]); list each point once",
                    )
                report.append(name)
        else:
            # every point that moves, in the order the links name them
            moving = _all_points({n: b for n, b in bodies.items() if n != FRAME})
            report = [p for p in moving if p not in bodies[FRAME].points]
        return accelerations, tuple(report)

    def scales(self, table: dict) -> Scales:
        self.check_keys(table, _SCALE_KEYS, "scales")
        values = {}
        for key in _SCALE_KEYS:
            if key in table:
                value = table[key]
                if key == "precision":
                    number = self.quantity(value, "length", "scales.precision") * 1e3  # m -> mm
                    if isinstance(value, (int, float)):
                        number = float(value)  # a bare number is already in mm
                elif isinstance(value, (int, float)) and not isinstance(value, bool):
                    number = float(value)
                else:
                    raise self.fail(f"scales.{key}", f"expected a number (per mm of drawing), got {_describe(value)}")
                if not math.isfinite(number) or number <= 0:
                    raise self.fail(f"scales.{key}", f"must be a positive number, got {value!r}")
                if not MIN_SCALE <= number <= MAX_MAGNITUDE:
                    raise self.fail(f"scales.{key}", f"{value!r} is outside the range plans computes in ({MIN_SCALE:g} to {MAX_MAGNITUDE:g})")
                values[key] = number
        return Scales(**values)


def diameter(zs: list[complex]) -> float:
    """The largest distance |a − b| between two of the points [m]; 0 for fewer than two.

    The farthest pair is a pair of antipodal vertices of the convex hull
    (monotone chain, then rotating calipers): O(n log n) instead of
    comparing all pairs.  Orientations are decided exactly (see
    :func:`_turn`), so nearly collinear points cannot mislead the hull.
    """
    hull = _hull(zs)
    if len(hull) < 2:
        return 0.0
    if len(hull) == 2:
        return abs(hull[0] - hull[1])
    n = len(hull)
    best = 0.0
    j = 1
    for i in range(n):
        p, q = hull[i], hull[(i + 1) % n]
        # advance j while hull[j + 1] is farther from the line pq than hull[j]
        while _turn(p, q, hull[j], hull[(j + 1) % n]) > 0:
            j = (j + 1) % n
        best = max(best, abs(hull[j] - p), abs(hull[j] - q))
    return best


def _turn(a: complex, b: complex, c: complex, d: complex) -> int:
    """The sign of the cross product (b − a) × (d − c), exactly.

    In floating point when the result is far from round-off, else with exact
    rational arithmetic on the coordinates (they are binary fractions).
    """
    ux, uy, vx, vy = b.real - a.real, b.imag - a.imag, d.real - c.real, d.imag - c.imag
    left, right = ux * vy, uy * vx
    det = left - right
    if abs(det) > 8 * _EPS * (abs(left) + abs(right)) and math.isfinite(det):
        return 1 if det > 0 else -1
    from fractions import Fraction as F

    exact = (F(b.real) - F(a.real)) * (F(d.imag) - F(c.imag)) - (F(b.imag) - F(a.imag)) * (F(d.real) - F(c.real))
    return (exact > 0) - (exact < 0)


_EPS = 2.0**-52


def _hull(zs: list[complex]) -> list[complex]:
    """Convex hull, counter-clockwise, without collinear points (Andrew's monotone chain)."""
    points = sorted(set(zs), key=lambda z: (z.real, z.imag))
    if len(points) <= 2:
        return points

    def half(seq):
        out: list[complex] = []
        for z in seq:
            while len(out) >= 2 and _turn(out[-2], out[-1], out[-2], z) <= 0:
                out.pop()
            out.append(z)
        return out

    lower, upper = half(points), half(reversed(points))
    return lower[:-1] + upper[:-1]


def _close_pair(zs: list[complex], tolerance: float) -> tuple[int, int] | None:
    """Indices (i, j), i < j, of two points at most *tolerance* apart, or None.

    Exactly equal points first (a dictionary), then, for a positive tolerance,
    neighbours on a grid of cells 2 × tolerance wide: two points within the
    tolerance lie in the same or adjacent cells, and a cell's neighbourhood
    holds a bounded number of points unless some of them are close (and then
    the first found is reported).  Of several pairs the one with the smallest
    j, then the smallest i, is returned.
    """
    seen: dict[complex, int] = {}
    for j, z in enumerate(zs):
        if z in seen:
            return seen[z], j
        seen[z] = j
    if not tolerance > 0 or len(zs) < 2:
        return None
    x0 = min(z.real for z in zs)
    y0 = min(z.imag for z in zs)
    width = 2.0 * tolerance
    cells: dict[tuple[int, int], list[int]] = {}
    for j, z in enumerate(zs):
        cx, cy = math.floor((z.real - x0) / width), math.floor((z.imag - y0) / width)
        near = [
            i
            for dx in (-1, 0, 1)
            for dy in (-1, 0, 1)
            for i in cells.get((cx + dx, cy + dy), ())
            if abs(zs[i] - z) <= tolerance
        ]
        if near:
            return min(near), j
        cells.setdefault((cx, cy), []).append(j)
    return None


def _all_points(bodies: dict[str, Body]) -> dict[str, None]:
    out: dict[str, None] = {}
    for body in bodies.values():
        for name in body.points:
            out.setdefault(name, None)
    return out


def _suggest(name: str, options) -> str:
    close = difflib.get_close_matches(str(name), [str(o) for o in options], n=1)
    return f"; did you mean {close[0]!r}?" if close else ""


def body_words(name: str) -> str:
    """``"the frame"`` or ``"link 3"``, for messages."""
    return "the frame" if name == FRAME else f"link {name}"


def _describe(value: object) -> str:
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return f"a list of {len(value)}"
    return repr(value)
