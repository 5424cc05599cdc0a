# SPDX-License-Identifier: Apache-2.0
"""Ground profiles: polylines (x, z) in m, from the library's generators, a road file, or
arrays (docs/models.md section 2)."""
import math

import numpy as np

from ._c import (ffi, lib, check, doubles, double_ptr, invalid, is_scalar, new_diag, one_or_all,
                 path_bytes)


class Profile:
    """An immutable ground profile. Build one with Profile(x, z) or the class methods."""

    def __init__(self, x, z):
        x = doubles(x, "x")
        z = doubles(z, "z")
        if x.size != z.size:
            raise ValueError(f"x and z differ in length: {x.size} and {z.size}")
        diag = new_diag()
        check(lib.tirenv_profile_validate(x.size, double_ptr(x), double_ptr(z), diag), diag)
        self._adopt(lib.tirenv_profile_alloc(x.size, double_ptr(x), double_ptr(z)),
                    "out of memory")

    def _adopt(self, p, why):
        if p == ffi.NULL:
            raise invalid(why)
        self._p = ffi.gc(p, lib.tirenv_profile_free)

    @classmethod
    def _from(cls, p, why):
        self = cls.__new__(cls)
        self._adopt(p, why)
        return self

    # --- generators: obstacles on flat ground z = 0, centred at x = 0 unless noted --------
    @classmethod
    def cleat(cls, length, height):
        """A rectangular cleat length x height (m)."""
        return cls._from(lib.tirenv_profile_cleat(length, height),
                         f"cleat {length} x {height}: expected positive sizes")

    @classmethod
    def step(cls, x0, height):
        """A step of height (m; negative: down) at x0 (m)."""
        return cls._from(lib.tirenv_profile_step(x0, height),
                         f"step at {x0} of {height}: expected a finite x0 and a nonzero height")

    @classmethod
    def trapezoid(cls, top_length, base_length, height):
        return cls._from(lib.tirenv_profile_trapezoid(top_length, base_length, height),
                         f"trapezoid {top_length}, {base_length}, {height}: expected all "
                         "positive, base_length >= top_length")

    @classmethod
    def triangle(cls, base_length, height):
        return cls._from(lib.tirenv_profile_triangle(base_length, height),
                         f"triangle {base_length} x {height}: expected positive sizes")

    @classmethod
    def cylinder(cls, radius, segments=None):
        """A half cylinder of radius (m), as a polygon of segments chords (default the
        CLI's --cylinder, tirenv_profile_resolution_default)."""
        if segments is None:
            segments = lib.tirenv_profile_resolution_default().cylinder_segments
        return cls._from(lib.tirenv_profile_half_cylinder(radius, segments),
                         f"cylinder of radius {radius} in {segments} segments: expected a "
                         "positive radius and 2 to 1e9 segments")

    @classmethod
    def sine(cls, amplitude, wavelength, periods, points_per_period=None):
        """amplitude*(1 - cos(2 pi x/wavelength)) from x = 0 over periods periods, in
        points_per_period segments a period (default the CLI's --sine,
        tirenv_profile_resolution_default)."""
        if points_per_period is None:
            points_per_period = lib.tirenv_profile_resolution_default().sine_points_per_period
        return cls._from(lib.tirenv_profile_sine(amplitude, wavelength, periods,
                                                 points_per_period),
                         f"sine {amplitude}, {wavelength}, {periods} in {points_per_period} "
                         "points a period: expected a positive amplitude, wavelength and "
                         "periods, at least 2 points a period and at most 1e9 points in all")

    @classmethod
    def road(cls, road_class="C", length=100.0, dx=0.01, seed=1, band=None, waviness=None):
        """A random road of an ISO 8608 class (as 'tirenv road'): length and dx in m, the
        phases seeded (same seed, same road bit for bit), band (n_min, n_max) in cycles/m."""
        s = ffi.new("tirenv_road_settings *")
        s[0] = lib.tirenv_road_default()
        if not (isinstance(road_class, str) and len(road_class) == 1):
            raise invalid(f"expected one letter A..H, got {road_class!r}", "class")
        s.road_class = road_class.encode()
        s.length = length
        s.dx = dx
        s.seed = seed
        if band is not None:
            s.n_min, s.n_max = band
        if waviness is not None:
            s.waviness = waviness
        out = ffi.new("tirenv_profile **")
        diag = new_diag()
        check(lib.tirenv_road_iso8608(s, out, diag), diag)
        return cls._from(out[0], "no road")

    @classmethod
    def read(cls, path, track=None, side=None):
        """A profile from a road file the CLI reads (--profile FILE), its format told by its
        content: CSV "x_m,z_m", an OpenCRG road (.crg) or a TNO/Adams 2-D road (.rdf). track
        is the lateral position (m, positive to the left; default 0) on an OpenCRG road,
        which varies across (--track); side is "left", "right" or "mean" (the default) of an
        RDF poly_line road's two sides (--side). A CSV road is 2-D, the same on every track.
        As the CLI, track is refused for a road that is not OpenCRG and side for one that is
        not RDF: they would select nothing."""
        src = ffi.new("tirenv_profile_source *")
        src[0] = lib.tirenv_profile_source_default()
        if track is not None:
            if not math.isfinite(track):
                raise invalid(f"expected a finite lateral position, got {track}", "track")
            src.crg.v = track
        if side is not None:
            side_c = ffi.new("tirenv_rdf_side *")
            if not isinstance(side, str) or lib.tirenv_rdf_side_find(side.encode(), side_c):
                raise invalid(f"expected left, right or mean, got {side!r}", "side")
            src.rdf_side = side_c[0]
        f, out, diag = ffi.new("tirenv_road_file **"), ffi.new("tirenv_profile *[1]"), new_diag()
        # the library's one road reader: the file opened once, its format told once
        check(lib.tirenv_road_file_open(path_bytes(path), f, diag), diag)
        try:
            fmt = lib.tirenv_road_file_format(f[0])
            kind = {lib.TIRENV_PROFILE_CRG: "an OpenCRG road", lib.TIRENV_PROFILE_RDF:
                    "an RDF road"}.get(fmt, "a CSV profile")
            if track is not None and fmt != lib.TIRENV_PROFILE_CRG:
                raise invalid(f"track applies to an OpenCRG road; {path} is {kind}", "track")
            if side is not None and fmt != lib.TIRENV_PROFILE_RDF:
                raise invalid(f"side applies to an RDF road; {path} is {kind}", "side")
            check(lib.tirenv_road_file_read(f[0], src, 1, ffi.NULL, out, diag), diag)
        finally:
            lib.tirenv_road_file_free(f[0])
        return cls._from(out[0], "no profile")

    # --- what it holds ---------------------------------------------------------------------
    def __len__(self):
        return lib.tirenv_profile_size(self._p)

    @property
    def x(self):
        """Vertex positions, m (a copy)."""
        return np.frombuffer(ffi.buffer(lib.tirenv_profile_x(self._p), 8 * len(self)),
                             dtype=np.float64).copy()

    @property
    def z(self):
        """Vertex heights, m (a copy)."""
        return np.frombuffer(ffi.buffer(lib.tirenv_profile_z(self._p), 8 * len(self)),
                             dtype=np.float64).copy()

    @property
    def extent(self):
        """(first, last) vertex x, m."""
        lo, hi = ffi.new("double *"), ffi.new("double *")
        lib.tirenv_profile_extent(self._p, lo, hi)
        return lo[0], hi[0]

    def height(self, x):
        """Ground height (m) at each x (m); at a wall the higher side. A scalar x gives a
        float, an array an array."""
        scalar = is_scalar(x)
        x = doubles(x, "x")
        return one_or_all(np.array([lib.tirenv_profile_height(self._p, v) for v in x]),
                          scalar)

    def __repr__(self):
        lo, hi = self.extent
        return f"<tirenv.Profile {len(self)} vertices, x {lo:g} .. {hi:g} m>"
