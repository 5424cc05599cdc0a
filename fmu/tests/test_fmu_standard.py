# SPDX-License-Identifier: Apache-2.0
"""A second importer of tirenv's FMU, independent of the C one and of the FMU's sources:
written from the FMI 2.0 standard's text alone (2.1.2 types, 2.1.5 callbacks, 2.2 the model
description, 2.3 the archive, 4.2 co-simulation) with Python's zipfile, xml.etree and ctypes.
Debian 12 packages no FMI importer or checker (no FMPy, FMIL or fmuCheck), so this is the
"importer that is not the FMU author's C code". It checks the description against the
standard's rules and against what the binary serves, and steps the FMU along a cleat
against 'tirenv envelope'."""
import ctypes
import os
import subprocess
import xml.etree.ElementTree as ET
import zipfile

import pytest

# --- 2.1.2: platform types "default" ---------------------------------------------------------
fmi2Component = ctypes.c_void_p
fmi2FMUstate = ctypes.c_void_p
fmi2ValueReference = ctypes.c_uint
fmi2Real = ctypes.c_double
fmi2Boolean = ctypes.c_int
fmi2String = ctypes.c_char_p
fmi2Status = ctypes.c_int
OK, WARNING, DISCARD, ERROR, FATAL, PENDING = range(6)
MODEL_EXCHANGE, CO_SIMULATION = 0, 1

# --- 2.1.5: callbacks (the logger is variadic; on this ABI a callee that takes the fixed
# arguments only is called correctly, and the FMU passes no extra arguments) -----------------
LOGGER = ctypes.CFUNCTYPE(None, ctypes.c_void_p, fmi2String, fmi2Status, fmi2String,
                          fmi2String)
ALLOC = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_size_t, ctypes.c_size_t)
FREE = ctypes.CFUNCTYPE(None, ctypes.c_void_p)
STEP_FINISHED = ctypes.CFUNCTYPE(None, ctypes.c_void_p, fmi2Status)


class CallbackFunctions(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ALLOC), ("freeMemory", FREE),
                ("stepFinished", STEP_FINISHED), ("componentEnvironment", ctypes.c_void_p)]


LIBC = ctypes.CDLL(None)


