# SPDX-License-Identifier: Apache-2.0
# What the tests need from the build (set by CTest; see python/CMakeLists.txt): the CLI, the
# source tree and the bit-for-bit reference program.
import os
import subprocess

import pytest


def _env(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run the tests through CTest (make test)")
    return value


@pytest.fixture(scope="session")
def cli():
    return _env("TIRENV_CLI")


@pytest.fixture(scope="session")
def source_dir():
    return _env("TIRENV_SOURCE_DIR")


@pytest.fixture(scope="session")
def envelope_ref():
    return _env("TIRENV_PYTHON_REF")


@pytest.fixture(scope="session")
def network_file(cli, source_dir, tmp_path_factory):
    """A small network trained by the CLI on the embedded data set (one restart, 20 epochs:
    a tenth of a second); its quality does not matter, only that both sides read the same."""
    path = tmp_path_factory.mktemp("nn") / "nn.json"
    subprocess.run([cli, "train", "--data", os.path.join(source_dir, "data", "dataset"),
                    "--restarts", "1", "--epochs", "20", "-o", str(path)], check=True,
                   capture_output=True)
    return path


def run_cli(cli, *args, cwd=None):
    """Runs the CLI; returns (exit status, stdout, stderr)."""
    r = subprocess.run([cli, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    return r.returncode, r.stdout, r.stderr
