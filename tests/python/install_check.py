#!/usr/bin/env python3
"""The README's Python lines on a copy of the sources: a virtual environment that sees Debian's packages,
`pip install --no-build-isolation ./python` in it (offline), and the README's example run there from
another folder. The README's example must be examples/python/first_break.py.

Usage: install_check.py SOURCE WORK
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

source, work = Path(sys.argv[1]), Path(sys.argv[2])
readme = (source / "README.md").read_text()
example = (source / "examples" / "python" / "first_break.py").read_text()
blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
if example not in blocks:
    sys.exit("README.md: no ```python block equal to examples/python/first_break.py")
install = re.search(r"```sh\n((?:[^`]*\n)*?)```\n(?=(?:[^`]|`[^`])*```python\n)", readme)
lines = install[1] if install else ""
for expected in ("/usr/bin/python3 -m venv --system-site-packages", "pip install --no-build-isolation ./python"):
    if expected not in lines:
        sys.exit(f"README.md: the Python section's install lines do not say '{expected}'")

if work.exists():
    shutil.rmtree(work)
copy = work / "source"
for name in ("python", "runtime", "simulation", "io", "generated"):
    shutil.copytree(source / name, copy / name, ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__"))
shutil.copy(source / "CMakeLists.txt", copy)
environment = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
environment["PIP_NO_INDEX"] = "1"  # offline: Debian's setuptools, wheel and numpy serve
venv = work / "venv"
subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", str(venv)], check=True)
subprocess.run([str(venv / "bin" / "pip"), "install", "--no-build-isolation", "./python"], cwd=copy, check=True,
               env=environment)
shutil.rmtree(copy)  # the example must run from the installed package alone
script = work / "first_break.py"
script.write_text(example)
done = subprocess.run([str(venv / "bin" / "python"), str(script)], cwd=work, env=environment, capture_output=True,
                      text=True)
print(done.stdout, done.stderr)
if done.returncode != 0 or not re.search(r"^\d+ events, at rest after [0-9.]+ s$", done.stdout, re.M):
    sys.exit("the README's example did not run as shown")
if "object balls pocketed per break: " not in done.stdout:
    sys.exit("the README's example printed no batch result")
