# SPDX-License-Identifier: Apache-2.0
"""The library's refusals reach Python as they reach the CLI (docs/models.md sections 1.3,
6.3 and 9.6): loads beyond a model's valid range, the network outside its trained ranges
unless extrapolate=True, a ride step too long for RK4, an unphysical vehicle."""
import pytest

import tirenv


def test_load_beyond_the_valid_range():
    # The default tire's contact law before it was identified on the ring (Q_RA1 0.61, Q_RA2
    # 0.66, the linear vertical law of VERTICAL_STIFFNESS 297000 N/m) meets the chord of the
    # free circle at 136 kN; the identified one at 337 kN.
    old_law = tirenv.Tire(set={"Q_RA1": 0.61, "Q_RA2": 0.66, "VERTICAL_STIFFNESS": 297000,
                               "Q_FZ2": 0})
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Model("cam", old_law).flat(2e5)
    assert e.value.field == "load" and "valid range, up to" in e.value.message
    assert tirenv.Model("rigid").flat(2e5).load == 2e5


def test_network_outside_its_range(network_file):
    net = tirenv.Network(network_file)
    tall = tirenv.Profile.cleat(0.10, 0.20)
    m = tirenv.Model("nn", network=net)
    with pytest.raises(tirenv.TirenvError) as e:
        m.set(tall, m.load_for_contact_length(0.33))
    assert e.value.field == "obstacle height" and "0.2 m is outside" in e.value.message
    m = tirenv.Model("nn", network=net, extrapolate=True)
    with pytest.warns(tirenv.TirenvWarning, match="0.2 m is outside"):
        m.set(tall, m.load_for_contact_length(0.33))
    assert len(m.sweep()) > 0 and any("extrapolation" in w for w in m.warnings)


def test_bare_network_warns_outside_its_range(network_file):
    """Network.envelope and .predict run the bare network anywhere, with a TirenvWarning
    outside the trained ranges, and none inside."""
    import warnings
    net = tirenv.Network(network_file)
    with pytest.warns(tirenv.TirenvWarning, match="obstacle height 0.2 m is outside"):
        net.envelope([0.0], 0.33, 0.10, 0.20)
    with pytest.warns(tirenv.TirenvWarning, match="contact length 0.9 m is outside"):
        net.predict([[0.5, 0.9, 0.05, 0.10]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        net.envelope([0.0], 0.33, 0.10, 0.05)
        net.predict([[0.5, 0.33, 0.05, 0.10]])


def test_ride_refusals():
    cleat = tirenv.Profile.cleat(0.30, 0.05)
    stiff = tirenv.Vehicle(set={"FRONT_AXLE.TIRE_STIFFNESS": 1e9,
                                "REAR_AXLE.TIRE_STIFFNESS": 1e9})
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.ride(cleat, speed="10km/h", vehicle=stiff)
    assert e.value.field == "dt" and "rk8pd" in e.value.message
    assert tirenv.ride(cleat, speed="10km/h", vehicle=stiff, method="rk8pd") is not None
    with pytest.raises(tirenv.TirenvError, match="outside the plausible range"):
        tirenv.Vehicle(set={"MASS": 1e30})


def test_generator_refusals_say_why():
    # Too many points is a reason of its own (each said 'expected all positive' or 'at least
    # 2 segments' of sizes that were both; 10**12 chords of a cylinder asked for 16 TB).
    with pytest.raises(tirenv.TirenvError, match="at most 1e9 points in all"):
        tirenv.Profile.sine(0.01, 1, 1e12)
    with pytest.raises(tirenv.TirenvError, match="at least 2 points a period"):
        tirenv.Profile.sine(0.01, 1, 2, points_per_period=1)
    with pytest.raises(tirenv.TirenvError, match="2 to 1e9 segments"):
        tirenv.Profile.cylinder(0.1, segments=10**12)
    assert len(tirenv.Profile.cylinder(0.1, segments=7)) == 8


def test_track_positions_bounded():
    # 10**9 tracks built a list of a billion floats and the process was killed for memory.
    for n in (0, 65, 10**9, 2.5, "3"):
        with pytest.raises(tirenv.TirenvError, match="from 1 to 64"):
            tirenv.track_positions(n)
    v = tirenv.track_positions(64, 0.1, 0.64)
    assert v.shape == (64,) and v[0] == 0.1 - 0.32 + 0.005 and v[-1] == 0.1 + 0.32 - 0.005
