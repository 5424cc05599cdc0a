# SPDX-License-Identifier: Apache-2.0
"""The Python package's version (python/pyproject.toml, which pip reads) is the project's, the
one CMakeLists.txt's project(VERSION) gives the library and 'tirenv --version'."""
import os
import tomllib

from conftest import run_cli


def test_pyproject_version_is_the_projects(cli, source_dir):
    with open(os.path.join(source_dir, "python", "pyproject.toml"), "rb") as f:
        version = tomllib.load(f)["project"]["version"]
    rc, out, err = run_cli(cli, "--version")
    assert rc == 0, err
    assert out.split() == ["tirenv", version]
