"""The examples in the docstrings run and print what they say (the README's API examples are tested elsewhere)."""

import doctest
import importlib
import pkgutil

import pytest

import plans

MODULES = sorted(m.name for m in pkgutil.walk_packages(plans.__path__, "plans.") if not m.name.endswith("__main__"))


def _with_examples():
    for name in MODULES:
        module = importlib.import_module(name)
        tests = doctest.DocTestFinder().find(module, name, module=module)
        if any(not example.options.get(doctest.SKIP) for t in tests for example in t.examples):
            yield name


@pytest.mark.parametrize("name", list(_with_examples()))
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0
    assert result.failed == 0, f"{result.failed} of {result.attempted} docstring examples in {name} fail"
