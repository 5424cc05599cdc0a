# SPDX-License-Identifier: Apache-2.0
"""Tires: the built-in default, or a .tir file, with keys overridden as --set does; the keys
read back as a mapping."""
import collections
import collections.abc

from ._c import ffi, lib, check, new_diag, path_bytes


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
        if path is not None:
            check(lib.tirenv_tir_read(path_bytes(path), self._t, diag), diag)
        for key, value in (set or {}).items():
            check(lib.tirenv_tir_set(self._t, _assignment(key, value), diag), diag)
        check(lib.tirenv_tire_check(self._t, diag), diag)
        self.path = path

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
