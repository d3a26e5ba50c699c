"""The shape of the package, read statically (ast): no import cycle among plans' modules,
and no private name (``_name``) imported from another module.

Every import counts, including those inside functions (a lazy import is still a
dependency: importing it the other way round makes a cycle).
"""

from __future__ import annotations

import ast
from pathlib import Path

import plans

ROOT = Path(plans.__file__).parent


def _modules() -> dict[str, Path]:
    found = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found[".".join(parts)] = path
    return found


MODULES = _modules()


def _imports(module: str, path: Path):
    """(target module, imported name or None) for every import of a plans module in *path*."""
    package = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[: len(package) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.split(".")[0] != "plans":
                continue
            for alias in node.names:
                full = f"{target}.{alias.name}"
                yield (full, None) if full in MODULES else (target, alias.name)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "plans":
                    yield alias.name, None


def _graph() -> dict[str, set[str]]:
    return {m: {t for t, _ in _imports(m, p) if t in MODULES and t != m} for m, p in MODULES.items()}


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan, iterative)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = 0
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on.add(root)
        while work:
            v, children = work[-1]
            for w in children:
                if w not in index:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(graph[w]))))
                    break
                if w in on:
                    low[v] = min(low[v], index[w])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[v])
                if low[v] == index[v]:
                    component = []
                    while True:
                        w = stack.pop()
                        on.discard(w)
                        component.append(w)
                        if w == v:
                            break
                    if len(component) > 1:
                        out.append(sorted(component))
    return out


def test_the_checker_sees_a_cycle_and_the_modules():
    # the checker itself: a planted cycle is found, and the package is really read
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert {"plans.drawing.readings", "plans.graphical.plan", "plans.handout", "plans.pages.handout"} <= set(MODULES)
    assert "plans.drawing.svgblocks" in _graph()["plans.pages.handout"]


def test_no_import_cycle_among_plans_modules():
    graph = _graph()
    # packages import their own modules; a module importing its parent package is what would close a loop
    assert _cycles(graph) == []


def test_the_graphical_layer_never_reaches_the_drawing_layer():
    graph = _graph()
    for module, targets in graph.items():
        if module.startswith(("plans.graphical", "plans.analytic", "plans.scene", "plans.structure")):
            assert not any(t.startswith("plans.drawing") for t in targets), (module, targets)


def test_no_private_name_is_imported_from_another_module():
    crossings = [
        (module, target, name)
        for module, path in MODULES.items()
        for target, name in _imports(module, path)
        if name is not None and name.startswith("_") and not name.startswith("__") and target != module
    ]
    assert crossings == []


def test_pages_are_set_from_drawing_blocks_and_drawing_knows_nothing_of_pages():
    graph = _graph()
    assert "plans.drawing.svgblocks" in graph["plans.pages.handout"]  # the plate places drawings of known size
    assert "plans.pages.typesetting" in graph["plans.pages.handout"]
    for module, targets in graph.items():
        if module.startswith("plans.drawing"):
            assert not any(t.startswith("plans.pages") for t in targets), (module, targets)
    # the handout's API module only orchestrates: it draws nothing and sets nothing itself
    assert not any(t.startswith("plans.drawing") for t in graph["plans.handout"]), graph["plans.handout"]
    # the sheets of plans draw are pages on the one engine: drawing blocks set by Typst through the Document
    assert {"plans.drawing.svgblocks", "plans.pages.document"} <= set(graph["plans.pages.sheet"])
    assert "plans.sheets" not in graph and "plans.drawing.sheets" not in graph  # the old fitter is gone
