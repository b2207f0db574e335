"""pip install of the Python module `foresight`: the library's sources and the binding compiled
by setuptools with pybind11's helpers (no CMake needed, no registry reached when installed with
`pip install --no-build-isolation --no-index .` from this folder).

Needs a C++20 compiler, GLM's headers (found in the usual include folders, or set
GLM_INCLUDE_DIR), pybind11 and NumPy. Compiles with NPY_NUM_BUILD_JOBS parallel jobs (default 2),
optimised with FORESIGHT_OPTIMIZE (default -O2).
The foresight sources are taken from the repository this folder is in (../../src, ../../include).
"""

import os

from pybind11.setup_helpers import ParallelCompile, Pybind11Extension, build_ext
from setuptools import setup

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SOURCE_DIR = os.path.join(ROOT, "src")


def library_sources():
    """The core library's sources: src/*.cpp except the C API's."""
    names = sorted(name for name in os.listdir(SOURCE_DIR) if name.endswith(".cpp") and name != "foresight_c.cpp")
    return [os.path.join(SOURCE_DIR, name) for name in names]


def version():
    with open(os.path.join(ROOT, "include", "foresight", "config.h"), encoding="utf-8") as header:
        for line in header:
            if line.startswith("#define FORESIGHT_VERSION_STRING"):
                return line.split('"')[1]
    raise RuntimeError("FORESIGHT_VERSION_STRING not found in include/foresight/config.h")


include_dirs = [os.path.join(ROOT, "include")]
if os.environ.get("GLM_INCLUDE_DIR"):
    include_dirs.append(os.environ["GLM_INCLUDE_DIR"])

extension = Pybind11Extension(
    "foresight",
    [os.path.join(HERE, "src", "foresight_python.cpp")] + library_sources(),
    include_dirs=include_dirs,
    cxx_std=20,
    # As the CMake build: no fused multiply-add contraction (determinism; the same numbers as the
    # C++ library). -fno-trapping-math (CMake: src/replication.cpp only) changes no value.
    # FORESIGHT_OPTIMIZE (default -O2) lets the install test compile faster (-O1); the numbers do
    # not depend on it (no contraction, no fast-math at any level).
    extra_compile_args=[os.environ.get("FORESIGHT_OPTIMIZE", "-O2"), "-ffp-contract=off", "-fno-trapping-math"],
)

ParallelCompile("NPY_NUM_BUILD_JOBS", default=2).install()

setup(
    name="foresight",
    version=version(),
    description="Movement prediction for games: characters, projectiles, vehicles, dead reckoning",
    ext_modules=[extension],
    cmdclass={"build_ext": build_ext},
    install_requires=["numpy"],
    zip_safe=False,
    python_requires=">=3.8",
)
