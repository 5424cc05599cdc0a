# SPDX-License-Identifier: Apache-2.0
"""The compiled side (cffi, API mode: tirenv_build.py), the exception, and small helpers
shared by the modules of the package."""
import errno
import os

import numpy as np

from ._native import ffi, lib


class TirenvError(Exception):
    """A failure reported by the library: status (a TIRENV_ code), status_name, and the
    diagnostic's file, line, column, field and message; str() is the library's one-line
    "file:line:column: field: message".

    What is raised is a subclass that is also the builtin exception a Python caller expects
    (error_class): TirenvFileNotFoundError (FileNotFoundError) and TirenvOSError (OSError)
    for a file that cannot be opened, read or written, TirenvValueError (ValueError) for a
    bad value, a malformed file or a load or obstacle outside a model's domain,
    TirenvMemoryError (MemoryError), TirenvRuntimeError (RuntimeError) for an iteration
    that did not converge. Catching TirenvError catches them all."""

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

    def __str__(self):
        # OSError's own str() would be "[Errno 2] ...: 'file'", without line and field.
        return str(self.args[0]) if self.args else ""


class TirenvValueError(TirenvError, ValueError):
    """A bad value, a malformed file, a load or obstacle outside a model's domain."""


class TirenvOSError(TirenvError, OSError):
    """A file that could not be opened, read or written (errno and filename set when known)."""


class TirenvFileNotFoundError(TirenvOSError, FileNotFoundError):
    """A file that does not exist."""


class TirenvMemoryError(TirenvError, MemoryError):
    """An allocation failed."""


class TirenvRuntimeError(TirenvError, RuntimeError):
    """An iteration stopped before meeting its tolerances."""


class TirenvWarning(UserWarning):
    """What a model warns of (tirenv_model_warnings): a network's input outside its training
    range, a cam touching the ground higher above its lowest point than the tire's
    ELLIPS_MAX_STEP. The result is computed all the same."""


def error_class(status, file=""):
    """The TirenvError subclass for a status (and, for a file error, whether file exists)."""
    if status == lib.TIRENV_EIO:
        return TirenvOSError if file and os.path.lexists(file) else TirenvFileNotFoundError
    if status == lib.TIRENV_ENOMEM:
        return TirenvMemoryError
    if status == lib.TIRENV_ENOCONV:
        return TirenvRuntimeError
    return TirenvValueError


def new_diag():
    d = ffi.new("tirenv_diag *")
    lib.tirenv_diag_clear(d)
    return d


def error_from(status, diag):
    buf = ffi.new("char[2048]")
    text = ffi.string(lib.tirenv_diag_format(diag, buf, len(buf))).decode(errors="replace")
    if not text:
        text = ffi.string(lib.tirenv_strerror(status)).decode()
    file = ffi.string(diag.file).decode(errors="replace")
    cls = error_class(status, file)
    e = cls(status, ffi.string(diag.message).decode(errors="replace"), file, diag.line,
            diag.column, ffi.string(diag.field).decode(errors="replace"), text)
    if issubclass(cls, OSError) and file:
        e.filename = file
        if cls is TirenvFileNotFoundError:
            e.errno, e.strerror = errno.ENOENT, os.strerror(errno.ENOENT)
    return e


def check_set(status, diag):
    """check() for a set={...} assignment: the library names its source "--set", the CLI's
    option; here it is the set argument."""
    if status and ffi.string(diag.file) == b"--set":
        diag.file = b"set"
    check(status, diag)


def check(status, diag):
    if status:
        raise error_from(status, diag)


def invalid(message, field=""):
    """A TirenvValueError for an argument the Python layer refuses before calling the
    library."""
    text = f"{field}: {message}" if field else message
    return TirenvValueError(lib.TIRENV_EINVAL, message, field=field, text=text)


def expect(value, cls, what, hint=""):
    """value, or a TypeError naming the argument when it is not a cls: the attribute error
    from deep inside ('str' object has no attribute '_require') named neither."""
    if not isinstance(value, cls):
        raise TypeError(f"{what}: expected a tirenv.{cls.__name__}{hint}, got "
                        f"{type(value).__name__}")
    return value


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
        raise invalid(f"expected a 1-D array, got shape {a.shape}", what)
    a = np.ascontiguousarray(a.reshape(-1), dtype=np.float64)
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size:
        raise invalid(f"{what}[{bad[0]}] = {a[bad[0]]}: not a finite number", what)
    return a


def is_scalar(values):
    """Whether values is one number (a Python or numpy scalar, or a 0-d array): the functions
    that map positions to values then return one value, as numpy's ufuncs do."""
    return np.ndim(values) == 0


def one_or_all(a, scalar):
    """a[0] as a Python float (a record of a structured array as itself) if scalar, else a."""
    if not scalar:
        return a
    return float(a[0]) if a.dtype.names is None else a[0]


def double_ptr(a):
    return ffi.cast("double *", ffi.from_buffer(a))


def struct_dtype(ctype, fields):
    """A numpy dtype laid out exactly as the C struct ctype (offsets and size from the
    compiler), with fields [(numpy name, C field, numpy format)]."""
    return np.dtype({"names": [f[0] for f in fields], "formats": [f[2] for f in fields],
                     "offsets": [ffi.offsetof(ctype, f[1]) for f in fields],
                     "itemsize": ffi.sizeof(ctype)})
