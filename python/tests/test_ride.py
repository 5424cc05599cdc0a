# SPDX-License-Identifier: Apache-2.0
"""The ride and its comfort figures are 'tirenv ride's."""
import os

import numpy as np
import pytest

import tirenv
from conftest import run_cli

COLUMNS = ("t", "x_front", "w_front", "w_rear", "z", "theta", "z_a", "seat_az", None,
           "seat_ax", "atheta", "F_front", "F_rear")


def test_ride_series_equals_cli(cli, tmp_path):
    out = tmp_path / "series.csv"
    rc, table, err = run_cli(cli, "ride", "--cleat", "0.30,0.05", "--speed", "10km/h",
                             "--model", "springs", "-o", out)
    assert rc == 0, err
    lines = out.read_text().splitlines()
    # The header first, then the comment line (docs/formats.md section 1).
    assert lines[0].startswith("t_s,x_front_m,w_front_m")
    assert lines[1].startswith("# tirenv ride: springs model")
    r = tirenv.ride(tirenv.Profile.cleat(0.30, 0.05), model="springs", speed="10km/h")
    c = r.comfort()
    s = r.series
    awz = c["seat_awz"]
    rows = []
    for k in range(len(s)):
        vals = [awz[k] if f is None else s[f][k] for f in COLUMNS]
        rows.append(",".join("%.9g" % v for v in vals))
    assert len(rows) == len(lines) - 2 > 3000
    assert rows == lines[2:]
    # the table's figures: a_wz, crest, VDV, MTVV, pitch, a_v, peak, lift-off
    cols = table.splitlines()[2].split()
    assert cols[0] == "springs"
    assert "%.4f" % c["seat"].rms == cols[2] and "%.2f" % c["seat"].crest == cols[3]
    assert "%.4f" % c["seat"].vdv == cols[4] and "%.4f" % c["seat"].mtvv == cols[5]
    assert "%.4f" % c["pitch"].rms == cols[6] and "%.4f" % c["a_v"] == cols[7]
    assert "%.3f" % c["peak_az"] == cols[8] and "%.3f" % c["lift_off"] == cols[9]


def test_point_contact_follows_the_ground():
    p = tirenv.Profile.cleat(0.30, 0.05)
    r = tirenv.ride(p, model="point", speed=2.0)
    assert np.array_equal(r.w_front, p.height(r.x))
    assert np.array_equal(r.w_front, r.w_rear)
    s = r.series
    assert s["t"][0] == 0 and np.allclose(np.diff(s["t"]), 1e-3)
    assert s["x_front"][0] == -1.15  # 1 m before the cleat


def test_vehicle_and_comfort():
    v = tirenv.Vehicle(set={"MASS": 5200.0})
    d = tirenv.Vehicle()
    assert v.tire_load("rear") > d.tire_load("rear")
    assert v.tire("front").R0 == tirenv.Tire().R0
    fs = 1000.0
    t = np.arange(20000) / fs
    a = np.sin(2 * np.pi * 5 * t)  # 5 Hz, where Wk is about 1
    a_w, m = tirenv.comfort(a, fs, "Wk")
    assert a_w.shape == a.shape
    assert 0.6 < m.rms < 0.8 and m.duration == 20.0
    assert abs(tirenv.total_value([1, 1], [3, 4]) - 5) < 1e-12


def test_vehicle_tires_are_the_tire_files(source_dir):
    """Each axle's k_t is its tire file's vertical law at its static load, c_t its
    VERTICAL_DAMPING, unless the vehicle gives them (docs/models.md section 9.1): the
    default tire's stiffer rear (13.3 kN) than front (8.7 kN), the 205/60R15 file's linear
    law 209651.5 N/m, and a file without VERTICAL_DAMPING refused without TIRE_DAMPING."""
    d = tirenv.Vehicle()
    front, rear = d.tire_spring("front"), d.tire_spring("rear")
    assert abs(front["k_t"] - 311320.5) < 0.1 and abs(rear["k_t"] - 342572.7) < 0.1
    assert front["c_t"] == rear["c_t"] == 3000.0
    assert front["k_t_from"] == rear["c_t_from"] == "tire file"
    v = tirenv.Vehicle(set={"FRONT_AXLE.TIRE_STIFFNESS": 283117.3})
    assert v.tire_spring("front")["k_t"] == 283117.3
    assert v.tire_spring("front")["k_t_from"] == "vehicle file"
    assert v.tire_spring("front")["c_t_from"] == "tire file"
    car = os.path.join(source_dir, "data", "tires", "205-60R15-mfswift.tir")
    with pytest.raises(tirenv.TirenvValueError) as e:
        tirenv.Vehicle(set={"REAR_AXLE.TIRE_FILE": car})
    assert e.value.field == "REAR_AXLE.TIRE_DAMPING"
    assert "VERTICAL_DAMPING" in e.value.message
    v = tirenv.Vehicle(set={"REAR_AXLE.TIRE_FILE": car, "REAR_AXLE.TIRE_DAMPING": 500.0})
    assert v.tire_spring("rear") == {"k_t": 209651.5, "c_t": 500.0, "k_t_from": "tire file",
                                     "c_t_from": "vehicle file"}


