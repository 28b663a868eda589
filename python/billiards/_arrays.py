"""Argument checks and broadcasting shared by the array calls.

Every call runs in one dtype, float64 or float32, taken from its ndarray arguments: arrays of the two
float dtypes are never mixed (TypeError), and no array is converted to another dtype. Python numbers
and lists have no dtype of their own and are converted to the call's.
"""

from __future__ import annotations

import numbers

import numpy as np

FLOATS = (np.dtype(np.float64), np.dtype(np.float32))


def describe(value) -> str:
    """A short description of a value for an error message."""
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape} and dtype {value.dtype}"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def call_dtype(function: str, arguments: dict) -> np.dtype:
    """The dtype a call runs in: that of its ndarray (and numpy scalar) arguments, float64 where none."""
    found = {}
    for name, value in arguments.items():
        if isinstance(value, (np.ndarray, np.generic)):
            if value.dtype not in FLOATS:
                raise TypeError(f"{function}: {name} has dtype {value.dtype}, expected float64 or float32 "
                                f"(convert it with .astype(numpy.float64) if that is what you mean)")
            found[name] = value.dtype
        elif not _plain(value):
            raise TypeError(f"{function}: {name} is {describe(value)}, expected a number, a sequence of "
                            f"numbers or a float64 or float32 array")
    kinds = set(found.values())
    if len(kinds) > 1:
        listed = ", ".join(f"{name} {dtype}" for name, dtype in found.items())
        raise TypeError(f"{function}: the arrays' dtypes differ ({listed}); expected one of float64 or float32")
    return kinds.pop() if kinds else np.dtype(np.float64)


def _plain(value) -> bool:
    if isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, numbers.Real):
        return True
    if isinstance(value, (list, tuple)):
        return all(_plain(v) for v in value)
    return False


def as_array(function: str, name: str, value, dtype: np.dtype, vector: int | tuple = 0) -> np.ndarray:
    """`value` as an array of `dtype`; `vector` > 0 (or a tuple of sizes): its last axis one of them."""
    array = np.asarray(value, dtype=dtype) if not isinstance(value, np.ndarray) else value
    sizes = vector if isinstance(vector, tuple) else ((vector,) if vector else ())
    if sizes and (array.ndim == 0 or array.shape[-1] not in sizes):
        expected = " or ".join(str(s) for s in sizes)
        raise ValueError(f"{function}: {name} has shape {array.shape}, expected a last axis of {expected} "
                         f"components")
    return array


def broadcast(function: str, scalars: dict, vectors: dict) -> tuple:
    """Broadcasts the arguments: `scalars` (name → array) over the cases' shape, `vectors` (name →
    array whose last axis is the vector) over the same shape. Returns (shape, flat scalars, rows of the
    vectors), each C-contiguous."""
    shapes = [a.shape for a in scalars.values()] + [a.shape[:-1] for a in vectors.values()]
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError:
        listed = ", ".join(f"{name} {a.shape}" for name, a in list(scalars.items()) + list(vectors.items()))
        raise ValueError(f"{function}: the arguments' shapes do not broadcast together ({listed}; a vector's "
                         f"last axis is its components)") from None
    count = int(np.prod(shape, dtype=np.int64))
    flat = {name: np.ascontiguousarray(np.broadcast_to(a, shape)).reshape(count) for name, a in scalars.items()}
    rows = {name: np.ascontiguousarray(np.broadcast_to(a, shape + a.shape[-1:])).reshape(count, a.shape[-1])
            for name, a in vectors.items()}
    return shape, flat, rows
