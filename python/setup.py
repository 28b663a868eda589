"""Builds billiards._billiards, the compiled half of the package, from the project's headers.

The version is the CMake project's (../CMakeLists.txt); the headers are the runtime's, the simulation
library's, the io library's and the checked-in generated kernels, beside this folder in the source tree.
"""

import os
import re
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

here = Path(__file__).resolve().parent
root = here.parent
version = re.search(r"project\(\s*billiards\s+VERSION\s+([0-9.]+)", (root / "CMakeLists.txt").read_text()).group(1)


def version_header(folder: Path) -> Path:
    """billiards/version.hpp as CMake configures it, written under `folder`."""
    major, minor, patch = version.split(".")
    target = folder / "billiards" / "version.hpp"
    target.parent.mkdir(parents=True, exist_ok=True)
    text = (root / "runtime" / "version.hpp.in").read_text()
    for name, value in (("PROJECT_VERSION_MAJOR", major), ("PROJECT_VERSION_MINOR", minor),
                        ("PROJECT_VERSION_PATCH", patch), ("PROJECT_VERSION", version)):
        text = text.replace(f"@{name}@", value)
    if not target.exists() or target.read_text() != text:
        target.write_text(text)
    return folder


def compile_in_parallel(compiler, jobs: int) -> None:
    """Makes `compiler` compile an extension's sources `jobs` at a time (setuptools compiles one source
    after another; each of ours takes the better part of a minute). The steps are distutils' own
    `CCompiler.compile`, with the loop over the objects run on a thread pool."""
    def compile(sources, output_dir=None, macros=None, include_dirs=None, debug=0, extra_preargs=None,
                extra_postargs=None, depends=None):
        macros, objects, extra_postargs, pp_opts, build = compiler._setup_compile(
            output_dir, macros, include_dirs, sources, depends, extra_postargs)
        cc_args = compiler._get_cc_args(pp_opts, debug, extra_preargs)

        def one(obj):
            source, ext = build[obj]
            compiler._compile(obj, source, ext, cc_args, extra_postargs, pp_opts)

        with ThreadPoolExecutor(max(1, min(jobs, len(objects)))) as pool:
            list(pool.map(one, objects))  # list(): the first failure is raised here
        return objects

    compiler.compile = compile


# The sources compiled together, as CMake's unity groups do (python/CMakeLists.txt): the templates they
# share (the shot's engine, the games' rules) compiled once a group, not once a file.
unity_groups = {"shot": ("engines.cpp", "batch.cpp", "games.cpp"),
                "rest": ("table_gas.cpp", "files.cpp", "runtime.cpp", "module.cpp")}


def unity_sources(folder: Path) -> list:
    """One source a group of `unity_groups`, written under `folder` (rewritten only where it changed),
    each including its group's files by name (src/ is on the include path: no path is quoted)."""
    sources = []
    for name, files in unity_groups.items():
        target = folder / f"unity_{name}.cpp"
        text = "".join(f'#include "{file}"\n' for file in files)
        target.parent.mkdir(parents=True, exist_ok=True)
        if not target.exists() or target.read_text() != text:
            target.write_text(text)
        sources.append(str(target))
    return sources


class BuildWithVersion(build_ext):
    def build_extensions(self):
        generated = version_header(Path(self.build_temp) / "version")
        for extension in self.extensions:
            extension.include_dirs += [str(generated), str(here / "src")]
            extension.sources = unity_sources(Path(self.build_temp) / "unity")
            extension.depends = [str(here / source) for source in sources]  # src/…, as listed below
        compile_in_parallel(self.compiler, len(os.sched_getaffinity(0)))
        super().build_extensions()


def pybind11_include() -> list:
    try:
        import pybind11  # Debian's python3-pybind11, where installed
        return [pybind11.get_include()]
    except ImportError:
        return []  # pybind11-dev's headers are in /usr/include


if not (root / "runtime" / "include").is_dir():
    sys.exit("billiards: build the package from the project's source tree (pip install ./python): "
             f"{root / 'runtime' / 'include'} is missing")

sources = [str(Path("src") / file) for files in unity_groups.values() for file in files]
extension = Extension(
    "billiards._billiards",
    sources=sources,
    include_dirs=[str(root / "runtime" / "include"), str(root / "simulation" / "include"), str(root / "io" / "include"),
                  str(root / "generated"), "/usr/include/eigen3"] + pybind11_include(),
    language="c++",
    # Portable code, the same bits as the project's programs (no -march=native: its fused multiply-adds
    # round differently); no debug information (Python's own flags ask for it: it makes the compiler
    # slower and the module larger).
    extra_compile_args=["-std=c++20", "-O3", "-fvisibility=hidden", "-DNDEBUG", "-g0"],
    extra_link_args=["-pthread"],
)

os.chdir(here)
setup(version=version, ext_modules=[extension], cmdclass={"build_ext": BuildWithVersion})