class Importer:
    """The FMU unpacked, described and loaded."""

    def __init__(self, fmu, where):
        with zipfile.ZipFile(fmu) as z:
            z.extractall(where)
        self.dir = where
        self.root = ET.parse(os.path.join(where, "modelDescription.xml")).getroot()
        cs = self.root.find("CoSimulation")
        self.identifier = cs.get("modelIdentifier")
        self.guid = self.root.get("guid")
        self.vars = {}
        for i, sv in enumerate(self.root.find("ModelVariables"), start=1):
            typ = next(iter(sv))
            self.vars[sv.get("name")] = dict(index=i, vr=int(sv.get("valueReference")),
                                             causality=sv.get("causality", "local"),
                                             variability=sv.get("variability", "continuous"),
                                             initial=sv.get("initial"), type=typ.tag,
                                             start=typ.get("start"))
        self.so = ctypes.CDLL(os.path.join(where, "binaries", "linux64",
                                           self.identifier + ".so"))
        f = self.so
        f.fmi2Instantiate.restype = fmi2Component
        f.fmi2Instantiate.argtypes = [fmi2String, ctypes.c_int, fmi2String, fmi2String,
                                      ctypes.POINTER(CallbackFunctions), fmi2Boolean,
                                      fmi2Boolean]
        f.fmi2FreeInstance.argtypes = [fmi2Component]
        f.fmi2FreeInstance.restype = None
        f.fmi2GetVersion.restype = ctypes.c_char_p
        f.fmi2GetTypesPlatform.restype = ctypes.c_char_p
        for name in ("fmi2EnterInitializationMode", "fmi2ExitInitializationMode",
                     "fmi2Terminate", "fmi2Reset"):
            getattr(f, name).argtypes = [fmi2Component]
        f.fmi2SetupExperiment.argtypes = [fmi2Component, fmi2Boolean, fmi2Real, fmi2Real,
                                          fmi2Boolean, fmi2Real]
        vrs = ctypes.POINTER(fmi2ValueReference)
        f.fmi2GetReal.argtypes = [fmi2Component, vrs, ctypes.c_size_t,
                                  ctypes.POINTER(fmi2Real)]
        f.fmi2SetReal.argtypes = f.fmi2GetReal.argtypes
        f.fmi2GetString.argtypes = [fmi2Component, vrs, ctypes.c_size_t,
                                    ctypes.POINTER(fmi2String)]
        f.fmi2SetString.argtypes = f.fmi2GetString.argtypes
        f.fmi2DoStep.argtypes = [fmi2Component, fmi2Real, fmi2Real, fmi2Boolean]
        f.fmi2GetFMUstate.argtypes = [fmi2Component, ctypes.POINTER(fmi2FMUstate)]
        f.fmi2SetFMUstate.argtypes = [fmi2Component, fmi2FMUstate]
        f.fmi2FreeFMUstate.argtypes = [fmi2Component, ctypes.POINTER(fmi2FMUstate)]
        f.fmi2GetRealStatus.argtypes = [fmi2Component, ctypes.c_int, ctypes.POINTER(fmi2Real)]
        f.fmi2CancelStep.argtypes = [fmi2Component]
        self.messages = []
        self.logger = LOGGER(self._log)
        self.callbacks = CallbackFunctions(
            self.logger, ALLOC(ctypes.cast(LIBC.calloc, ctypes.c_void_p).value),
            FREE(ctypes.cast(LIBC.free, ctypes.c_void_p).value), STEP_FINISHED(), None)

    def _log(self, env, instance, status, category, message):
        # 2.1.5: the message is a printf format; this FMU passes no arguments, so "%%" is "%"
        self.messages.append((status, category.decode(), message.decode().replace("%%", "%")))

    def instantiate(self, guid=None, kind=CO_SIMULATION):
        uri = "file://" + os.path.join(self.dir, "resources")
        return self.so.fmi2Instantiate(b"road", kind, (guid or self.guid).encode(),
                                       uri.encode(), ctypes.byref(self.callbacks), 0, 0)

    def get_real(self, c, names):
        vr = (fmi2ValueReference * len(names))(*[self.vars[n]["vr"] for n in names])
        out = (fmi2Real * len(names))()
        status = self.so.fmi2GetReal(c, vr, len(names), out)
        return status, list(out)

    def set_real(self, c, values):
        vr = (fmi2ValueReference * len(values))(*[self.vars[n]["vr"] for n in values])
        v = (fmi2Real * len(values))(*values.values())
        return self.so.fmi2SetReal(c, vr, len(values), v)

    def set_string(self, c, values):
        vr = (fmi2ValueReference * len(values))(*[self.vars[n]["vr"] for n in values])
        v = (fmi2String * len(values))(*[s.encode() for s in values.values()])
        return self.so.fmi2SetString(c, vr, len(values), v)

    def get_string(self, c, name):
        vr = (fmi2ValueReference * 1)(self.vars[name]["vr"])
        out = (fmi2String * 1)()
        status = self.so.fmi2GetString(c, vr, 1, out)
        return status, out[0].decode() if status == OK else None


@pytest.fixture()
def fmu(tmp_path):
    return Importer(os.environ["TIRENV_FMU"], str(tmp_path / "fmu"))


def test_description_follows_the_standard(fmu):
    r = fmu.root
    assert r.tag == "fmiModelDescription" and r.get("fmiVersion") == "2.0"
    assert r.get("guid") and r.get("modelName")
    assert fmu.so.fmi2GetVersion() == b"2.0"
    assert fmu.so.fmi2GetTypesPlatform() == b"default"
    assert r.find("ModelExchange") is None  # co-simulation only
    by_type = {}
    for name, v in fmu.vars.items():
        key = (v["type"], v["vr"])
        assert key not in by_type, f"{name} shares value reference {key} with {by_type[key]}"
        by_type[key] = name
        assert v["causality"] in ("parameter", "input", "output")
        # 2.2.7: a parameter is fixed or tunable and has a start value; an input has one;
        # an output is continuous and, calculated, has none
        if v["causality"] == "parameter":
            assert v["variability"] in ("fixed", "tunable") and v["start"] is not None
        elif v["causality"] == "input":
            assert v["start"] is not None
        else:
            assert v["initial"] in (None, "calculated") and v["start"] is None
    outputs = [u.get("index") for u in r.find("ModelStructure/Outputs")]
    assert sorted(map(int, outputs)) == sorted(
        v["index"] for v in fmu.vars.values() if v["causality"] == "output")
    units = {u.get("name") for u in r.find("UnitDefinitions")}
    used = {sv.find("Real").get("unit") for sv in r.find("ModelVariables")
            if sv.find("Real") is not None} - {None}
    assert used <= units


