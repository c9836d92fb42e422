"""Builds the Python module with CMake (python/CMakeLists.txt) for the interpreter that runs pip, and
puts it and its type stubs where setuptools packs them. pyproject.toml has the rest."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / 'cmake'
        subprocess.check_call(['cmake', '-S', str(ROOT), '-B', str(build), '-DCMAKE_BUILD_TYPE=Release',
                               '-DCOLLIDE2D_BUILD_TOOLS=OFF', '-DCOLLIDE2D_BUILD_PYTHON=ON',
                               f'-DCOLLIDE2D_PYTHON={sys.executable}'])
        subprocess.check_call(['cmake', '--build', str(build), '--target', 'collide2d_python', '-j',
                               str(os.cpu_count() or 1)])
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(build / 'python' / target.name, target)
        shutil.copy(build / 'python' / 'collide2d.pyi', target.parent / 'collide2d.pyi')


setup(ext_modules=[Extension("collide2d", sources=[])], cmdclass={"build_ext": CMakeBuild}, packages=[], py_modules=[])
