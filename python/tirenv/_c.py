# SPDX-License-Identifier: GPL-3.0-or-later
"""The compiled side (cffi, API mode: tirenv_build.py), the exception, and small helpers
shared by the modules of the package."""
import os

import numpy as np

from ._native import ffi, lib


class TirenvError(Exception):
    """A failure reported by the library: status (a TIRENV_ code), status_name, and the
    diagnostic's file, line, column, field and message; str() is the library's one-line
    "file:line:column: field: message"."""

    def __init__(self, status, message, file="", line=0, column=0, field="", text=None):
        self.status = status
        self.status_name = ffi.string(lib.tirenv_strerror(status)).decode()
        self.message = message
        self.file = file
        self.line = line
        self.column = column
        self.field = field
        self.index = None  # the failing position's index in an envelope, where there is one
        super().__init__(text if text is not None else message)


def new_diag():
    d = ffi.new("tirenv_diag *")
    lib.tirenv_diag_clear(d)
    return d


def error_from(status, diag):
    buf = ffi.new("char[2048]")
    text = ffi.string(lib.tirenv_diag_format(diag, buf, len(buf))).decode(errors="replace")
    if not text:
        text = ffi.string(lib.tirenv_strerror(status)).decode()
    return TirenvError(status, ffi.string(diag.message).decode(errors="replace"),
                       ffi.string(diag.file).decode(errors="replace"), diag.line, diag.column,
                       ffi.string(diag.field).decode(errors="replace"), text)


def check(status, diag):
    if status:
        raise error_from(status, diag)


def invalid(message, field=""):
    """A TirenvError for an argument the Python layer refuses before calling the library."""
    text = f"{field}: {message}" if field else message
    return TirenvError(lib.TIRENV_EINVAL, message, field=field, text=text)


def path_bytes(path):
    return os.fsencode(path)


def doubles(values, what):
    """values as a C-contiguous float64 vector (a copy only when needed): any real dtype,
    any strides, a scalar as one element. Refuses complex, object and string data, more
    than one dimension, and non-finite values, naming the first."""
    a = np.asarray(values)
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{what}: expected real numbers, got an array of dtype {a.dtype}")
    if a.ndim > 1:
        raise ValueError(f"{what}: expected a 1-D array, got shape {a.shape}")
    a = np.ascontiguousarray(a.reshape(-1), dtype=np.float64)
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size:
        raise ValueError(f"{what}[{bad[0]}] = {a[bad[0]]}: not a finite number")
    return a


def double_ptr(a):
    return ffi.cast("double *", ffi.from_buffer(a))


def struct_dtype(ctype, fields):
    """A numpy dtype laid out exactly as the C struct ctype (offsets and size from the
    compiler), with fields [(numpy name, C field, numpy format)]."""
    return np.dtype({"names": [f[0] for f in fields], "formats": [f[2] for f in fields],
                     "offsets": [ffi.offsetof(ctype, f[1]) for f in fields],
                     "itemsize": ffi.sizeof(ctype)})
