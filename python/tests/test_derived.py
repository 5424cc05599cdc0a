# SPDX-License-Identifier: Apache-2.0
"""An MF-Tyre file without tirenv's sections gives Python's Tire the models the CLI derives
(tirenv_tir_derive, docs/models.md section 14.2): the same C function, so the same doubles."""
import os
import threading
import warnings

import pytest

import tirenv
from conftest import run_cli


def _sample(source_dir, name):
    return os.path.join(source_dir, "tests", "data", "samples", "tir", name)


@pytest.mark.parametrize("model", ["springs", "ring"])
def test_foreign_tir_gives_the_cli_models(cli, source_dir, model):
    path = _sample(source_dir, "mf_185_80R14.tir")
    with pytest.warns(UserWarning, match="derived RADIAL_STIFFNESS") as w:
        tire = tirenv.Tire(path)
    assert tire.derived == {"springs", "ring", "cam"}
    rc, out, err = run_cli(cli, "flat", "--csv", "--model", model, "--tire", path)
    assert rc == 0, err
    # The same note on the CLI's standard error as in the warning.
    assert f"tirenv: {path}: {tire.derived_note}" in err
    assert str(w[0].message) == f"{path}: {tire.derived_note}"
    rows = [line.split(",") for line in out.splitlines()[1:]]
    assert [float(r[0]) for r in rows] == [1900, 2850, 3800, 4750, 5700]  # 0.5-1.5 FNOMIN
    m = tirenv.Model(model, tire)
    for r in rows:
        f = m.flat(float(r[0]))
        # The CLI prints 9 significant digits: the same doubles print the same text.
        assert [f"{v:.9g}" for v in (f.z_flat, f.deflection, f.contact_length)] == r[1:4]
    # The derived keys read back as the CLI's: the cam's contact law identified on the ring.
    assert tire["Q_RA1"] != tirenv.Tire()["Q_RA1"]
    assert f"Q_RA1 = {tire['Q_RA1']:.4g}" in err


def test_foreign_tir_without_fnomin_refuses_the_springs_model(tmp_path, source_dir):
    path = tmp_path / "nofnomin.tir"
    path.write_text("[DIMENSION]\nUNLOADED_RADIUS = 0.376\n[VERTICAL]\n"
                    "VERTICAL_STIFFNESS = 1.75e5\n")
    with pytest.warns(UserWarning, match="no FNOMIN"):
        tire = tirenv.Tire(path)
    assert tire.derived == frozenset()
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Model("springs", tire)
    assert e.value.field == "FNOMIN"
    point = tirenv.Model("point", tire)  # needs no enveloping section
    # ... but its load at a contact length is the springs model's (as the CLI's).
    with pytest.raises(tirenv.TirenvError) as e:
        point.load_for_contact_length(0.2)
    assert e.value.field == "FNOMIN"
    # The network's contact length is its own file's law (tirenv_tir_need); an older file's
    # without one would take the springs model's, which this tire file cannot describe.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        older = tirenv.Network(os.path.join(source_dir, "tests", "data", "nn-v1.json"))
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Model("nn", tire, network=older)
    assert e.value.field == "FNOMIN"


def test_sidewall_read_and_used_as_the_cli(cli, source_dir):
    """The 205/60R15's springs model has a sidewall in series (docs/models.md section 4.9):
    Python reads its keys with the C reader and its flat ground is the CLI's, hub height,
    deflection and stiffness included, to the printed digit."""
    path = os.path.join(source_dir, "data", "tires", "205-60R15-mfswift.tir")
    tire = tirenv.Tire(path)
    assert tire["SIDEWALL_STIFFNESS"] == 622300 and tire["SIDEWALL_PRELOAD"] == 2584
    rc, out, err = run_cli(cli, "flat", "--csv", "--model", "springs", "--tire", path)
    assert rc == 0, err
    m = tirenv.Model("springs", tire)
    for r in [line.split(",") for line in out.splitlines()[1:]]:
        f = m.flat(float(r[0]))
        assert [f"{v:.9g}" for v in (f.z_flat, f.deflection, f.contact_length,
                                     f.stiffness)] == r[1:5]
    # Without the sidewall: the elements alone, less deflection above the preload.
    bare = tirenv.Model("springs", tirenv.Tire(path, set={"SIDEWALL_PRELOAD": 0,
                                                          "SIDEWALL_STIFFNESS": 0}))
    assert bare.flat(6000).deflection < m.flat(6000).deflection - 0.005


