"""Gaussian-Product Subdivision surfaces: covariance meshes, exact subdivision and evaluation, fitting,
distances and off-screen rendering, with numpy arrays in and out.

Arrays handed out are read-only copies; assign whole arrays to change a Mesh. Every call that
computes runs without the GIL (other Python threads run meanwhile) and stops on Ctrl-C. Errors
raise gpsurf.Error with the command line's one-line message, ValueError, TypeError or IndexError
for arguments. help(gpsurf.Mesh), help(gpsurf.Surface) and the stubs (__init__.pyi) give the API.
"""
import ast as _ast
import functools as _functools
import inspect as _inspect

try:
    import numpy as _numpy  # noqa: F401  (the extension's arrays: without it, its import fails unexplained)
except ImportError as _error:
    raise ImportError("gpsurf needs numpy in this Python (" + str(_error) + ")") from None

from ._gpsurf import *  # noqa: F401,F403
from ._gpsurf import __version__  # noqa: F401
from . import _gpsurf

# Named by the package, as Python users import them (pickle, repr, help).
for _name in dir(_gpsurf):
    if not _name.startswith("_"):
        try:
            getattr(_gpsurf, _name).__module__ = __name__
        except (AttributeError, TypeError):
            pass
del _name


def _split_parameters(text):
    """The parameters of a signature's text, split at commas outside brackets and quotes."""
    parts, depth, quote, current = [], 0, None, ""
    for c in text:
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(current.strip())
            current = ""
            continue
        current += c
    return [p for p in (*parts, current.strip()) if p]


def _signature(function):
    """The inspect.Signature of a compiled function, from the first line of its docstring (as
    pybind11 writes it: `name(a: type, b: type = default) -> type`)."""
    line = function.__doc__.splitlines()[0]
    parameters, kind = [], _inspect.Parameter.POSITIONAL_OR_KEYWORD
    for part in _split_parameters(line[line.index("(") + 1:line.rindex(") ->")]):
        if part == "*":  # the keyword-only parameters follow
            kind = _inspect.Parameter.KEYWORD_ONLY
            continue
        name, _, rest = part.partition(":")
        annotation, _, default = rest.partition(" = ")
        try:
            value = _ast.literal_eval(default) if default else _inspect.Parameter.empty
        except ValueError:
            value = default
        parameters.append(_inspect.Parameter(name.strip(), kind, default=value, annotation=annotation.strip()))
    return _inspect.Signature(parameters)


def _shown_type(annotation):
    """A parameter's type as a user reads it: `int or None`, `gpsurf.Mesh`."""
    if annotation.startswith("Optional[") and annotation.endswith("]"):
        return _shown_type(annotation[len("Optional["):-1]) + " or None"
    return annotation.replace("gpsurf._gpsurf.", "gpsurf.")


def _takes(annotation, value):
    """Whether a value can be what a parameter of this type takes; True where the type is not one
    of the plain ones told apart here (arrays, sequences, callables)."""
    if annotation.startswith("Optional[") and annotation.endswith("]"):
        return value is None or _takes(annotation[len("Optional["):-1], value)
    if annotation == "str":
        return isinstance(value, str)
    if annotation == "bool":
        return isinstance(value, bool) or type(value).__name__ == "bool_"
    if annotation == "int":
        return not isinstance(value, (str, bytes, float)) and hasattr(value, "__index__")
    if annotation == "float":
        return not isinstance(value, (str, bytes)) and (hasattr(value, "__float__") or hasattr(value, "__index__"))
    if annotation.startswith("gpsurf._gpsurf."):
        cls = getattr(_gpsurf, annotation.rpartition(".")[2], None)
        return not isinstance(cls, type) or isinstance(value, cls)
    return True


def _refusal(name, signature, args, kwargs):
    """The TypeError for a call whose arguments pybind11 found incompatible, in Python's words:
    the argument that is not of its parameter's type, or the name or count that does not fit."""
    try:
        bound = signature.bind(*args, **kwargs)
    except TypeError as error:
        return TypeError(f"{name}(): {error}")
    for parameter, value in bound.arguments.items():
        annotation = signature.parameters[parameter].annotation
        if isinstance(annotation, str) and not _takes(annotation, value):
            return TypeError(f"{name}(): {parameter} must be {_shown_type(annotation)}, not {type(value).__name__}")
    shown = ", ".join(f"{p.name}: {_shown_type(p.annotation)}" for p in signature.parameters.values())
    return TypeError(f"{name}(): the arguments do not fit ({shown})")


def _with_signature(function, name=None):
    """`function` as a Python function that inspect.signature and help() read, whose wrong arguments
    are named as Python names them under `name` (pybind11 lists every overload and the arguments' reprs)."""
    signature = _signature(function)
    name = name or function.__name__

    @_functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            if "incompatible function arguments" not in str(error) and "incompatible constructor" not in str(error):
                raise
            raise _refusal(name, signature, args, kwargs) from None

    call.__signature__ = signature.replace(
        parameters=[p.replace(annotation=_inspect.Parameter.empty) for p in signature.parameters.values()])
    return call


def _initialising_once(init):
    """A compiled class's `init` refusing an instance initialised already, which pybind11 would leave
    as it was without a word."""

    @_functools.wraps(init)
    def call(self, *args, **kwargs):
        if getattr(self, "_initialised", False):
            raise TypeError(f"{type(self).__name__}: already initialised; make a new one")
        return init(self, *args, **kwargs)

    return call


_WRAPPED_SPECIAL = ("__init__", "__copy__", "__deepcopy__")


def _give_signatures():
    names = globals()
    for name, value in list(names.items()):
        if name.startswith("_") or not callable(value):
            continue
        if isinstance(value, type):
            if not issubclass(value, BaseException):
                for member, method in list(vars(value).items()):
                    if callable(method) and (not member.startswith("_") or member in _WRAPPED_SPECIAL):
                        if member == "__init__":
                            method = _initialising_once(method)
                        shown = value.__name__ if member == "__init__" else f"{value.__name__}.{member}"
                        setattr(value, member, _with_signature(method, shown))
        else:
            names[name] = _with_signature(value)


_give_signatures()


def _mesh_from_state(state):
    """A Mesh from its pickled state: what pickle calls to load one (Mesh.__reduce__ names it)."""
    return _gpsurf._mesh_from_state(state)
