# SPDX-License-Identifier: Apache-2.0
"""Bad input raises TirenvError carrying the library's diagnostic; nothing crashes."""
import pytest

import tirenv


def test_missing_tire_file_names_the_file(tmp_path):
    path = tmp_path / "nope.tir"
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Tire(path)
    assert e.value.file == str(path)
    assert "cannot open" in e.value.message
    assert str(path) in str(e.value)
    assert e.value.status_name == "input/output error"


def test_bad_tire_line_names_line_and_key(tmp_path):
    path = tmp_path / "bad.tir"
    path.write_text("[DIMENSION]\nUNLOADED_RADIUS = 0.68\n[ENVELOPING_SPRINGS]\n"
                    "RADIAL_STIFFNESS = lots\n")
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Tire(path)
    assert (e.value.file, e.value.line, e.value.field) == (str(path), 4, "RADIAL_STIFFNESS")
    assert f"{path}:4" in str(e.value)


def test_set_of_unknown_key_and_unphysical_value():
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Tire(set={"NO_SUCH_KEY": 1})
    assert "NO_SUCH_KEY" in str(e.value)
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Tire(set={"UNLOADED_RADIUS": -1.0})
    assert "UNLOADED_RADIUS" in str(e.value) or "R0" in str(e.value)
    t = tirenv.Tire(set={"UNLOADED_RADIUS": 0.7})
    assert t.R0 == 0.7


def test_unknown_model_lists_the_names():
    with pytest.raises(tirenv.TirenvError, match="springs"):
        tirenv.Model("sprongs")