def test_cam_refused_without_its_shape_keys(cli, tmp_path):
    """The cam's shape (ELLIPS_*) is never derived: a file without it is refused naming the
    keys and the file, as the CLI refuses it, where Python ran the cam with the default tire's
    shape; the ride's cam too; --set's keys make it run, as the CLI's."""
    path = tmp_path / "nocam.tir"
    path.write_text("[DIMENSION]\nUNLOADED_RADIUS = 0.376\n[VERTICAL]\nFNOMIN = 3800\n"
                    "VERTICAL_STIFFNESS = 175000\nQ_FZ2 = 0\n[CONTACT_PATCH]\nQ_RA1 = 0.7\n"
                    "Q_RA2 = 0.6\n")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tire = tirenv.Tire(path)
    with pytest.raises(tirenv.TirenvValueError) as e:
        tirenv.Model("cam", tire)
    assert e.value.field == "ELLIPS_SHIFT" and e.value.file == str(path)
    assert "ELLIPS_SHIFT, ELLIPS_LENGTH, ELLIPS_HEIGHT, ELLIPS_ORDER" in str(e.value)
    assert str(e.value).startswith(f"{path}: ELLIPS_SHIFT: ")
    rc, _, err = run_cli(cli, "flat", "--model", "cam", "--tire", path)
    assert rc == 2 and f"tirenv: {path}: ELLIPS_SHIFT: " in err
    tirenv.Model("springs", tire)  # needs none of them
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        # The file has no VERTICAL_DAMPING: the vehicle gives the rear tires' damper.
        vehicle = tirenv.Vehicle(set={"REAR_AXLE.TIRE_FILE": str(path),
                                      "REAR_AXLE.TIRE_DAMPING": 3000})
        with pytest.raises(tirenv.TirenvValueError) as e:
            tirenv.ride(tirenv.Profile.cleat(0.2, 0.05), model="cam", speed="3km/h",
                        vehicle=vehicle)
    assert e.value.field == "ELLIPS_SHIFT" and e.value.file == str(path)
    shape = {"ELLIPS_SHIFT": 0.8328, "ELLIPS_LENGTH": 1.4634, "ELLIPS_HEIGHT": 0.9551,
             "ELLIPS_ORDER": 1.5257}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        given = tirenv.Tire(path, set=shape)
    m = tirenv.Model("cam", given)
    m.set(tirenv.Profile.cleat(0.05, 0.02), 3800)
    assert m.sweep()["h_m"].max() > 0.01


def _from_fifo(tmp_path, text, make):
    """make(path) on a FIFO that a thread fills once with text, behind a timeout: a second
    read would wait for ever for another writer. Returns make's result or raises its error."""
    fifo = tmp_path / "tire.fifo"
    os.mkfifo(fifo)

    def feed():
        with open(fifo, "w") as f:
            f.write(text)

    writer = threading.Thread(target=feed, daemon=True)
    writer.start()
    box = {}

    def call():
        try:
            box["value"] = make(str(fifo))
        except Exception as e:  # handed to the test's thread
            box["error"] = e

    caller = threading.Thread(target=call, daemon=True)
    caller.start()
    caller.join(timeout=60)
    hung = caller.is_alive()
    if hung:  # release the reader waiting to open: a writer that writes nothing
        os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        caller.join(timeout=10)
    writer.join(timeout=10)
    assert not hung, "the FIFO was read twice: the second read waited for a writer"
    if "error" in box:
        raise box["error"]
    return box["value"]


def test_tire_from_a_fifo_reads_it_once(tmp_path, source_dir):
    path = os.path.join(source_dir, "data", "tires", "default.tir")
    with open(path) as f:
        text = f.read()
    tire = _from_fifo(tmp_path, text, tirenv.Tire)
    assert tire == tirenv.Tire(path)  # every key the same value


def test_fifo_without_a_model_is_refused_not_read_again(tmp_path):
    text = "[DIMENSION]\nUNLOADED_RADIUS = 0.376\n[VERTICAL]\nVERTICAL_STIFFNESS = 1.75e5\n"

    def springs(path):
        with pytest.warns(UserWarning, match="no FNOMIN"):
            tire = tirenv.Tire(path)
        return tirenv.Model("springs", tire)

    with pytest.raises(tirenv.TirenvError) as e:
        _from_fifo(tmp_path, text, springs)
    assert isinstance(e.value, OSError)
    assert e.value.file == str(tmp_path / "tire.fifo")
    assert "not a regular file" in str(e.value) and "springs model" in str(e.value)
