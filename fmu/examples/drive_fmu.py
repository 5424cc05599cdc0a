#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Drives tirenv's FMU as a co-simulation master would, with nothing but Python's standard
library: a wheel rolling at 10 km/h over the FMU's default road (100 m of ISO 8608 class C)
with the cam model at 20 kN, one FMI 2.0 step every 10 ms; prints what the wheel follows.

    /usr/bin/python3 fmu/examples/drive_fmu.py build/tirenv_effective_road.fmu
"""
import ctypes
import os
import shutil
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

fmu_path = sys.argv[1] if len(sys.argv) > 1 else "build/tirenv_effective_road.fmu"
where = tempfile.mkdtemp()
zipfile.ZipFile(fmu_path).extractall(where)
desc = ET.parse(os.path.join(where, "modelDescription.xml")).getroot()
vr = {v.get("name"): int(v.get("valueReference")) for v in desc.iter("ScalarVariable")}
so = ctypes.CDLL(os.path.join(where, "binaries", "linux64", "tirenv_effective_road.so"))

# fmi2CallbackFunctions: logger, allocateMemory, freeMemory, stepFinished, environment
LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int,
                          ctypes.c_char_p, ctypes.c_char_p)
libc = ctypes.CDLL(None)


class Callbacks(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ctypes.c_void_p),
                ("freeMemory", ctypes.c_void_p), ("stepFinished", ctypes.c_void_p),
                ("componentEnvironment", ctypes.c_void_p)]


def log(env, name, status, category, message):
    print(f"FMU {category.decode()}: {message.decode()}", file=sys.stderr)


callbacks = Callbacks(LOGGER(log), ctypes.cast(libc.calloc, ctypes.c_void_p),
                      ctypes.cast(libc.free, ctypes.c_void_p), None, None)
so.fmi2Instantiate.restype = ctypes.c_void_p
so.fmi2Instantiate.argtypes = [ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                               ctypes.c_char_p, ctypes.POINTER(Callbacks), ctypes.c_int,
                               ctypes.c_int]
so.fmi2DoStep.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int]
for f in ("fmi2EnterInitializationMode", "fmi2ExitInitializationMode", "fmi2FreeInstance"):
    getattr(so, f).argtypes = [ctypes.c_void_p]
resources = ("file://" + os.path.join(where, "resources")).encode()
c = so.fmi2Instantiate(b"front-left", 1, desc.get("guid").encode(), resources,
                       ctypes.byref(callbacks), 0, 0)


def set_real(**values):
    refs = (ctypes.c_uint * len(values))(*[vr[k] for k in values])
    assert so.fmi2SetReal(ctypes.c_void_p(c), refs, len(values),
                          (ctypes.c_double * len(values))(*values.values())) == 0


def get_real(*names):
    refs, out = (ctypes.c_uint * len(names))(*[vr[n] for n in names]), (ctypes.c_double * len(names))()
    assert so.fmi2GetReal(ctypes.c_void_p(c), refs, len(names), out) == 0
    return list(out)


model = (ctypes.c_char_p * 1)(b"cam")
assert so.fmi2SetString(ctypes.c_void_p(c), (ctypes.c_uint * 1)(vr["model"]), 1, model) == 0
so.fmi2EnterInitializationMode(c)
set_real(x=0.0, load=20000.0)
assert so.fmi2ExitInitializationMode(c) == 0
speed, dt, t, peak = 10 / 3.6, 0.01, 0.0, 0.0
print("   t_s     x_m      h_mm   slope   terrain_normal.x")
for k in range(3600):  # 36 s: the 100 m road
    set_real(x=speed * (t + dt), load=20000.0)
    assert so.fmi2DoStep(ctypes.c_void_p(c), t, dt, 1) == 0
    t += dt
    h, slope, nx = get_real("h", "slope", "terrain_normal.x")
    peak = max(peak, abs(h))
    if k % 400 == 399:
        print(f"{t:6.2f} {speed * t:7.2f} {1000 * h:9.3f} {slope:7.4f} {nx:10.5f}")
print(f"largest |h| over the road: {1000 * peak:.2f} mm")
so.fmi2FreeInstance(c)
shutil.rmtree(where)
