# SPDX-License-Identifier: Apache-2.0
"""tirenv from Python: the quasi-static enveloping models of a tire over obstacles and roads,
the empirical network, the tractor ride and ISO 2631-1 comfort, over libtirenv (python/README.md).

    import tirenv
    m = tirenv.Model("springs", tirenv.Tire())
    m.set(tirenv.Profile.cleat(0.10, 0.10), m.load_for_contact_length(0.28))
    curve = m.envelope(tirenv.positions(-1.0, 1.0, 0.001))   # curve["h_m"], curve["slope"], ...

Errors of the library raise TirenvError carrying its diagnostic (file, line, field, message),
as a subclass that is also the builtin exception expected: FileNotFoundError or OSError for a
file, ValueError for a bad value or file content, MemoryError, RuntimeError for an iteration
that did not converge. What a model warns of while it computes (tirenv_model_warnings) is
issued once as a TirenvWarning (the warnings module). Functions of positions take a scalar and return a scalar, or an array
and return an array.
Every long loop (an envelope over many positions, a ride) is one library call, during which
cffi releases the GIL."""
from ._c import (TirenvError, TirenvFileNotFoundError, TirenvMemoryError, TirenvOSError,
                 TirenvRuntimeError, TirenvValueError, TirenvWarning, lib as _lib)
from .model import Flat, Model, POINT_DTYPE, model_names, positions, track_positions
from .network import Network, NetworkRoad
from .profile import Profile
from .ride import Metrics, Ride, SAMPLE_DTYPE, Vehicle, comfort, ride, total_value
from .tire import Tire

# The version of the headers the module was built against: the project's (CMakeLists.txt).
__version__ = (f"{_lib.TIRENV_VERSION_MAJOR}.{_lib.TIRENV_VERSION_MINOR}."
               f"{_lib.TIRENV_VERSION_PATCH}")

__all__ = ["__version__", "TirenvError", "TirenvValueError", "TirenvOSError",
           "TirenvFileNotFoundError", "TirenvMemoryError", "TirenvRuntimeError", "TirenvWarning",
           "Tire",
           "Model", "Profile", "Network", "NetworkRoad", "Vehicle", "Ride", "Flat", "Metrics", "ride", "comfort", "total_value", "positions",
           "track_positions", "model_names", "POINT_DTYPE", "SAMPLE_DTYPE"]
