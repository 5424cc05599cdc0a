# SPDX-License-Identifier: Apache-2.0
"""The module's curves are the CLI's: the same text in the envelope CSV, and the same bits as
the library computes them for the CLI (envelope_ref.c prints every bit)."""
import os
import subprocess

import numpy as np
import pytest

import tirenv
from conftest import run_cli

# Case R of the paper's Table 3: contact length 0.28 m, cleat 0.10 x 0.10 m.
L, H, LC = 0.10, 0.10, 0.28


def csv_rows(curve):
    """The envelope CSV's rows as src/cli/cmd_envelope.c writes them (%.9g, %zu)."""
    return ["%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d" % tuple(r.tolist()) for r in curve]


def python_curve(model, tire_path):
    m = tirenv.Model(model, tirenv.Tire(tire_path))
    load = m.load_for_contact_length(LC)
    m.set(tirenv.Profile.cleat(L, H), load)
    return load, m.sweep()


@pytest.mark.parametrize("model", ["rigid", "springs", "cam", "ring"])
def test_curve_equals_cli_csv(model, cli, source_dir, tmp_path):
    tire = os.path.join(source_dir, "data", "tires", "default.tir")
    out = tmp_path / "curve.csv"
    rc, _, err = run_cli(cli, "envelope", "--model", model, "--cleat", f"{L},{H}",
                         "--contact-length", LC, "--tire", tire, "-o", out)
    assert rc == 0, err
    lines = out.read_text().splitlines()
    assert lines[0] == "x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations"
    _, curve = python_curve(model, tire)
    assert len(curve) == len(lines) - 1 > 1000
    assert csv_rows(curve) == lines[1:]


@pytest.mark.parametrize("model", ["springs", "cam"])
def test_curve_equals_library_bit_for_bit(model, envelope_ref, source_dir):
    tire = os.path.join(source_dir, "data", "tires", "default.tir")
    ref = subprocess.run([envelope_ref, model, tire, str(L), str(H), str(LC)], check=True,
                         capture_output=True, text=True).stdout.split("\n")
    load, curve = python_curve(model, tire)
    assert float.fromhex(ref[0]) == load
    rows = [r.split() for r in ref[1:] if r]
    assert len(rows) == len(curve)
    floats = np.array([[float.fromhex(v) for v in r[:6]] for r in rows])
    ints = np.array([[int(v) for v in r[6:]] for r in rows], dtype=np.uintp)
    got = np.column_stack([curve[f] for f in ("x_m", "z_m", "h_m", "slope", "fx_N", "fz_N")])
    assert np.array_equal(got.view(np.int64), floats.view(np.int64))  # every bit, signed zeros
    assert np.array_equal(np.column_stack([curve["contacts"], curve["iterations"]]), ints)


def test_structured_array_fields():
    m = tirenv.Model("springs")
    m.set(tirenv.Profile.cleat(0.3, 0.05), 11903.6)
    c = m.envelope([-1.0, 0.0, 1.0])
    assert c.dtype.names == ("x_m", "z_m", "h_m", "slope", "fx_N", "fz_N", "contacts",
                             "iterations")
    assert list(c["x_m"]) == [-1.0, 0.0, 1.0]
    assert np.allclose(c["fz_N"], 11903.6, rtol=0, atol=1e-6)  # the load, at equilibrium
    assert c["h_m"][0] == 0 and c["h_m"][2] == 0                # flat ground far away
    assert 0.03 < c["h_m"][1] < 0.051                             # on the cleat
    assert np.allclose(c["z_m"] - c["h_m"], m.flat(11903.6).z_flat, rtol=0, atol=1e-12)


def test_envelope_takes_any_real_array():
    m = tirenv.Model("cam")
    m.set(tirenv.Profile.cleat(0.3, 0.05), 11903.6)
    x = np.linspace(-1, 1, 41)
    ref = m.set(m.profile, 11903.6).envelope(x)
    strided = np.zeros(82)
    strided[::2] = x
    assert not strided[::2].flags.c_contiguous
    assert np.array_equal(m.set(m.profile, 11903.6).envelope(strided[::2]), ref)
    as_list = m.set(m.profile, 11903.6).envelope(list(x))
    assert np.array_equal(as_list, ref)
    f32 = x.astype(np.float32)
    got = m.set(m.profile, 11903.6).envelope(f32)
    assert np.array_equal(got["x_m"], f32.astype(np.float64))  # float32 values, widened
    ints = m.set(m.profile, 11903.6).envelope(np.array([-1, 0, 1], dtype=np.int32))
    assert list(ints["x_m"]) == [-1.0, 0.0, 1.0]
    one = m.envelope(0.0)  # a scalar is one position, and gives one record
    assert one.shape == () and one == m.envelope([0.0])[0]
    assert m.envelope([]).shape == (0,)


