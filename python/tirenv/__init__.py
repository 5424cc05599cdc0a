# SPDX-License-Identifier: GPL-3.0-or-later
"""tirenv from Python: the quasi-static enveloping models of a tire over obstacles and roads,
the empirical network, the tractor ride and ISO 2631-1 comfort, over libtirenv (python/README.md).

    import tirenv
    m = tirenv.Model("springs", tirenv.Tire())
    m.set(tirenv.Profile.cleat(0.10, 0.10), m.load_for_contact_length(0.28))
    curve = m.envelope(tirenv.positions(-1.0, 1.0, 0.001))   # curve["h_m"], curve["slope"], ...

Errors of the library raise TirenvError carrying its diagnostic (file, line, field, message).
Every long loop (an envelope over many positions, a ride) is one library call, during which
cffi releases the GIL."""
from ._c import TirenvError
from .model import Flat, Model, POINT_DTYPE, model_names, positions, track_positions
from .network import Network, NetworkRoad
from .profile import Profile
from .ride import Metrics, Ride, SAMPLE_DTYPE, Vehicle, comfort, ride, total_value
from .tire import Tire

__all__ = ["TirenvError", "Tire", "Model", "Profile", "Network", "NetworkRoad", "Vehicle",
           "Ride", "Flat", "Metrics", "ride", "comfort", "total_value", "positions",
           "track_positions", "model_names", "POINT_DTYPE", "SAMPLE_DTYPE"]