def test_network_ride_equals_cli(cli, network_file, tmp_path):
    """The network over the cleat as each axle's input (src/cli/ride_input.c's choices)."""
    # extrapolate: by the contact law of the network's data the front tire's 8.74 kN is a
    # 0.23 m patch, below the data set's 0.28 m (docs/models.md section 14.3).
    out = tmp_path / "series.csv"
    rc, _, err = run_cli(cli, "ride", "--cleat", "0.30,0.05", "--speed", "5km/h", "--model",
                         "nn", "--nn", network_file, "--extrapolate", "-o", out)
    assert rc == 0, err
    lines = out.read_text().splitlines()[2:]
    r = tirenv.ride(tirenv.Profile.cleat(0.30, 0.05), model="nn", speed="5km/h",
                    network=tirenv.Network(network_file), extrapolate=True)
    s = r.series
    got = [",".join("%.9g" % s[f][k] for f in ("t", "x_front", "w_front", "w_rear", "z"))
           for k in range(len(s))]
    assert got == [",".join(line.split(",")[:5]) for line in lines]


def test_static_and_dynamic_enveloping_equal_cli(cli, tmp_path):
    """enveloping="static" is 'tirenv ride --enveloping static', the default "dynamic" the
    CLI's default (docs/models.md section 9.5); the two differ over a cleat."""
    runs = {}
    for way in ("static", "dynamic"):
        out = tmp_path / f"{way}.csv"
        rc, _, err = run_cli(cli, "ride", "--cleat", "0.30,0.05", "--speed", "5km/h",
                             "--model", "cam", "--enveloping", way, "-o", out)
        assert rc == 0, err
        r = tirenv.ride(tirenv.Profile.cleat(0.30, 0.05), model="cam", speed="5km/h",
                        enveloping=way)
        s = r.series
        got = [",".join("%.9g" % s[f][k] for f in ("t", "x_front", "w_front", "w_rear", "z"))
               for k in range(len(s))]
        lines = out.read_text().splitlines()[2:]
        assert got == [",".join(line.split(",")[:5]) for line in lines]
        runs[way] = s["w_front"]
    assert not np.array_equal(runs["static"], runs["dynamic"])


def test_comfort_equals_cli_table(cli, tmp_path):
    """Ride.comfort is the CLI's comfort.csv to the nine digits it writes: both are
    tirenv_ride_comfort_measure (a static and a dynamic run over a cleat high enough to lift
    a tire off)."""
    rc, _, err = run_cli(cli, "ride", "--cleat", "0.10,0.15", "--speed", "3",
                         "--model", "springs", "--enveloping", "static,dynamic",
                         "--out-dir", tmp_path / "out")
    assert rc == 0, err
    rows = [line.split(",") for line in (tmp_path / "out" / "comfort.csv").read_text()
            .splitlines() if not line.startswith("#")]
    head, rows = rows[0], rows[1:]
    assert len(rows) == 2
    for row in rows:
        f = dict(zip(head, row))
        r = tirenv.ride(tirenv.Profile.cleat(0.10, 0.15), model="springs", speed=3.0,
                        enveloping=f["enveloping"])
        c = r.comfort()
        got = {"a_wz_m_s2": c["seat"].rms, "crest": c["seat"].crest,
               "vdv_m_s1.75": c["seat"].vdv, "mtvv_m_s2": c["seat"].mtvv,
               "peak_awz_m_s2": c["seat"].peak, "a_w_pitch_rad_s2": c["pitch"].rms,
               "vdv_pitch_rad_s1.75": c["pitch"].vdv, "a_v_m_s2": c["a_v"],
               "peak_az_m_s2": c["peak_az"], "lift_off_s": c["lift_off"]}
        for name, value in got.items():
            assert "%.9g" % value == f[name], (f["enveloping"], name)
    assert any(float(dict(zip(head, row))["lift_off_s"]) > 0 for row in rows)
