# SPDX-License-Identifier: Apache-2.0
"""The empirical model: a trained network read from its model file (tirenv train -o FILE),
over a single cleat (docs/models.md section 6) or any profile (section 12)."""
import threading
import warnings

import numpy as np

from ._c import (TirenvWarning, ffi, lib, check, doubles, double_ptr, expect, invalid,
                 is_scalar, new_diag, one_or_all, path_bytes)
from .profile import Profile

INPUTS = ("x_N", "contact_length_m", "obstacle_height_m", "obstacle_length_m")


class Network:
    """A network model file. predict() runs the bare network; envelope() gives h over a
    cleat and road() over any profile. R0 is the free radius (m) of the data it was trained
    on, as the file records it (None if not). Calls on one network are serialised."""

    def __init__(self, path):
        out, rec, diag = ffi.new("tirenv_nn **"), ffi.new("tirenv_train_record *"), new_diag()
        check(lib.tirenv_nn_read_json(path_bytes(path), out, rec, diag), diag)
        self._nn = ffi.gc(out[0], lib.tirenv_nn_free)
        self.R0 = rec.R0 if rec.R0 > 0 else None
        # The load-to-contact-length relation of the data's tire (docs/models.md section
        # 14.3); an older file has none, and the springs model of the tire stands in.
        self._law = ffi.new("tirenv_contact_law *", rec.law)
        if rec.law.n == 0:
            warnings.warn(f"{path} records no relation between load and contact length of its "
                          "tire (training.data.contact_law): loads become contact lengths by "
                          "the springs model of the tire; train it again to record it")
        self.path = path
        self._lock = threading.Lock()

    @property
    def n_inputs(self):
        return lib.tirenv_nn_n_inputs(self._nn)

    def _R0(self, R0):
        R0 = R0 if R0 is not None else self.R0
        if R0 is None:
            raise invalid("the model file records no R0: pass R0 (m)", "R0")
        return R0

    def _outside(self, columns):
        """A TirenvWarning for each of the obstacle's inputs (columns: index -> values) outside
        the range the network was trained on, as Model("nn", extrapolate=True) warns."""
        n = self.n_inputs
        lo, hi = ffi.new("double[]", n), ffi.new("double[]", n)
        lib.tirenv_nn_input_range(self._nn, lo, hi)
        names = {1: "contact length", 2: "obstacle height", 3: "obstacle length"}
        for i, v in columns.items():
            v = np.asarray(v, dtype=np.float64)
            if v.size and (v.min() < lo[i] or v.max() > hi[i]):
                bad = v.min() if v.min() < lo[i] else v.max()
                warnings.warn(f"{names[i]} {bad:g} m is outside the range the network was "
                              f"trained on ({lo[i]:g} to {hi[i]:g} m): the prediction is an "
                              "extrapolation", TirenvWarning, stacklevel=3)

    def predict(self, inputs):
        """h (m) for rows of raw inputs (x_N, l_c m, H m, L m): an array of shape (n, 4) gives
        n values, one row of 4 a float. A NaN or infinite input raises ValueError naming its
        row and column; a contact length or obstacle outside the trained ranges is evaluated
        with a TirenvWarning."""
        a = np.asarray(inputs)
        one = a.ndim == 1
        if a.dtype.kind not in "biuf":
            raise TypeError(f"inputs: expected real numbers, got dtype {a.dtype}")
        a = np.ascontiguousarray(np.atleast_2d(a), dtype=np.float64)
        if a.ndim != 2 or a.shape[1] != self.n_inputs:
            raise invalid(f"expected shape (n, {self.n_inputs}), got {a.shape}", "inputs")
        bad = ~np.isfinite(a)
        if bad.any():  # the activations saturate: inf would map to a plausible-looking h
            row, col = (int(i) for i in np.argwhere(bad)[0])
            raise invalid(f"expected finite numbers, got {a[row, col]} in row {row}, "
                          f"column {col}", "inputs")
        self._outside({i: a[:, i] for i in range(1, min(4, self.n_inputs))})
        y = np.empty(a.shape[0])
        with self._lock:
            lib.tirenv_nn_run_batch(self._nn, a.shape[0], double_ptr(a), double_ptr(y))
        return one_or_all(y, one)

    def envelope(self, x, contact_length, length, height, R0=None):
        """h (m) at centre positions x (m) over a length x height (m) cleat centred at 0, at
        the given contact length (m); a scalar x gives a float. Outside the trained ranges,
        evaluated with a TirenvWarning."""
        if self.n_inputs >= 4:
            self._outside({1: contact_length, 2: height, 3: length})
        scalar = is_scalar(x)
        x = doubles(x, "x")
        h, diag = np.empty(x.size), new_diag()
        with self._lock:
            check(lib.tirenv_nn_envelope(self._nn, self._R0(R0), contact_length, length,
                                         height, x.size, double_ptr(x), double_ptr(h), diag),
                  diag)
        return one_or_all(h, scalar)

    def road(self, profile, contact_length, R0=None):
        """The network over any profile by equivalent cleats (include/tirenv/nn_road.h)."""
        return NetworkRoad(self, expect(profile, Profile, "profile"), contact_length,
                           self._R0(R0))


class NetworkRoad:
    """The network's decomposition of one profile at one contact length."""

    def __init__(self, net, profile, contact_length, R0):
        out, diag = ffi.new("tirenv_nn_road **"), new_diag()
        with net._lock:
            check(lib.tirenv_nn_road_alloc(net._nn, R0, contact_length, profile._p, ffi.NULL,
                                           out, diag), diag)
        self._r = ffi.gc(out[0], lib.tirenv_nn_road_free)
        self.profile = profile
        self._lock = threading.Lock()
        info = lib.tirenv_nn_road_info_of(self._r)
        self.obstacles = info.obstacles
        self.outside_training = {"height_below": info.height_below,
                                 "height_above": info.height_above,
                                 "length_below": info.length_below,
                                 "length_above": info.length_above}

    def eval(self, x):
        """(h, slope) at centre positions x (m): h m, slope dh/dx; floats for a scalar x."""
        scalar = is_scalar(x)
        x = doubles(x, "x")
        h, slope, diag = np.empty(x.size), np.empty(x.size), new_diag()
        with self._lock:
            check(lib.tirenv_nn_road_eval(self._r, x.size, double_ptr(x), double_ptr(h),
                                          double_ptr(slope), diag), diag)
        return one_or_all(h, scalar), one_or_all(slope, scalar)