def test_what_chrono_takes(fmu):
    """Project Chrono's tire FMU takes terrain_height and terrain_normal.x/.y/.z; these are
    outputs here under the same names."""
    fmu_vars = fmu.vars
    for name in ("terrain_height", "terrain_normal.x", "terrain_normal.y",
                 "terrain_normal.z", "h", "slope", "fx", "fz"):
        assert fmu_vars[name]["causality"] == "output", name
    for name in ("x", "load"):
        assert fmu_vars[name]["causality"] == "input"
    for name in ("model", "tire_file", "road_file", "track", "width"):
        assert fmu_vars[name]["causality"] == "parameter"


def test_binary_serves_the_description(fmu):
    c = fmu.instantiate()
    assert c
    for name, v in fmu.vars.items():
        if v["causality"] == "output":
            continue
        if v["type"] == "Real":
            status, (value,) = fmu.get_real(c, [name])
            assert status == OK and value == float(v["start"]), name
        else:
            status, value = fmu.get_string(c, name)
            assert status == OK and value == v["start"], name
    taken = {v["vr"] for v in fmu.vars.values()}
    unknown = next(k for k in range(1000) if k not in taken)
    vr = (fmi2ValueReference * 1)(unknown)
    out = (fmi2Real * 1)()
    assert fmu.so.fmi2GetReal(c, vr, 1, out) == ERROR
    assert str(unknown) in fmu.messages[-1][2]
    fmu.so.fmi2FreeInstance(c)


def test_steps_along_a_cleat_as_tirenv_envelope(fmu, tmp_path):
    road = tmp_path / "cleat.csv"
    road.write_text("x_m,z_m\n-0.05,0\n-0.05,0.1\n0.05,0.1\n0.05,0\n")
    ref = tmp_path / "ref.csv"
    load, x_from, dx, n = 11903.6, -0.8, 0.001, 1601
    subprocess.run([os.environ["TIRENV_CLI"], "envelope", "--model", "cam", "--profile",
                    str(road), "--load", repr(load), "--x-from", repr(x_from), "--x-to",
                    "0.8", "--dx", repr(dx), "-o", str(ref)], check=True, capture_output=True)
    rows = [r.split(",") for r in ref.read_text().splitlines()[1:]]
    assert len(rows) == n
    c = fmu.instantiate()
    assert fmu.set_string(c, {"model": "cam", "road_file": str(road)}) == OK
    assert fmu.so.fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0) == OK
    assert fmu.so.fmi2EnterInitializationMode(c) == OK
    assert fmu.set_real(c, {"x": x_from, "load": load}) == OK
    assert fmu.so.fmi2ExitInitializationMode(c) == OK
    t, h, state = 0.0, [], fmi2FMUstate()
    for k in range(n):
        assert fmu.set_real(c, {"x": x_from + k * dx, "load": load}) == OK
        assert fmu.so.fmi2DoStep(c, t, 0.01, 1) == OK
        t += 0.01
        status, (hk, slope, fx, fz) = fmu.get_real(c, ["h", "slope", "fx", "fz"])
        assert status == OK
        h.append(hk)
        assert ["%.9g" % v for v in (hk, slope, fx, fz)] == \
            [rows[k][2], rows[k][3], rows[k][4], rows[k][5]], f"row {k}"
        if k == 750:
            assert fmu.so.fmi2GetFMUstate(c, ctypes.byref(state)) == OK
            t_saved = t
    status, (t_fmu,) = (lambda v: (fmu.so.fmi2GetRealStatus(c, 2, ctypes.byref(v)),
                                   [v.value]))(fmi2Real())
    assert status == OK and abs(t_fmu - t) < 1e-9  # fmi2LastSuccessfulTime
    # back to step 750 and on: the same heights, bit for bit
    assert fmu.so.fmi2SetFMUstate(c, state) == OK
    t = t_saved
    for k in range(751, 900):
        fmu.set_real(c, {"x": x_from + k * dx, "load": load})
        assert fmu.so.fmi2DoStep(c, t, 0.01, 0) == OK
        t += 0.01
        assert fmu.get_real(c, ["h"])[1][0] == h[k]
    assert fmu.so.fmi2FreeFMUstate(c, ctypes.byref(state)) == OK and not state.value
    assert fmu.so.fmi2CancelStep(c) == ERROR and "fmi2CancelStep" in fmu.messages[-1][2]
    assert fmu.so.fmi2Terminate(c) == OK
    fmu.so.fmi2FreeInstance(c)


