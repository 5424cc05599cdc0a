# SPDX-License-Identifier: Apache-2.0
"""The package behaves as Python packages do: a __version__, exceptions that are
the builtin ones as well as TirenvError, scalars in and scalars out, a Tire whose keys read
like a dict's."""
import errno
import os

import numpy as np
import pytest

import tirenv
from conftest import run_cli


def test_version_is_the_clis(cli):
    rc, out, err = run_cli(cli, "--version")
    assert rc == 0, err
    assert out.split() == ["tirenv", tirenv.__version__]


def test_a_missing_file_is_file_not_found(tmp_path):
    missing = tmp_path / "no-such-tire.tir"
    with pytest.raises(FileNotFoundError) as e:
        tirenv.Tire(missing)
    assert isinstance(e.value, tirenv.TirenvError) and isinstance(e.value, OSError)
    assert e.value.errno == errno.ENOENT and e.value.filename == str(missing)
    assert str(missing) in str(e.value)  # the library's line, not only "[Errno 2]"
    with pytest.raises(FileNotFoundError):
        tirenv.Profile.read(tmp_path / "no-such-road.csv")


def test_an_unreadable_file_is_an_os_error_not_file_not_found(tmp_path):
    # A directory exists but is no road: the library cannot read it (EIO).
    with pytest.raises(OSError) as e:
        tirenv.Profile.read(tmp_path)
    assert isinstance(e.value, tirenv.TirenvError)
    assert not isinstance(e.value, FileNotFoundError)


def test_bad_values_and_contents_are_value_errors(tmp_path):
    with pytest.raises(ValueError) as e:
        tirenv.Tire(set={"RADIAL_STIFFNESS": -1})
    assert isinstance(e.value, tirenv.TirenvError) and e.value.field
    bad = tmp_path / "bad.csv"
    bad.write_text("x_m,z_m\n0,0\n1,zero\n")
    with pytest.raises(ValueError) as e:
        tirenv.Profile.read(bad)
    assert e.value.line == 3 and isinstance(e.value, tirenv.TirenvError)
    with pytest.raises(ValueError):
        tirenv.Model("sprongs")
    with pytest.raises(tirenv.TirenvError):  # the Python layer's refusals are both too
        tirenv.Profile.cleat(0.1, 0.1).height([np.nan])
    with pytest.raises(ValueError):
        tirenv.Profile.cleat(0.1, 0.1).height([np.nan])


def test_scalars_in_scalars_out():
    p = tirenv.Profile.cleat(0.10, 0.10)
    h = p.height(0.0237)
    assert isinstance(h, float) and h == 0.1
    assert p.height(np.float64(0.4)) == 0.0 and isinstance(p.height(np.float64(0.4)), float)
    arr = p.height([0.0237, 0.4])
    assert isinstance(arr, np.ndarray) and arr.shape == (2,) and list(arr) == [0.1, 0.0]
    assert p.height([0.0237]).shape == (1,)  # a list of one stays an array
    m = tirenv.Model("rigid")
    m.set(p, 7500)
    one = m.envelope(-0.0713)
    assert one.shape == () and one["h_m"] == m.envelope([-0.0713])["h_m"][0]


def test_tire_keys_read_like_a_dict(tmp_path):
    t = tirenv.Tire(set={"RADIAL_STIFFNESS": 1.6123e6, "MAX_ITERATIONS": 37,
                         "METHOD": "brent"})
    assert t["RADIAL_STIFFNESS"] == 1.6123e6 and isinstance(t["RADIAL_STIFFNESS"], float)
    assert t["MAX_ITERATIONS"] == 37 and isinstance(t["MAX_ITERATIONS"], int)
    assert t["METHOD"] == "brent"
    assert t["UNLOADED_RADIUS"] == t.R0
    assert "RADIAL_STIFFNESS" in t and "Q_FZ3" not in t and 3 not in t
    assert t["FNOMIN"] == 17900 and "Q_FZ2" in t  # the cam's vertical law (models.md 7.3)
    assert t["Q_FZ1"] == 0 and t["PFZ1"] == 0  # none: Q_FZ1 from VERTICAL_STIFFNESS
    with pytest.raises(KeyError):
        t["Q_FZ3"]
    keys = list(t)
    assert len(keys) == len(t) and len(set(keys)) == len(keys)
    assert "UNLOADED_RADIUS" in keys and "NODE_ANGLE" in keys and "METHOD" in keys
    # Every key reads back through a file the same: what the writer writes is what get gives.
    path = tmp_path / "t.tir"
    t.write(path)
    back = tirenv.Tire(path)
    assert dict(back.items()) == dict(t.items())
    # and the values are those a file sets
    other = tirenv.Tire(set={"TREAD_STIFFNESS": 2.345e6})
    assert other["TREAD_STIFFNESS"] == 2.345e6 and t["TREAD_STIFFNESS"] != 2.345e6
    with pytest.raises(TypeError):
        t["RADIAL_STIFFNESS"] = 1.0  # read-only
    assert os.fspath(path)  # the file was written


def test_cam_takes_own_q_fz1_and_pfz1():
    """The cam's vertical law is MF-Tyre's (docs/models.md 7.3) through the same C: with
    Q_FZ1 12.3 and PFZ1 0.83 at INFLPRES 1.5 bar on NOMPRES 1.2 bar, the deflection at FNOMIN
    is the closed-form root of f*(Q_FZ1*s + Q_FZ2*s^2) = 1, f = 1.2075, to round-off."""
    t = tirenv.Tire(set={"Q_FZ1": 12.3, "PFZ1": 0.83, "INFLPRES": 1.5e5, "NOMPRES": 1.2e5})
    q1, q2, f, r0 = 12.3, t["Q_FZ2"], 1 + 0.83 * 0.25, t.R0
    s = (-q1 + (q1 * q1 + 4 * q2 / f) ** 0.5) / (2 * q2)
    rho = tirenv.Model("cam", tire=t).flat(t["FNOMIN"]).deflection
    assert abs(rho / (r0 * s) - 1) < 1e-12
    plain = tirenv.Model("cam", tire=tirenv.Tire()).flat(t["FNOMIN"]).deflection
    assert abs(rho / plain - 1) > 0.1  # neither is ignored