def test_bad_profile_file_names_line(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("x_m,z_m\n0,0\n1,zero\n")
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Profile.read(path)
    assert (e.value.file, e.value.line) == (str(path), 3)


def test_bad_generator_and_arrays():
    with pytest.raises(tirenv.TirenvError, match="positive"):
        tirenv.Profile.cleat(-0.1, 0.1)
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Profile([0, 1, 0.5], [0, 0, 0])  # x decreasing
    assert e.value.field == "x" and e.value.line == 3
    with pytest.raises(tirenv.TirenvError):
        tirenv.Profile.road("Z")


def test_load_the_tire_cannot_carry_and_contact_length_out_of_range():
    m = tirenv.Model("springs")
    with pytest.raises(tirenv.TirenvError) as e:
        m.set(tirenv.Profile.cleat(0.3, 0.05), 1e9)  # more than the tire can carry
    assert e.value.status == 5 and e.value.field == "load"  # TIRENV_ENOBRACKET
    assert "the tire carries with its centre at the ground" in e.value.message
    with pytest.raises(tirenv.TirenvError) as e:
        m.load_for_contact_length(5.0)  # not in (0, 2 R0)
    assert e.value.status == 1 and e.value.field == "contact length"  # TIRENV_EINVAL


def test_obstacle_too_tall_is_a_range_error():
    """Ground within R0 rising to the hub is refused where it is met (docs/models.md section
    2.5): the point contact before a 1 m wall."""
    m = tirenv.Model("point")
    m.set(tirenv.Profile.cleat(0.3, 1.0), 10000)
    with pytest.raises(tirenv.TirenvError) as e:
        m.envelope([-0.5])
    assert e.value.status == 8  # TIRENV_ERANGE


def test_envelope_before_set():
    with pytest.raises(tirenv.TirenvError, match="set"):
        tirenv.Model("cam").envelope([0.0])


def test_bad_network_file(tmp_path):
    path = tmp_path / "nn.json"
    path.write_text('{"format": "something else"}')
    with pytest.raises(tirenv.TirenvError) as e:
        tirenv.Network(path)
    assert e.value.file == str(path)


def test_bad_vehicle_and_ride_arguments(tmp_path):
    with pytest.raises(tirenv.TirenvError, match="MASS"):
        tirenv.Vehicle(set={"MASS": -5})
    with pytest.raises(tirenv.TirenvError, match="speed"):
        tirenv.ride(tirenv.Profile.cleat(0.3, 0.05), speed="fast")
    with pytest.raises(tirenv.TirenvError, match="network"):
        tirenv.ride(tirenv.Profile.cleat(0.3, 0.05), model="nn")
    with pytest.raises(tirenv.TirenvError, match="too coarse") as e:  # 100 Hz < 320 Hz
        tirenv.ride(tirenv.Profile.cleat(0.3, 0.05), dt=0.01)
    assert e.value.field == "dt"
    # A 10 m grid never sampled the 0.3 m cleat: a still seat, as if the road were flat.
    with pytest.raises(tirenv.TirenvError, match="coarser than a tenth") as e:
        tirenv.ride(tirenv.Profile.cleat(0.3, 0.05), dx=10)
    assert e.value.field == "dx"
    with pytest.raises(tirenv.TirenvError, match="Wk"):
        tirenv.comfort([0.0] * 1000, 1000.0, "Wz")


def test_positions_that_would_never_end():
    # tirenv_positions_count looped forever on these once; now each is an error.
    for args in [(0.0, float("inf"), 0.1), (0.0, float("nan"), 0.1), (-1e300, 1e300, 0.1),
                 (1e300, 1e300, 0.1), (0.0, 1.0, 1e-300)]:
        with pytest.raises(tirenv.TirenvError, match="dx"):
            tirenv.positions(*args)
    assert len(tirenv.positions(0.0, 1.0, 0.1)) == 11


def test_network_refuses_inputs_that_are_not_finite(network_file):
    # The activations saturate: inf came out as a plausible h of -0.0187 m once.
    import numpy as np
    net = tirenv.Network(network_file)
    good = np.array([[0.1, 0.3, 0.05, 0.1]])
    assert np.isfinite(net.predict(good)).all()
    for bad in [float("inf"), float("-inf"), float("nan")]:
        rows = np.vstack([good, good])
        rows[1, 2] = bad
        with pytest.raises(ValueError, match="row 1, column 2"):
            net.predict(rows)


def test_plausible_ranges_name_the_key():
    for key, value in [("TREAD_STIFFNESS", 1e-308), ("NODE_ANGLE", 1e-20),
                       ("ELLIPS_SHIFT", 1e308)]:
        with pytest.raises(tirenv.TirenvError, match=key):
            tirenv.Tire(set={key: value})
    for key, value in [("MASS", 1e9), ("GRAVITY", 1e-308), ("SEAT_AHEAD_OF_CG", 1e9)]:
        with pytest.raises(tirenv.TirenvError, match=key):
            tirenv.Vehicle(set={key: value})


def test_set_names_the_argument_not_the_cli_option():
    """A bad set={...} entry is named as the set argument, not as the CLI's --set."""
    with pytest.raises(tirenv.TirenvValueError) as e:
        tirenv.Tire(set={"FOO": 1})
    assert e.value.file == "set" and e.value.field == "FOO" and str(e.value).startswith("set: ")
    with pytest.raises(tirenv.TirenvValueError) as e:
        tirenv.Vehicle(set={"MASS": 1e30})
    assert e.value.file == "set" and "plausible range" in e.value.message


def test_wrong_object_names_the_argument(network_file):
    """An object of the wrong kind raised AttributeError from deep inside ("'str' object has
    no attribute '_require'"), naming neither the argument nor what it takes."""
    cleat = tirenv.Profile.cleat(0.1, 0.05)
    cases = [(lambda: tirenv.Model("springs", "my.tir"), "tire: expected a tirenv.Tire"),
             (lambda: tirenv.Model("nn", network="net.json"),
              "network: expected a tirenv.Network"),
             (lambda: tirenv.ride(None, model="cam", speed=10),
              "profile: expected a tirenv.Profile"),
             (lambda: tirenv.ride(cleat, vehicle="tractor.veh"),
              "vehicle: expected a tirenv.Vehicle"),
             (lambda: tirenv.Network(network_file).road("road.csv", 0.3),
              "profile: expected a tirenv.Profile"),
             (lambda: tirenv.Tire(set=[("RADIAL_STIFFNESS", 1e6)]), "set: expected a mapping")]
    for call, words in cases:
        with pytest.raises(TypeError) as e:
            call()
        assert words in str(e.value)


def test_failed_set_leaves_the_model_unset():
    """A set the library refuses leaves its model unset; the Model kept the profile and load
    of the set before (model.load 20000 N while the library's load was NaN)."""
    model = tirenv.Model("springs")
    cleat = tirenv.Profile.cleat(0.3, 0.1)
    model.set(cleat, 20000)
    with pytest.raises(tirenv.TirenvError):
        model.set(cleat, 1e9)
    assert model.load is None and model.profile is None
    with pytest.raises(tirenv.TirenvError, match="call set"):
        model.envelope(0.0)
    with pytest.raises(tirenv.TirenvError):
        model.set([cleat, cleat], -1.0)
    assert model.load is None
    model.set(cleat, 20000)
    assert model.load == 20000 and model.envelope(0.0)["fz_N"] == pytest.approx(20000)