def test_crg_road_track_as_tirenv_envelope(fmu, tmp_path):
    """An OpenCRG road file: the track at v = track, as 'tirenv envelope --track'; a width
    over it is refused (the FMU evaluates one track)."""
    road = os.path.join(os.environ["TIRENV_SAMPLES"], "crg", "handmade_curved.crg")
    ref = tmp_path / "ref.csv"
    load, x_from, dx, n = 11903.6, -0.5, 0.01, 2301
    subprocess.run([os.environ["TIRENV_CLI"], "envelope", "--model", "springs", "--profile",
                    road, "--track", "0.5", "--load", repr(load), "--x-from", repr(x_from),
                    "--x-to", "22.5", "--dx", repr(dx), "-o", str(ref)], check=True,
                   capture_output=True)
    rows = [r.split(",") for r in ref.read_text().splitlines()[1:]]
    assert len(rows) == n
    c = fmu.instantiate()
    assert fmu.set_string(c, {"model": "springs", "road_file": road}) == OK
    assert fmu.set_real(c, {"track": 0.5}) == OK
    assert fmu.so.fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0) == OK
    assert fmu.so.fmi2EnterInitializationMode(c) == OK
    assert fmu.set_real(c, {"x": x_from, "load": load}) == OK
    assert fmu.so.fmi2ExitInitializationMode(c) == OK
    t = 0.0
    for k in range(n):
        assert fmu.set_real(c, {"x": x_from + k * dx, "load": load}) == OK
        assert fmu.so.fmi2DoStep(c, t, 0.01, 1) == OK
        t += 0.01
        status, (hk, slope) = fmu.get_real(c, ["h", "slope"])
        assert status == OK
        assert ["%.9g" % v for v in (hk, slope)] == [rows[k][2], rows[k][3]], f"row {k}"
    fmu.so.fmi2FreeInstance(c)
    c = fmu.instantiate()
    assert fmu.set_string(c, {"road_file": road}) == OK
    assert fmu.set_real(c, {"width": 0.38}) == OK
    assert fmu.so.fmi2EnterInitializationMode(c) == OK
    assert fmu.so.fmi2ExitInitializationMode(c) == ERROR
    assert "one track" in fmu.messages[-1][2]
    fmu.so.fmi2FreeInstance(c)


def test_errors_are_logged(fmu, tmp_path):
    assert not fmu.instantiate(guid="{another}")
    assert "GUID" in fmu.messages[-1][2]
    assert not fmu.instantiate(kind=MODEL_EXCHANGE)
    c = fmu.instantiate()
    assert fmu.set_string(c, {"road_file": str(tmp_path / "missing.csv")}) == OK
    assert fmu.so.fmi2EnterInitializationMode(c) == OK
    assert fmu.so.fmi2ExitInitializationMode(c) == ERROR
    status, category, text = fmu.messages[-1]
    assert status == ERROR and category == "logStatusError"
    assert "missing.csv" in text and "cannot open" in text
    fmu.so.fmi2FreeInstance(c)
    with pytest.raises(KeyError):  # a name the description does not have: the importer's
        fmu.set_real(c, {"speed": 1.0})
