"""The type stubs (gpsurf/__init__.pyi, with py.typed) against the module: the same names, and for
every function and method the parameters and defaults that pybind11's own signatures give (as
inspect.signature reads them); mypy accepts a script written against them."""
import ast
import importlib.util
import inspect
import os
import subprocess
import sys
import textwrap

import pytest

import gpsurf

PACKAGE_DIR = os.path.dirname(gpsurf.__file__)
STUB = os.path.join(PACKAGE_DIR, "__init__.pyi")
TYPE_ALIASES = {"PathLike", "FloatArray", "IntArray", "Progress"}


def runtime_parameters(function):
    """[(name, default or inspect.Parameter.empty)] as inspect.signature gives them (the package
    reads them from pybind11's own signature of the compiled function), `self` left out."""
    return [(p.name, p.default) for p in inspect.signature(function).parameters.values() if p.name != "self"]


def stub_parameters(node):
    """[(name, default or None)] of a stub's function, keyword-only ones last, `self` left out; `...`
    stands for any default. Of overloads, the last is compared with the runtime's defaults."""
    args = node.args.args + node.args.kwonlyargs
    defaults = [None] * (len(node.args.args) - len(node.args.defaults)) + list(node.args.defaults)
    defaults += node.args.kw_defaults
    return [(a.arg, d) for a, d in zip(args, defaults) if a.arg != "self"]


def same_default(runtime, stub):
    if (runtime is inspect.Parameter.empty) != (stub is None):
        return False
    if stub is None or (isinstance(stub, ast.Constant) and stub.value is Ellipsis):
        return True
    return ast.literal_eval(stub) == runtime


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read())


def test_stubs_are_installed_with_the_package():
    assert os.path.isfile(STUB)
    assert os.path.isfile(os.path.join(PACKAGE_DIR, "py.typed"))


def compare(where, runtime_function, stub_node, problems):
    """Appends to `problems` where the stub's parameters differ from the runtime's."""
    runtime, stub = runtime_parameters(runtime_function), stub_parameters(stub_node)
    if [n for n, _ in runtime] != [n for n, _ in stub] or not all(
            same_default(r, s) for (_, r), (_, s) in zip(runtime, stub)):
        problems.append(f"{where}: {runtime} against the stub's {[(n, d and ast.unparse(d)) for n, d in stub]}")


def test_stubs_name_what_the_module_has_with_its_parameters():
    stubbed = {}
    for node in stub_tree().body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            stubbed[node.name] = node
        elif isinstance(node, (ast.AnnAssign, ast.Assign)):
            target = node.target if isinstance(node, ast.AnnAssign) else node.targets[0]
            stubbed[target.id] = node
    public = {name for name in dir(gpsurf) if not name.startswith("_")} | {"__version__"}
    assert set(stubbed) - TYPE_ALIASES == public | ({"render", "read_image", "write_image"} - public)
    problems = []
    for name, node in stubbed.items():
        if name not in public:
            continue
        if isinstance(node, ast.FunctionDef):
            compare(name, getattr(gpsurf, name), node, problems)
        elif isinstance(node, ast.ClassDef) and node.name not in ("Error", "Cancelled"):
            cls = getattr(gpsurf, name)
            methods = [n for n in node.body if isinstance(n, ast.FunctionDef)]
            setters = {n.name for n in methods
                       if any(isinstance(d, ast.Attribute) and d.attr == "setter" for d in n.decorator_list)}
            properties = {n.name for n in methods if any(isinstance(d, ast.Name) and d.id == "property"
                                                         for d in n.decorator_list)}
            functions = {n.name: n for n in methods if n.name not in properties}
            runtime = {m for m in vars(cls) if not m.startswith("_") or m in ("__init__", "__copy__", "__deepcopy__")}
            if not hasattr(gpsurf, "render"):
                runtime.discard("render")
                functions.pop("render", None)
            assert properties | set(functions) == runtime, name
            for member in properties:
                value = vars(cls)[member]
                if not isinstance(value, property) or (value.fset is not None) != (member in setters):
                    problems.append(f"{name}.{member}: a property {'with' if value.fset else 'without'} a setter")
            for member, function in functions.items():
                compare(f"{name}.{member}", getattr(cls, member), function, problems)
    assert not problems, problems


@pytest.mark.skipif(importlib.util.find_spec("mypy") is None, reason="mypy is not installed (python3-mypy)")
def test_mypy_accepts_a_script_against_the_stubs(tmp_path):
    script = tmp_path / "uses_gpsurf.py"
    script.write_text(textwrap.dedent("""
        import numpy as np
        import gpsurf

        mesh: gpsurf.Mesh = gpsurf.sample("cone")
        surface = gpsurf.Surface(mesh, scheme="loop")
        positions, du, dv, normals = surface.evaluate(np.arange(3), 0.25, 0.25)
        points, point_normals, triangles = surface.tessellate(4)
        fitted = gpsurf.fit(mesh, points, iterations=1, progress=lambda f: None)
        refitted, report = gpsurf.fit(fitted, points, iterations=1, tolerance=0.1, time=5.0, report=True)
        stop: str = report["stop"]
        d: np.ndarray = gpsurf.distance(points, fitted)
        mesh.positions = mesh.positions + 1.0
        gpsurf.read("x.ply", bias=0.1).write("y.ply")
    """))
    bad = tmp_path / "misuses_gpsurf.py"
    bad.write_text("import gpsurf\ngpsurf.tessellate(gpsurf.sample('cone'), level='8')\n")
    env = dict(os.environ)
    if os.path.basename(os.path.dirname(PACKAGE_DIR)) not in ("site-packages", "dist-packages"):
        env["MYPYPATH"] = os.path.dirname(PACKAGE_DIR)  # the build's package; an installed one mypy finds itself
    ok = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", str(script)], capture_output=True,
                        text=True, env=env, cwd=tmp_path)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    refused = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", str(bad)], capture_output=True,
                             text=True, env=env, cwd=tmp_path)
    assert refused.returncode == 1 and "level" in refused.stdout, refused.stdout


def test_inspect_signature_gives_the_stubs_parameters():
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef) and hasattr(gpsurf, node.name):
            names = list(inspect.signature(getattr(gpsurf, node.name)).parameters)
            assert names == [n for n, _ in stub_parameters(node)], node.name
        elif isinstance(node, ast.ClassDef) and node.name in ("Mesh", "Surface"):
            cls = getattr(gpsurf, node.name)
            for method in node.body:
                if isinstance(method, ast.FunctionDef) and not method.decorator_list and hasattr(cls, method.name) \
                        and not method.name.startswith("__"):
                    names = [n for n in inspect.signature(getattr(cls, method.name)).parameters if n != "self"]
                    assert names == [n for n, _ in stub_parameters(method)], f"{node.name}.{method.name}"
    assert list(inspect.signature(gpsurf.Mesh).parameters) == ["positions", "faces", "covariances"]
    assert inspect.signature(gpsurf.read).parameters["bias"].default == 0.05
