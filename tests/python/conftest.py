"""Fixtures of the Python package's tests: the C++ programs the bindings are compared with."""

import os
import subprocess

import numpy as np
import pytest


def _program(variable: str) -> str:
    path = os.environ.get(variable, "")
    if not path or not os.path.exists(path):
        pytest.skip(f"{variable} does not name a built program (the tests run under ctest set it)")
    return path


@pytest.fixture(scope="session")
def runtime_reference():
    """Runs the C++ checked call `name` over `cases` (rows of numbers): one list of results a case, or
    None where the C++ call rejects it."""
    program = _program("BILLIARDS_RUNTIME_REFERENCE")

    def run(name: str, cases: np.ndarray, scalar: str = "double"):
        lines = [f"{name} {scalar}"] + [" ".join(float(x).hex() for x in row) for row in np.asarray(cases)]
        out = subprocess.run([program], input="\n".join(lines) + "\n", capture_output=True, text=True, check=True)
        return [None if line == "rejected" else [float.fromhex(w) for w in line.split()]
                for line in out.stdout.splitlines()]

    return run


@pytest.fixture(scope="session")
def shot_program():
    """The path of billiards-shot."""
    return _program("BILLIARDS_SHOT_PROGRAM")


@pytest.fixture
def rng():
    return np.random.default_rng(20261206)


@pytest.fixture(scope="session")
def gas_program():
    """The path of billiards-gas."""
    return _program("BILLIARDS_GAS_PROGRAM")