@pytest.mark.parametrize("bad, exc, words", [
    (np.zeros((2, 2)), ValueError, "1-D"),
    (np.array([0.0, np.nan]), ValueError, "x[1]"),
    (np.array([1 + 2j]), TypeError, "complex"),
    (["a", "b"], TypeError, "real numbers"),
])
def test_envelope_refuses_what_it_cannot_take(bad, exc, words):
    m = tirenv.Model("rigid")
    m.set(tirenv.Profile.cleat(0.3, 0.05), 10000)
    with pytest.raises(exc, match=words.replace("[", r"\[").replace("]", r"\]")):
        m.envelope(bad)


@pytest.mark.parametrize("bad", [None, "cleat.csv", [tirenv.Profile.cleat(0.3, 0.05), None]])
def test_set_refuses_what_is_not_a_profile(bad):
    with pytest.raises(TypeError, match="expected a tirenv.Profile"):
        tirenv.Model("rigid").set(bad, 10000)


def test_positions_are_the_clis():
    x = tirenv.positions(-0.75, 0.75, 0.001)
    assert len(x) == 1501 and x[0] == -0.75 and x[-1] == -0.75 + 1500 * 0.001
    assert len(tirenv.positions(0, 1, 0.1)) == 11  # the 1e-9 allowance


def test_generators_match_the_cli(cli, tmp_path):
    """Every obstacle of the CLI has a generator with the same resolution: the rigid model's
    curve over it is the CLI's, text for text."""
    cases = [(["--step", "0,0.05"], tirenv.Profile.step(0, 0.05)),
             (["--trapezoid", "0.1,0.3,0.05"], tirenv.Profile.trapezoid(0.1, 0.3, 0.05)),
             (["--triangle", "0.3,0.05"], tirenv.Profile.triangle(0.3, 0.05)),
             (["--cylinder", "0.1"], tirenv.Profile.cylinder(0.1)),
             (["--sine", "0.02,0.5,2"], tirenv.Profile.sine(0.02, 0.5, 2))]
    for args, profile in cases:
        out = tmp_path / "c.csv"
        rc, _, err = run_cli(cli, "envelope", "--model", "rigid", *args, "--load", 10000,
                             "-o", out)
        assert rc == 0, err
        m = tirenv.Model("rigid")
        m.set(profile, 10000)
        assert csv_rows(m.sweep()) == out.read_text().splitlines()[1:], args


def test_road_and_read_equal_the_cli(cli, tmp_path):
    path = tmp_path / "road.csv"
    rc, _, err = run_cli(cli, "road", "--class", "C", "--length", 20, "--dx", 0.01, "--seed",
                         3, "-o", path)
    assert rc == 0, err
    read = tirenv.Profile.read(path)
    made = tirenv.Profile.road("C", length=20, dx=0.01, seed=3)
    assert len(read) == len(made) == 2001
    # the file holds 9 significant digits
    assert np.allclose(read.x, made.x, rtol=1e-9, atol=0)
    assert np.allclose(read.z, made.z, rtol=0, atol=1e-9 * max(1, np.abs(made.z).max()))
    out = tmp_path / "c.csv"
    rc, _, err = run_cli(cli, "envelope", "--model", "springs", "--profile", path, "--load",
                         11903.6, "-o", out)
    assert rc == 0, err
    m = tirenv.Model("springs")
    m.set(read, 11903.6)
    # The CLI's sweep starts cold every 8192 positions (its --jobs chunks, docs/models.md
    # section 2.4), the Python sweep runs warm throughout: the same values in every column,
    # the iterations apart at a chunk's first row.
    py, cli_rows = csv_rows(m.sweep()), out.read_text().splitlines()[1:]
    assert len(py) == len(cli_rows) > 8192
    for k, (a, b) in enumerate(zip(py, cli_rows)):
        if k % 8192 == 0:
            a, b = a.rsplit(",", 1)[0], b.rsplit(",", 1)[0]
        assert a == b, k


