# SPDX-License-Identifier: Apache-2.0
"""Enveloping models over a profile at constant vertical load (tirenv/model.h)."""
import collections
import threading
import warnings as _warnings

import numpy as np

from ._c import (TirenvWarning, ffi, lib, check, doubles, double_ptr, error_from, expect, invalid,
                 is_scalar, new_diag, one_or_all, struct_dtype)
from .network import Network
from .profile import Profile
from .tire import Tire

# One row of 'tirenv envelope's CSV, laid out as the library's tirenv_point, so that the
# library writes straight into the array.
POINT_DTYPE = struct_dtype("tirenv_point", [
    ("x_m", "x", "f8"), ("z_m", "z", "f8"), ("h_m", "h", "f8"), ("slope", "slope", "f8"),
    ("fx_N", "fx", "f8"), ("fz_N", "fz", "f8"),
    ("contacts", "contacts", np.uintp), ("iterations", "iterations", np.uintp)])

Flat = collections.namedtuple("Flat", "load z_flat deflection contact_length stiffness")
Flat.__doc__ = "The tire on flat ground: load N, centre height m, deflection m, " \
               "contact length m, vertical stiffness N/m."


def model_names():
    """Names of the model types of the library's table."""
    types = lib.tirenv_model_types()
    names, i = [], 0
    while types[i] != ffi.NULL:
        names.append(ffi.string(lib.tirenv_model_type_name(types[i])).decode())
        i += 1
    return names


TRACKS_MAX = 64  # as 'tirenv envelope --tracks' takes them


def track_positions(n, track=0.0, width=0.38):
    """The lateral positions (m) of n tracks spread over a tire of width (m) around track
    (m): the centres of n equal slices, as 'tirenv envelope --tracks N --width W --track V'
    places them (docs/models.md section 13); n from 1 to TRACKS_MAX (64), as there."""
    if not (isinstance(n, (int, np.integer)) and 1 <= n <= TRACKS_MAX):
        raise invalid(f"expected a whole number of tracks from 1 to {TRACKS_MAX} (as 'tirenv "
                      f"envelope --tracks'), got {n!r}", "n")
    out, diag = ffi.new("double[]", int(n)), new_diag()
    check(lib.tirenv_tracks_spread(int(n), track, width, out, diag), diag)
    return np.frombuffer(ffi.buffer(out), dtype=np.float64).copy()


def positions(x_from, x_to, dx=None):
    """The CLI's sweep x_k = x_from + k*dx up to x_to (with its 1e-9 dx allowance), bit for
    bit the positions 'tirenv envelope --x-from --x-to --dx' evaluates; dx (m) by default
    the CLI's (tirenv_positions_default). Ends that are not finite, more than 1e12 positions
    or a dx too small to move x raise TirenvError (tirenv_positions_count gives 0)."""
    if dx is None:  # the default sweep's spacing, which does not depend on its ends
        dx = lib.tirenv_positions_default(x_from, x_to, 0.0).dx
    if not (dx > 0 and x_to >= x_from):
        raise invalid(f"expected dx > 0 and x_to >= x_from, got dx {dx} from {x_from} to "
                      f"{x_to}", "dx")
    n = lib.tirenv_positions_count(x_from, x_to, dx)
    if n == 0:  # not finite, more than TIRENV_POSITIONS_MAX, or a step that does not move x
        raise invalid(f"expected finite ends, at most 1e12 positions (TIRENV_POSITIONS_MAX) "
                      f"and x + dx != x, got dx {dx} from {x_from} to {x_to}", "dx")
    return x_from + np.arange(n, dtype=np.float64) * dx


