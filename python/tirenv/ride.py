# SPDX-License-Identifier: Apache-2.0
"""The tractor ride (docs/models.md section 9) and ISO 2631-1 comfort (section 10)."""
import collections
import math

import numpy as np

from ._c import (ffi, lib, check, check_set, doubles, double_ptr, expect, invalid, new_diag,
                 path_bytes, struct_dtype)
from .model import Model
from .profile import Profile
from .tire import Tire

# The names of the library's tirenv_ride_sample, in its order.
SAMPLE_FIELDS = tuple(name for name, _ in ffi.typeof("tirenv_ride_sample").fields)
# One output sample of the ride, laid out as the library's tirenv_ride_sample.
SAMPLE_DTYPE = struct_dtype("tirenv_ride_sample", [(f, f, "f8") for f in SAMPLE_FIELDS])

Metrics = collections.namedtuple("Metrics", "duration rms peak crest vdv mtvv")
Metrics.__doc__ = "ISO 2631-1 clause 6 figures of one weighted series (units of the input)."

AXLES = {"front": 0, "rear": 1, 0: 0, 1: 1}


def _axle(axle):
    if axle not in AXLES:
        raise invalid(f"expected 'front', 'rear', 0 or 1, got {axle!r}", "axle")
    return AXLES[axle]


class Vehicle:
    """The pitch-plane tractor: Vehicle() the built-in default (data/vehicles/tractor.veh),
    Vehicle(path) a vehicle file, set={"MASS": 5200, "FRONT_AXLE.TIRES": 4} overrides.
    Each axle's tires are its TIRE_FILE's, read once here: their spring the file's vertical
    law F_z(rho) (k_t its tangent at the static load, for the linear checks), their damper
    c_t its VERTICAL_DAMPING, unless the vehicle gives TIRE_STIFFNESS (a linear spring) or
    TIRE_DAMPING (the same library call as 'tirenv ride', tirenv_vehicle_tires;
    docs/models.md section 9.1); tire_spring(axle) says which."""

    def __init__(self, path=None, set=None):
        self._v = ffi.new("tirenv_vehicle *")
        self._v[0] = lib.tirenv_vehicle_default()
        diag = new_diag()
        if path is not None:
            check(lib.tirenv_vehicle_read(path_bytes(path), self._v, diag), diag)
        for key, value in (set or {}).items():
            value = repr(value) if isinstance(value, float) else value
            check_set(lib.tirenv_vehicle_set(self._v, f"{key}={value}".encode(), diag), diag)
        check(lib.tirenv_vehicle_check(self._v, diag), diag)
        # The vehicle as given (NAN: the tire file's), then its tires' springs and dampers.
        self._given = ffi.new("tirenv_vehicle *", self._v[0])
        paths = [ffi.string(ax.tire_file).decode() for ax in (self._v.front, self._v.rear)]
        front = Tire(paths[0]) if paths[0] else Tire()
        self._tires = (front, front if paths[1] == paths[0] else
                       Tire(paths[1]) if paths[1] else Tire())
        check(lib.tirenv_vehicle_tires(self._v, self._tires[0]._t, self._tires[1]._t, diag),
              diag)
        check(lib.tirenv_vehicle_check(self._v, diag), diag)

    @property
    def wheelbase(self):
        return self._v.a + self._v.b

    def tire_load(self, axle):
        """Static load of one tire of the axle ('front' or 'rear'), N."""
        return lib.tirenv_vehicle_tire_load(self._v, _axle(axle))

    def tire(self, axle):
        """The axle's tire: its TIRE_FILE, or the default tire (read when the vehicle was)."""
        return self._tires[_axle(axle)]

    def tire_spring(self, axle):
        """One tire of the axle as the ride has it: a dict of k_t (N/m) and c_t (N*s/m), and
        k_t_from, c_t_from: "tire file" (its vertical law, which the force follows, k_t its
        tangent at the static load; its VERTICAL_DAMPING) or "vehicle file" (TIRE_STIFFNESS,
        a linear spring; TIRE_DAMPING; or set=)."""
        i = _axle(axle)
        ax, given = (self._v.rear, self._given.rear) if i else (self._v.front, self._given.front)
        return {"k_t": ax.k_t, "c_t": ax.c_t,
                "k_t_from": "tire file" if math.isnan(given.k_t) else "vehicle file",
                "c_t_from": "tire file" if math.isnan(given.c_t) else "vehicle file"}


