"""Every example of the module's docstrings (the lines that start with '>>> ') runs, so that
help() cannot show a call that fails. They run in one namespace where `solver` is a GeodesicSolver
of the bundled bunny, `V` and `F` its arrays, and `np` and `dggvtp` are imported."""
import inspect

import numpy as np
import pytest

import dggvtp
import dggvtp.gdist
from conftest import mesh


def documented():
    """(name, docstring) of the module, its functions, classes and their methods"""
    out = [("dggvtp", dggvtp.__doc__)]
    for name in dggvtp.__all__:
        obj = getattr(dggvtp, name)
        out.append((name, getattr(obj, "__doc__", None)))
        if inspect.isclass(obj):
            for member, value in vars(obj).items():
                if not member.startswith("_") or member == "__init__":
                    out.append((f"{name}.{member}", getattr(value, "__doc__", None)))
    for name in getattr(dggvtp.gdist, "__all__", []):
        out.append((f"gdist.{name}", getattr(getattr(dggvtp.gdist, name), "__doc__", None)))
    return out


EXAMPLES = [(name, line[4:]) for name, doc in documented() if doc for line in doc.splitlines()
            if line.startswith(">>> ")]


def test_there_are_examples():
    assert EXAMPLES, "no '>>> ' line in the docstrings"


@pytest.fixture(scope="module")
def namespace():
    V, F = dggvtp.read_mesh(mesh("bunny.ply"))
    return {"np": np, "dggvtp": dggvtp, "V": V, "F": F, "solver": dggvtp.GeodesicSolver(V, F)}


@pytest.mark.parametrize("name,code", EXAMPLES, ids=[f"{n}:{c[:40]}" for n, c in EXAMPLES])
def test_example_runs(name, code, namespace):
    exec(compile(code, f"<docstring of {name}>", "exec"), namespace)