class Model:
    """A model of the library's table ("rigid", "springs", "ring", "cam", "point", and "nn",
    which needs network=Network(path)) for a tire (default: Tire()). The network refuses input
    outside its trained ranges unless extrapolate=True (tirenv_model_set_extrapolate). Not
    shareable between threads at once: calls on one model are serialised."""

    def __init__(self, name, tire=None, network=None, extrapolate=False):
        self.tire = expect(tire, Tire, "tire", " (Tire(path) reads a .tir file)") \
            if tire is not None else Tire()
        if network is not None:
            expect(network, Network, "network", " (Network(path) reads a model file)")
        t = lib.tirenv_model_type_find(str(name).encode())
        if t == ffi.NULL:
            raise invalid(f"unknown model {name!r}; expected one of "
                          f"{', '.join(model_names())}", "model")
        needs_network = bool(lib.tirenv_model_type_flags(t) & lib.TIRENV_MODEL_NEEDS_NETWORK)
        if needs_network and network is None:
            raise invalid(f"the {name} model needs network=Network(path)", "network")
        # The models that must describe this tire, by the library's one rule (tirenv_tir_need;
        # a Tire serves every model, so none is alone); a network whose file records no
        # contact law takes the springs model's, as the CLI's does.
        needs = lib.tirenv_tir_need(t, 0)
        if needs_network and not network._law.n:
            needs |= lib.TIRENV_TIR_SPRINGS
        self.tire._require(needs)
        if needs & lib.TIRENV_TIR_CAM:
            self.tire._require_cam_shape()
        # The rigid disc's and the point's load at a contact length is the springs model's
        # (load_for_contact_length requires it, as the CLI's --contact-length does).
        flags = lib.tirenv_model_type_flags(t)
        self._at_chord = not flags & (lib.TIRENV_MODEL_CONTACT_LENGTH |
                                      lib.TIRENV_MODEL_NEEDS_NETWORK)
        m = lib.tirenv_model_alloc(t, self.tire._t)
        if m == ffi.NULL:
            raise invalid("the tire's parameters are not valid for this model")
        self._m = ffi.gc(m, lib.tirenv_model_free)
        lib.tirenv_model_set_extrapolate(self._m, 1 if extrapolate else 0)
        self.network = network  # kept alive with the model
        if needs_network:
            diag = new_diag()
            with network._lock:
                check(lib.tirenv_model_set_network(self._m, network._nn,
                                                   network.R0 if network.R0 else 0.0, diag),
                      diag)
            if network._law.n:
                check(lib.tirenv_model_set_contact_law(self._m, network._law, diag), diag)
        self._lock = threading.Lock()
        self.profile = None   # the profile set: kept alive here, the library borrows it
        self.load = None
        self._tracks = None   # several tracks set: all of them and the weights, kept alive
        self._warned = ()     # the warnings issued since the last set

    @property
    def name(self):
        return ffi.string(lib.tirenv_model_name(self._m)).decode()

    @property
    def reach(self):
        """How far from a position the model reads the profile, m."""
        return lib.tirenv_model_reach(self._m)

    def load_for_contact_length(self, l_c):
        """The load (N) at which the flat-ground contact length is l_c (m)."""
        if self._at_chord:
            self.tire._require(lib.TIRENV_TIR_SPRINGS)
        load, diag = ffi.new("double *"), new_diag()
        with self._lock:
            check(lib.tirenv_model_load_for_contact_length(self._m, l_c, load, diag), diag)
        return load[0]

    def flat(self, load):
        """The tire on flat ground at load (N): a Flat."""
        out, diag = ffi.new("tirenv_flat *"), new_diag()
        with self._lock:
            check(lib.tirenv_model_flat(self._m, load, out, diag), diag)
        return Flat(out.load, out.z_flat, out.deflection, out.contact_length, out.stiffness)

    def set(self, profile, load, weights=None):
        """Sets the ground profile and the load (N); resets the warm start. profile may be a
        list of profiles, the tracks across the tire's width (tirenv_model_set_tracks,
        docs/models.md section 13), with weights (default equal); the model then combines
        them by its type's rule (springs and ring: one equilibrium of the slices)."""
        diag = new_diag()
        for p in profile if isinstance(profile, (list, tuple)) else (profile,):
            if not isinstance(p, Profile):
                raise TypeError(f"profile: expected a tirenv.Profile or a list of them, got "
                                f"{type(p).__name__}")
        if isinstance(profile, (list, tuple)):
            tracks = list(profile)
            if not tracks:
                raise invalid("expected at least one track", "tracks")
            w = ffi.NULL
            if weights is not None:
                w = doubles(weights, "weights")
                if w.size != len(tracks):
                    raise invalid(f"{len(tracks)} tracks and {w.size} weights", "weights")
            ps = ffi.new("const tirenv_profile *[]", [t._p for t in tracks])
            with self._lock:
                before = self.profile, self._tracks  # alive through the call, which may read
                self.profile = self.load = self._tracks = None  # them; unset if it fails
                check(lib.tirenv_model_set_tracks(self._m, len(tracks), ps,
                                                  w if w is ffi.NULL else double_ptr(w), load,
                                                  diag), diag)
                # the first track gives the sweep's extent; all are kept alive with the model
                self.profile, self.load, self._tracks = tracks[0], load, (tracks, w)
                self._warned = ()
            self._warn()
            return self
        with self._lock:
            # A set that fails leaves the library's model unset: so is this one, rather than
            # still naming the profile and load of the set before (kept alive through the
            # call, which may read them).
            before = self.profile, self._tracks
            self.profile = self.load = self._tracks = None
            check(lib.tirenv_model_set(self._m, profile._p, load, diag), diag)
            self.profile, self.load, self._tracks = profile, load, None
            self._warned = ()
        self._warn()
        return self

    @property
    def warnings(self):
        """What the model warns of since the last set(), one line each (tirenv_model_warnings:
        a network's input outside its training range, the cam touching the ground higher
        above its lowest point than the tire's ELLIPS_MAX_STEP); () if nothing."""
        with self._lock:
            text = ffi.string(lib.tirenv_model_warnings(self._m)).decode()
        return tuple(text.splitlines())

    def _warn(self):
        """Issues the warnings not issued since the last set() as TirenvWarning."""
        said = self.warnings
        new = [w for w in said if w not in self._warned]
        self._warned = said
        for w in new:
            _warnings.warn(w, TirenvWarning, stacklevel=3)

    def envelope(self, x):
        """The equilibrium at each position x (m), in order, warm-started from the previous:
        a structured array with the envelope CSV's fields x_m, z_m, h_m, slope, fx_N, fz_N,
        contacts, iterations. x may be any 1-D real array (copied to float64 if needed).
        One library call, with the GIL released. TirenvError (with .index) if a position
        has no equilibrium. A scalar x gives one record."""
        if self.profile is None:
            raise invalid("no profile: call set(profile, load) first")
        scalar = is_scalar(x)
        x = doubles(x, "x")
        out = np.zeros(x.size, dtype=POINT_DTYPE)
        failed, diag = ffi.new("size_t *"), new_diag()
        with self._lock:
            status = lib.tirenv_model_envelope(self._m, x.size, double_ptr(x),
                                               ffi.cast("tirenv_point *", ffi.from_buffer(out)),
                                               failed, diag)
        if status:
            e = error_from(status, diag)
            e.index = failed[0]
            raise e
        self._warn()
        return one_or_all(out, scalar)

    def sweep(self, x_from=None, x_to=None, dx=None):
        """envelope() over 'tirenv envelope's positions: the library's default sweep of the
        tire over the profile (tirenv_positions_default: from R0 and a margin before its first
        vertex to as far after its last), each of x_from, x_to, dx (m) given replacing its
        part, as --x-from, --x-to and --dx do."""
        if self.profile is None:
            raise invalid("no profile: call set(profile, load) first")
        first, last = self.profile.extent
        s = lib.tirenv_positions_default(first, last, self.tire.R0)
        return self.envelope(positions(s.x_from if x_from is None else x_from,
                                       s.x_to if x_to is None else x_to,
                                       s.dx if dx is None else dx))

    def __repr__(self):
        return f"<tirenv.Model {self.name}, {self.tire!r}>"