def comfort(a, fs, weighting="Wk"):
    """Weights the series a (m/s^2, or rad/s^2 for We) sampled at fs (Hz) with an ISO 2631-1
    weighting ("Wk", "Wd", "We") and returns (a_w, Metrics)."""
    a = doubles(a, "a")
    w, diag = ffi.new("tirenv_weighting *"), new_diag()
    check(lib.tirenv_weighting_parse(str(weighting).encode(), w, diag), diag)
    a_w, m = np.empty_like(a), ffi.new("tirenv_comfort_metrics *")
    check(lib.tirenv_comfort_evaluate(w[0], fs, double_ptr(a), double_ptr(a_w), a.size, m,
                                      diag), diag)
    return a_w, Metrics(m.duration, m.rms, m.peak, m.crest, m.vdv, m.mtvv)


def total_value(k, a_w):
    """ISO 2631-1 6.5: (sum (k_i a_w,i)^2)^(1/2) over axes."""
    k, a_w = doubles(k, "k"), doubles(a_w, "a_w")
    if k.size != a_w.size:
        raise ValueError("k and a_w differ in length")
    out, diag = ffi.new("double *"), new_diag()
    check(lib.tirenv_comfort_total_value(double_ptr(k), double_ptr(a_w), k.size, out, diag),
          diag)
    return out[0]


class Ride:
    """One run: series (structured array, fields SAMPLE_FIELDS), the inputs' grid x (m) and
    what each axle's tires followed, w_front and w_rear (m)."""

    def __init__(self, model, speed, dt, series, x, w_front, w_rear):
        self.model, self.speed, self.dt = model, speed, dt
        self.series, self.x, self.w_front, self.w_rear = series, x, w_front, w_rear

    def comfort(self):
        """The seat's figures as 'tirenv ride' reports them, by the same library call
        (tirenv_ride_comfort_measure): a dict with seat (Wk, vertical), pitch (We), a_v
        (vibration total value, k = 1 and 0.4 m/rad), seat_awz (the weighted series), peak_az
        and lift_off (s with a tire off the ground)."""
        s = np.ascontiguousarray(self.series)
        seat_awz, c, diag = np.empty(s.size), ffi.new("tirenv_ride_comfort *"), new_diag()
        check(lib.tirenv_ride_comfort_measure(ffi.cast("tirenv_ride_sample *",
                                                       ffi.from_buffer(s)),
                                              s.size, self.dt, double_ptr(seat_awz), c, diag),
              diag)
        seat = Metrics(c.seat.duration, c.seat.rms, c.seat.peak, c.seat.crest, c.seat.vdv,
                       c.seat.mtvv)
        pitch = Metrics(c.pitch.duration, c.pitch.rms, c.pitch.peak, c.pitch.crest,
                        c.pitch.vdv, c.pitch.mtvv)
        return {"seat": seat, "pitch": pitch, "a_v": c.a_v, "seat_awz": seat_awz,
                "peak_az": c.peak_az, "lift_off": c.lift_off}


def _inputs(name, tire, load, profile, network, x0, dx, n, extrapolate=False):
    """What one axle's tires follow on the grid: the model type's effective height, the
    network's through the same table (src/cli/ride_input.c)."""
    w, diag = np.empty(n), new_diag()
    m = Model(name, tire, network, extrapolate)
    check(lib.tirenv_ride_effective(m._m, profile._p, load, x0, dx, n, double_ptr(w), diag),
          diag)
    return w


def _table(name, tire, load, profile, network, x0, dx, n, extrapolate=False):
    """What one axle's tires follow at every load of 'tirenv ride's table (docs/models.md
    section 9.5): (loads, rows), rows[j] on the grid at loads[j]."""
    m_max = lib.TIRENV_RIDE_TABLE_LOADS
    loads, w = np.empty(m_max), np.empty(m_max * n)
    rows, diag = ffi.new("size_t *"), new_diag()
    m = Model(name, tire, network, extrapolate)
    check(lib.tirenv_ride_table_build(m._m, profile._p, load, x0, dx, n, double_ptr(loads),
                                      double_ptr(w), rows, ffi.NULL, 0, diag), diag)
    return loads[:rows[0]].copy(), w[:rows[0] * n].reshape(rows[0], n).copy()


def speed_of(v):
    """A speed in m/s from a number (m/s) or text as 'tirenv ride --speed' takes it, by the
    same library call (tirenv_ride_speed_parse): "10km/h", "2.5m/s" or "2.5". A number is
    checked where the run is planned (tirenv_ride_plan_make)."""
    if isinstance(v, str):
        out, diag = ffi.new("double *"), new_diag()
        check(lib.tirenv_ride_speed_parse(v.strip().encode(), out, diag), diag)
        return out[0]
    try:
        return float(v)
    except (TypeError, ValueError):
        raise invalid(f"expected a speed > 0, got {v!r}", "speed") from None


def _nan_if_none(v):
    return float("nan") if v is None else v


