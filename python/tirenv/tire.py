# SPDX-License-Identifier: GPL-3.0-or-later
"""Tires: the built-in default, or a .tir file, with keys overridden as --set does."""
from ._c import ffi, lib, check, new_diag, path_bytes


def _assignment(key, value):
    if isinstance(value, float):
        value = repr(value)  # the shortest text that reads back to the same double
    return f"{key}={value}".encode()


class Tire:
    """Tire() is the built-in default tire (data/tires/default.tir); Tire(path) reads a .tir
    file over it; set={"KEY": value} overrides keys of the file (RADIAL_STIFFNESS=1.6e6, as
    the CLI's --set KEY=VALUE). The result is checked (tirenv_tire_check)."""

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

    def write(self, path):
        """Writes the tire as a .tir file (all or nothing)."""
        diag = new_diag()
        check(lib.tirenv_tir_write(path_bytes(path), self._t, diag), diag)

    def __repr__(self):
        return f"<tirenv.Tire {self.path or 'default'}, R0 {self.R0:g} m>"
