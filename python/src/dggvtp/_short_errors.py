"""Short TypeErrors for the extension's functions.

pybind11 answers arguments it cannot convert with a TypeError that lists every signature and the
repr of every argument: the whole V and F arrays, 700 characters and more for a swapped pair of
arguments. The functions are wrapped here to say in one line which argument is wrong and why.
"""
import ast
import functools
import inspect
import operator
from typing import Any, Callable, Dict, Optional, Tuple

import numpy as np

_PYBIND11_MESSAGES = ("incompatible function arguments", "incompatible constructor arguments")


def _signature(function: Callable[..., Any]) -> Optional[inspect.Signature]:
    """The signature on the first line of a pybind11 docstring (names, kinds, defaults, and each
    annotation's text), or None if it does not read."""
    first = (function.__doc__ or "").split("\n")[0]
    header = first.split(" -> ")[0]
    try:
        args = ast.parse(f"def {header}: ...").body[0].args  # type: ignore[attr-defined]
    except SyntaxError:
        return None
    parameters = []
    positional = args.posonlyargs + args.args
    defaults = [inspect.Parameter.empty] * (len(positional) - len(args.defaults)) + list(args.defaults)
    for a, d in zip(positional, defaults):
        parameters.append(inspect.Parameter(a.arg, inspect.Parameter.POSITIONAL_OR_KEYWORD, default=d,
                                            annotation=ast.unparse(a.annotation) if a.annotation else ""))
    for a, d in zip(args.kwonlyargs, args.kw_defaults):
        parameters.append(inspect.Parameter(a.arg, inspect.Parameter.KEYWORD_ONLY,
                                            default=inspect.Parameter.empty if d is None else d,
                                            annotation=ast.unparse(a.annotation) if a.annotation else ""))
    return inspect.Signature(parameters)


def _converts(kind: str, value: Any) -> bool:
    """whether pybind11 takes `value` for an argument of the simple type `kind`"""
    if kind == "float":
        return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))
    if kind == "int":
        try:
            operator.index(value)
        except TypeError:
            return False
        return not isinstance(value, (bool, np.bool_))
    if kind == "bool":
        return isinstance(value, (bool, np.bool_))
    if kind == "str":
        return isinstance(value, str)
    return True


def _what_is_wrong(name: str, signature: Optional[inspect.Signature], args: Tuple[Any, ...],
                   kwargs: Dict[str, Any]) -> str:
    where = f"(see help(dggvtp.{name}))"
    if signature is None:
        return f"{name}(): arguments of the wrong kind {where}"
    try:
        bound = signature.bind(*args, **kwargs)
    except TypeError as e:
        return f"{name}(): {e} {where}"
    for parameter, value in bound.arguments.items():
        kind = signature.parameters[parameter].annotation
        if not _converts(kind, value):
            shown = repr(value) if len(repr(value)) <= 40 else type(value).__name__
            return f"{name}(): {parameter} must be {'an' if kind == 'int' else 'a'} {kind}, not {shown} {where}"
    return f"{name}(): arguments of the wrong kind {where}"


def short_type_errors(function: Callable[..., Any], name: str) -> Callable[..., Any]:
    """`function` raising a TypeError of one line where pybind11 would list its arguments"""
    signature = _signature(function)

    @functools.wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return function(*args, **kwargs)
        except TypeError as e:
            if not any(m in str(e) for m in _PYBIND11_MESSAGES):
                raise
            raise TypeError(_what_is_wrong(name, signature, args, kwargs)) from None

    return wrapper