def test_profile_from_arrays():
    p = tirenv.Profile([0, 1, 1, 2], [0, 0, 0.1, 0.1])
    assert len(p) == 4 and p.extent == (0.0, 2.0)
    assert list(p.height([0.5, 1.0, 3.0])) == [0.0, 0.1, 0.1]
    assert np.array_equal(p.z, [0, 0, 0.1, 0.1])


def test_flat_and_contact_length_agree():
    for name in ("springs", "cam", "ring"):
        m = tirenv.Model(name)
        load = m.load_for_contact_length(0.33)
        f = m.flat(load)
        assert f.load == load
        assert abs(f.contact_length - 0.33) < 1e-9
        assert f.deflection > 0 and f.stiffness > 0
    assert set(tirenv.model_names()) >= {"rigid", "springs", "ring", "cam"}


def test_network_equals_cli_predict(cli, network_file, tmp_path):
    out = tmp_path / "p.csv"
    rc, _, err = run_cli(cli, "predict", "--nn", network_file, "--cleat", "0.10,0.10",
                         "--contact-length", 0.28, "-o", out)
    assert rc == 0, err
    rows = [r.split(",") for r in out.read_text().splitlines()[1:]]
    x = np.array([float(r[0]) for r in rows])
    net = tirenv.Network(network_file)
    assert net.R0 == tirenv.Tire().R0 and net.n_inputs == 4
    x_py = tirenv.positions(-0.05 - net.R0 - 0.02, 0.05 + net.R0 + 0.02)
    assert ["%.9g" % v for v in x_py] == [r[0] for r in rows]
    h = net.envelope(x_py, 0.28, 0.10, 0.10)
    assert ["%.9g" % v for v in h] == [r[2] for r in rows]
    # the bare network, row by row, is what envelope evaluates on the approach half
    y = net.predict([[0.5, 0.28, 0.10, 0.10], [0.9, 0.33, 0.05, 0.2]])
    assert y.shape == (2,) and np.all(np.isfinite(y))
    road = net.road(tirenv.Profile.cleat(0.10, 0.10), 0.28)
    h_road, slope = road.eval(x_py)
    assert road.obstacles == 1
    assert np.allclose(h_road, h, rtol=0, atol=1e-9)  # one cleat: the cleat's own curve
    assert np.all(np.isfinite(slope))


def test_cam_warns_above_its_max_step():
    """A cam touching the ground higher above its lowest point than ELLIPS_MAX_STEP: one
    TirenvWarning naming the key, at the curve's first rise; the same curve as without it;
    a lower cleat after set() warns of nothing."""
    plain = tirenv.Model("cam", tirenv.Tire())
    m = tirenv.Model("cam", tirenv.Tire(set={"ELLIPS_MAX_STEP": 0.025}))
    assert m.tire["ELLIPS_MAX_STEP"] == 0.025
    load = m.load_for_contact_length(LC)
    x = tirenv.positions(-1.0, 1.0, 0.001)
    with pytest.warns(tirenv.TirenvWarning, match="ELLIPS_MAX_STEP") as caught:
        m.set(tirenv.Profile.cleat(L, 0.03), load)
        curve = m.envelope(x)
        curve_again = m.envelope(x)   # the same warning is not issued twice
    assert len([w for w in caught if issubclass(w.category, tirenv.TirenvWarning)]) == 1
    assert curve.tobytes() == curve_again.tobytes()
    assert len(m.warnings) == 1
    rise = x[np.argmax(curve["h_m"] > 0)]
    assert abs(float(m.warnings[0].split("x = ")[1].split(" m")[0]) - rise) < 1e-6
    plain.set(tirenv.Profile.cleat(L, 0.03), load)
    assert plain.envelope(x).tobytes() == curve.tobytes() and plain.warnings == ()
    m.set(tirenv.Profile.cleat(L, 0.02), load)
    m.envelope(x)
    assert m.warnings == ()
