# SPDX-License-Identifier: Apache-2.0
# pip install --no-build-isolation ./python, against an installed libtirenv (python/README.md).
from setuptools import setup

setup(cffi_modules=["tirenv_build.py:ffibuilder"])