def ride(profile, model="point", speed=1.0, vehicle=None, network=None, dx=None, dt=None,
         method=None, tol=None, x_from=None, x_to=None, enveloping=None, extrapolate=False):
    """Drives the tractor at speed (m/s) over profile, each axle's tires following what model
    makes of it ("point" for single-point contact, a model name, or "nn" with network), as
    'tirenv ride' does, by the same library call planning the run (tirenv_ride_plan_make):
    the same grid of the inputs (every dx m), the same start x_from and end x_to of the front
    axle (m; from a run-in before the obstacle to once the rear axle has passed it and the
    body settled), the output interval dt (s), the integrator method ("rk4", "rk8pd") and
    its tol, all by default the library's, as the CLI's (tirenv_ride_plan_params_default),
    and the same way of enveloping (the library's default, TIRENV_RIDE_ENVELOPING_DEFAULT,
    "dynamic": the effective road at the load the tires carry, from tables over loads; or
    "static", at the axle's static tire load; docs/models.md section 9.5; "direct" is the
    CLI's alone). The integration is one library call with the GIL released. extrapolate=True
    lets the network run outside its trained ranges, as 'tirenv ride --extrapolate'. Returns
    a Ride (w_front, w_rear: the static load's rows)."""
    expect(profile, Profile, "profile")
    v = expect(vehicle, Vehicle, "vehicle", " (Vehicle(path) reads a vehicle file)") \
        if vehicle is not None else Vehicle()
    speeds = ffi.new("double[1]", [speed_of(speed)])
    pp, diag = ffi.new("tirenv_ride_plan_params *"), new_diag()
    pp[0] = lib.tirenv_ride_plan_params_default()
    if dx is not None:
        pp.span.dx = dx
    if dt is not None:
        pp.dt = dt
    if tol is not None:
        pp.tol = tol
    if method is not None:
        m = ffi.new("tirenv_ride_method *")
        check(lib.tirenv_ride_method_parse(str(method).encode(), m, diag), diag)
        pp.method = m[0]
    way = ffi.new("tirenv_ride_enveloping *", lib.TIRENV_RIDE_ENVELOPING_DEFAULT)
    if enveloping is not None:
        check(lib.tirenv_ride_enveloping_parse(str(enveloping).encode(), way, diag), diag)
    if way[0] == lib.TIRENV_RIDE_DIRECT:
        raise invalid("direct is tirenv ride's alone here: expected static or dynamic",
                      "enveloping")
    pp.x_from, pp.x_to = _nan_if_none(x_from), _nan_if_none(x_to)
    plan = ffi.new("tirenv_ride_plan *")
    check(lib.tirenv_ride_plan_make(pp, v._v, profile._p, speeds, 1, plan, diag), diag)
    tires = [v.tire(axle) for axle in (0, 1)]  # each read once, for the grid and the inputs
    dx_max = lib.tirenv_ride_dx_max(tires[0].R0, tires[1].R0)
    if not plan.dx <= dx_max:
        raise invalid(f"a grid of {plan.dx:g} m is coarser than a tenth of the tires' free "
                      f"radius: expected at most {dx_max:g} m", "dx")
    s = ffi.new("tirenv_ride_settings *", plan.run[0])
    x0, dx, n = plan.x0, plan.dx, plan.n
    series = np.zeros(lib.tirenv_ride_n_samples(s), dtype=SAMPLE_DTYPE)
    out = ffi.cast("tirenv_ride_sample *", ffi.from_buffer(series))
    if way[0] == lib.TIRENV_RIDE_STATIC:
        w = [_inputs(model, tires[axle], v.tire_load(axle), profile, network, x0, dx, n,
                     extrapolate) for axle in (0, 1)]
        tracks = [ffi.new("tirenv_ride_track *",
                          {"x0": x0, "dx": dx, "n": n, "w": double_ptr(a)}) for a in w]
        check(lib.tirenv_ride_run(v._v, tracks[0], tracks[1], s, out, diag), diag)
    else:
        tables = [_table(model, tires[axle], v.tire_load(axle), profile, network, x0, dx, n,
                         extrapolate) for axle in (0, 1)]
        c = [ffi.new("tirenv_ride_table *", {"x0": x0, "dx": dx, "n": n, "m": len(loads),
                                             "load": double_ptr(loads), "w": double_ptr(rows)})
             for loads, rows in tables]
        check(lib.tirenv_ride_run_dynamic(v._v, c[0], c[1], s, out, diag), diag)
        w = [rows[int(np.argmin(np.abs(loads - v.tire_load(axle))))]
             for axle, (loads, rows) in enumerate(tables)]
    return Ride(model, s.speed, s.dt, series, x0 + np.arange(n, dtype=np.float64) * dx, w[0],
                w[1])
