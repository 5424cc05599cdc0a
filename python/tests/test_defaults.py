# SPDX-License-Identifier: Apache-2.0
"""The module keeps no copy of the CLI's defaults: the resolution of --cylinder and --sine,
'tirenv envelope's default sweep and 'tirenv ride's span and grid all come from the library,
so the profiles, positions and runs here are the CLI's."""
import os

import pytest

import tirenv
from tirenv._c import ffi, lib
from conftest import run_cli

LOAD = 10937.0  # N
RES = lib.tirenv_profile_resolution_default()
CASES = [
    (["--cleat", "0.2931,0.0743"], lambda: tirenv.Profile.cleat(0.2931, 0.0743)),
    (["--cylinder", "0.1173"], lambda: tirenv.Profile.cylinder(0.1173)),
    (["--sine", "0.0213,0.4519,1.5"], lambda: tirenv.Profile.sine(0.0213, 0.4519, 1.5)),
]


def rows(curve):
    return ["%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d" % tuple(r.tolist()) for r in curve]


def point_curve(tire, profile):
    return tirenv.Model("point", tirenv.Tire(tire)).set(profile, LOAD).sweep()


def cli_curve(cli, tire, args, tmp_path):
    out = tmp_path / "curve.csv"
    rc, _, err = run_cli(cli, "envelope", "--model", "point", *args, "--load", LOAD,
                         "--tire", tire, "-o", out)
    assert rc == 0, err
    return out.read_text().splitlines()[1:]


@pytest.mark.parametrize("args, make", CASES, ids=[c[0][0] for c in CASES])
def test_default_sweep_and_profile_are_the_clis(args, make, cli, source_dir, tmp_path):
    """The point contact's curve is the ground under each position: the same rows mean the
    same positions (the x column) over the same polyline."""
    tire = os.path.join(source_dir, "data", "tires", "default.tir")
    lines = cli_curve(cli, tire, args, tmp_path)
    curve = point_curve(tire, make())
    assert len(lines) > 1000
    assert ["%.9g" % x for x in curve["x_m"]] == [line.split(",")[0] for line in lines]
    assert rows(curve) == lines


@pytest.mark.parametrize("args, other", [
    (["--cylinder", "0.1173"],
     lambda: tirenv.Profile.cylinder(0.1173, RES.cylinder_segments + 1)),
    (["--sine", "0.0213,0.4519,1.5"],
     lambda: tirenv.Profile.sine(0.0213, 0.4519, 1.5, RES.sine_points_per_period + 1)),
], ids=["cylinder", "sine"])
def test_another_resolution_is_another_curve(args, other, cli, source_dir, tmp_path):
    """The comparison above sees one chord more or less."""
    tire = os.path.join(source_dir, "data", "tires", "default.tir")
    assert rows(point_curve(tire, other())) != cli_curve(cli, tire, args, tmp_path)


def test_sweep_takes_the_clis_overrides(cli, source_dir, tmp_path):
    tire = os.path.join(source_dir, "data", "tires", "default.tir")
    lines = cli_curve(cli, tire, ["--cylinder", "0.1173", "--x-from", "-0.4", "--dx", "0.0023"],
                      tmp_path)
    m = tirenv.Model("point", tirenv.Tire(tire)).set(tirenv.Profile.cylinder(0.1173), LOAD)
    assert rows(m.sweep(x_from=-0.4, dx=0.0023)) == lines
    assert tirenv.positions(-0.4, 0.4)[1] == -0.4 + lib.tirenv_positions_default(0, 0, 0).dx


@pytest.mark.parametrize("args, make, extra", [
    (["--cylinder", "0.1173"], lambda: tirenv.Profile.cylinder(0.1173), {}),
    (["--sine", "0.0213,0.4519,1.5", "--dx", "0.0117"],
     lambda: tirenv.Profile.sine(0.0213, 0.4519, 1.5), {"dx": 0.0117}),
], ids=["cylinder", "sine-dx"])
def test_ride_span_is_the_clis(args, make, extra, cli, tmp_path):
    """The point contact at the static load: the run's start, end and input grid decide the
    series' t, x_front, w_front, w_rear and z columns."""
    out = tmp_path / "series.csv"
    rc, _, err = run_cli(cli, "ride", *args, "--speed", "2.3", "--model", "point",
                         "--enveloping", "static", "-o", out)
    assert rc == 0, err
    lines = out.read_text().splitlines()[2:]
    profile = make()
    r = tirenv.ride(profile, model="point", speed=2.3, enveloping="static", **extra)
    s = r.series
    got = [",".join("%.9g" % s[f][k] for f in ("t", "x_front", "w_front", "w_rear", "z"))
           for k in range(len(s))]
    assert got == [",".join(line.split(",")[:5]) for line in lines]
    span = ffi.new("tirenv_ride_span *", lib.tirenv_ride_span_default())
    first, _ = profile.extent
    assert s["x_front"][0] == lib.tirenv_ride_span_start(span, first)
    assert r.x[1] - r.x[0] == pytest.approx(extra.get("dx", span.dx), rel=1e-9)
