# SPDX-License-Identifier: Apache-2.0
# Roads from other tools: Profile.read takes OpenCRG and RDF roads as the CLI's --profile does,
# and a list of tracks is the CLI's --tracks, bit for bit.
import os

import numpy as np
import pytest

import tirenv
from conftest import run_cli


def samples(source_dir):
    path = os.path.join(source_dir, "tests", "data", "samples")
    if not os.path.isdir(path):
        pytest.fail(f"the sample road files are missing: {path}")
    return path


def csv_rows(curve):
    return ["%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d" % tuple(r) for r in curve.tolist()]


def test_read_crg_track_equals_convert(cli, source_dir, tmp_path):
    road = os.path.join(samples(source_dir), "crg", "halfround_6in.crg")
    out = tmp_path / "t.csv"
    rc, _, err = run_cli(cli, "convert", "--profile", road, "--track", 0.9, "-o", out)
    assert rc == 0, err
    via_csv = tirenv.Profile.read(out)
    p = tirenv.Profile.read(road, track=0.9)
    assert len(p) == len(via_csv) == 10001
    assert np.array_equal(p.x, via_csv.x) and np.array_equal(p.z, via_csv.z)


def test_read_rdf_sides(source_dir):
    road = os.path.join(samples(source_dir), "rdf", "plateau.rdf")
    mean = tirenv.Profile.read(road)
    left = tirenv.Profile.read(road, side="left")
    right = tirenv.Profile.read(road, side="right")
    assert np.array_equal(mean.z, (left.z + right.z) / 2)
    with pytest.raises(tirenv.TirenvError, match="left, right or mean"):
        tirenv.Profile.read(road, side="middle")


def test_read_refuses_what_selects_nothing(source_dir, tmp_path):
    # As the CLI's --track and --side: a track of a road that is the same on every track, or a
    # side of a road that has none, was taken without a word.
    crg = os.path.join(samples(source_dir), "crg", "halfround_6in.crg")
    rdf = os.path.join(samples(source_dir), "rdf", "plateau.rdf")
    csv = tmp_path / "r.csv"
    csv.write_text("x_m,z_m\n0,0\n1,0.01\n")
    for path, kw, says in ((csv, {"track": 3.0}, "track applies to an OpenCRG road"),
                           (rdf, {"track": 0.0}, "track applies to an OpenCRG road"),
                           (crg, {"side": "left"}, "side applies to an RDF road"),
                           (csv, {"side": "mean"}, "side applies to an RDF road")):
        with pytest.raises(tirenv.TirenvError, match=says):
            tirenv.Profile.read(path, **kw)
    assert len(tirenv.Profile.read(csv)) == 2


def test_tracks_equal_the_cli(cli, source_dir, tmp_path):
    road = os.path.join(samples(source_dir), "crg", "handmade_curved.crg")
    v = tirenv.track_positions(3, 0.2, 0.38)
    assert np.allclose(v, [0.2 - 0.38 / 3, 0.2, 0.2 + 0.38 / 3], rtol=0, atol=1e-15)
    for name in ("springs", "cam", "rigid"):
        out = tmp_path / f"{name}.csv"
        rc, _, err = run_cli(cli, "envelope", "--model", name, "--profile", road, "--track",
                             0.2, "--tracks", 3, "--contact-length", 0.33, "--dx", 0.01,
                             "-o", out)
        assert rc == 0, err
        m = tirenv.Model(name)
        m.set([tirenv.Profile.read(road, track=t) for t in v], m.load_for_contact_length(0.33))
        assert csv_rows(m.sweep(dx=0.01)) == out.read_text().splitlines()[1:]


def test_one_track_list_is_set():
    p = tirenv.Profile.cleat(0.3, 0.05)
    a, b = tirenv.Model("springs"), tirenv.Model("springs")
    a.set(p, 11903.6)
    b.set([p, p, p], 11903.6, weights=[1, 2, 3])
    assert np.array_equal(a.sweep(), b.sweep())
