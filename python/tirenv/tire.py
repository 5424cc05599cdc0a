# SPDX-License-Identifier: Apache-2.0
"""Tires: the built-in default, or a .tir file, with keys overridden as --set does; the keys
read back as a mapping."""
import collections
import collections.abc
import os
import stat
import warnings

from ._c import ffi, lib, check, check_set, new_diag, path_bytes


def _assignment(key, value):
    if isinstance(value, float):
        value = repr(value)  # the shortest text that reads back to the same double
    return f"{key}={value}".encode()


def _keys():
    """The keys in file order; one that two sections share (CONTACT) as SECTION.KEY, the
    form tirenv_tir_get and --set take for it."""
    pairs, i, section = [], 0, ffi.new("char **")
    while (k := lib.tirenv_tir_key(i, section)) != ffi.NULL:
        pairs.append((ffi.string(section[0]).decode(), ffi.string(k).decode()))
        i += 1
    counts = collections.Counter(key for _, key in pairs)
    return tuple(f"{sec}.{key}" if counts[key] > 1 else key for sec, key in pairs)


class Tire(collections.abc.Mapping):
    """Tire() is the built-in default tire (data/tires/default.tir); Tire(path) reads a .tir
    file over it; set={"KEY": value} overrides keys of the file (RADIAL_STIFFNESS=1.6e6, as
    the CLI's --set KEY=VALUE). The result is checked (tirenv_tire_check).

    A read-only mapping of its keys, as a .tir file names them (tirenv_tir_get):
    tire["RADIAL_STIFFNESS"] is a float in SI units, tire["MAX_ITERATIONS"] an int,
    tire["METHOD"] a str; keys(), items(), "KEY" in tire, len(tire) as for a dict. A key
    that is not one raises KeyError. To change one, make a new Tire with set=."""

    def __init__(self, path=None, set=None):
        self._t = ffi.new("tirenv_tire *")
        self._t[0] = lib.tirenv_tire_default()
        diag = new_diag()
        self._origin = ffi.new("tirenv_tir_origin *")
        if path is not None:
            # The models the file has no section for, derived from its MF-Tyre keys as every
            # CLI command does (tirenv_tir_read_derive, docs/models.md section 14.2): the same C
            # function, so the same tire, on one read of the file, which may be a pipe; what
            # it derived is said as the CLI says it on standard error, as a warning.
            check(lib.tirenv_tir_read_derive(path_bytes(path), self._t, 0, self._origin,
                                             diag), diag)
            if self._origin.note[0] != b"\0":
                warnings.warn(f"{path}: {self.derived_note}", stacklevel=2)
        if set is not None and not isinstance(set, collections.abc.Mapping):
            raise TypeError(f"set: expected a mapping of keys to values such as "
                            f"{{'RADIAL_STIFFNESS': 1.6e6}}, got {type(set).__name__}")
        for key, value in (set or {}).items():
            check_set(lib.tirenv_tir_set(self._t, _assignment(key, value), diag), diag)
        check(lib.tirenv_tire_check(self._t, diag), diag)
        self.path = path

    @property
    def derived_note(self):
        """Which values were derived from the file's MF-Tyre keys (the CLI's standard-error
        note), or "" when the file has every section or the tire is the default."""
        return ffi.string(self._origin.note).decode()

    @property
    def derived(self):
        """The models derived from the file's MF-Tyre keys: a subset of {"springs", "ring",
        "cam"} (the cam's contact-length law Q_RA1, Q_RA2, or its vertical law's Q_FZ2)."""
        bits = self._origin.derived
        cam = lib.TIRENV_TIR_CAM | lib.TIRENV_TIR_VERTICAL
        return frozenset(name for name, bit in (("springs", lib.TIRENV_TIR_SPRINGS),
                                                ("ring", lib.TIRENV_TIR_RING),
                                                ("cam", cam)) if bits & bit)

    def _require(self, bits):
        """Refuses, naming the missing key, a model that neither the file nor its MF-Tyre
        keys describe (as the CLI refuses it for a command that uses the model). Only the
        springs and ring models are refused so (the cam names its own missing keys)."""
        bits &= lib.TIRENV_TIR_SPRINGS | lib.TIRENV_TIR_RING
        if self.path is None or not bits & ~(self._origin.own | self._origin.derived):
            return
        t, origin, diag = ffi.new("tirenv_tire *"), ffi.new("tirenv_tir_origin *"), new_diag()
        # The missing key is named by reading the file again, which a pipe (or any file but a
        # regular one) cannot give: refused naming the file, as the CLI refuses a pipe it
        # would read twice, rather than waiting for ever on a second writer.
        try:
            regular = stat.S_ISREG(os.stat(self.path).st_mode)
        except OSError:
            regular = True  # gone: the read below says so
        if not regular:
            name = path_bytes(self.path)
            diag.file = name[:ffi.sizeof(diag.file) - 1]
            models = " and ".join(m for m, b in (("springs", lib.TIRENV_TIR_SPRINGS),
                                                 ("ring", lib.TIRENV_TIR_RING)) if bits & b)
            diag.message = (f"not a regular file (a pipe can be read only once): the {models} "
                            f"model needs a section the file neither has nor derives, named "
                            f"by reading the file again; expected a regular file").encode()
            check(lib.TIRENV_EIO, diag)
        t[0] = lib.tirenv_tire_default()
        check(lib.tirenv_tir_read_derive(path_bytes(self.path), t, bits, origin, diag), diag)

    def _require_cam_shape(self):
        """Refuses the cam for a tire without a value of its own for every cam key, naming the
        keys and the file: its shape (ELLIPS_*) is never derived, and the default tire's would
        stand in (tirenv_tire_check_cam_keys, as the CLI and the FMU refuse it)."""
        diag = new_diag()
        status = lib.tirenv_tire_check_cam_keys(self._t, diag)
        if status and self.path is not None:
            name = path_bytes(self.path)
            diag.file = name[:ffi.sizeof(diag.file) - 1]
        check(status, diag)

    @property
    def R0(self):
        """Free radius, m."""
        return self._t.springs.R0

    def __getitem__(self, key):
        if not isinstance(key, str):
            raise KeyError(key)
        buf, kind, diag = ffi.new("char[64]"), ffi.new("tirenv_tir_kind *"), new_diag()
        if lib.tirenv_tir_get(self._t, key.encode(), buf, len(buf), kind, diag):
            raise KeyError(key)
        text = ffi.string(buf).decode()
        if kind[0] == lib.TIRENV_TIR_COUNT:
            return int(text)
        if kind[0] == lib.TIRENV_TIR_NAME:
            return text
        return float(text)  # the shortest text of the double: the same double back

    def __iter__(self):
        return iter(_keys())

    def __len__(self):
        return len(_keys())

    def write(self, path):
        """Writes the tire as a .tir file (all or nothing)."""
        diag = new_diag()
        check(lib.tirenv_tir_write(path_bytes(path), self._t, diag), diag)

    def __repr__(self):
        return f"<tirenv.Tire {self.path or 'default'}, R0 {self.R0:g} m>"
