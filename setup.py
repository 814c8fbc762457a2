"""Builds the extension sgmp._sgmp with the project's CMake build and packages it beside the
pure-Python sgmp/python/package/sgmp/ (pyproject.toml names the backend).

The CMake build tree is a temporary one under setuptools' build directory, configured with
the interpreter that runs pip; SGMP_CMAKE_BUILD_DIR names an existing build tree to build
the target in instead (it must have been configured for the same Python). SGMP_CMAKE_JOBS
sets the parallel jobs (default: the CPUs this process may use).
"""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, extension):
        build_dir = os.environ.get("SGMP_CMAKE_BUILD_DIR")
        if build_dir:
            build_dir = pathlib.Path(build_dir).resolve()
        else:
            build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
            build_dir.mkdir(parents=True, exist_ok=True)
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir),
                            "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        jobs = os.environ.get("SGMP_CMAKE_JOBS", str(len(os.sched_getaffinity(0))))
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "sgmp_python",
                        "--parallel", jobs], check=True)
        built = sorted((build_dir / "sgmp" / "python" / "sgmp").glob("_sgmp*.so"))
        if not built:
            raise RuntimeError(f"no _sgmp extension under {build_dir}/sgmp/python/sgmp")
        target = pathlib.Path(self.get_ext_fullpath(extension.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


setup(
    packages=["sgmp"],
    package_dir={"sgmp": "sgmp/python/package/sgmp"},
    package_data={"sgmp": ["py.typed", "_sgmp.pyi"]},
    ext_modules=[Extension("sgmp._sgmp", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
