#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Builds a self-contained wheel of the tirenv Python module (make wheel): the package, its
compiled extension and libtirenv.so.MAJOR beside it, found through an $ORIGIN run path, so
that 'pip install --no-index tirenv-*.whl' works in any virtual environment on any path with
no environment variable; it needs only Debian's runtime libraries that libtirenv itself
links (libc, libm, libjansson and whatever else 'readelf -d libtirenv.so' lists) and the
Python packages cffi and numpy.

The wheel is written by hand (a zip with the dist-info files PEP 427 and PEP 376 describe)
rather than through setuptools, which would rebuild the extension against an installed
libtirenv. Its tag is the interpreter's own (cp311-cp311-linux_x86_64 on Debian 12): the
extension is compiled for that CPython's ABI, not the stable one, and named accordingly.

  python3 make_wheel.py --out DIR --include DIR [--include DIR] --library FILE
                        --version X.Y.Z --work DIR
"""
import argparse
import base64
import hashlib
import os
import shutil
import sys
import sysconfig
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import tirenv_build  # noqa: E402  (the same cffi declarations as make python)


def wheel_tag():
    """The interpreter's tag, e.g. cp311-cp311-linux_x86_64."""
    impl = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{impl}-{impl}-{platform}"


def record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}"


def metadata(version):
    with open(os.path.join(HERE, "README.md"), encoding="utf-8") as f:
        readme = f.read()
    return (f"Metadata-Version: 2.1\nName: tirenv\nVersion: {version}\n"
            "Summary: Quasi-static tire enveloping models, the tractor ride and ISO 2631-1 "
            "comfort, over libtirenv\nLicense: Apache-2.0\nLicense-File: LICENSE\n"
            "License-File: NOTICE\nRequires-Python: >=3.9\nRequires-Dist: cffi>=1.15\n"
            "Requires-Dist: numpy>=1.21\nDescription-Content-Type: text/markdown\n\n"
            + readme)


def build(out, include_dirs, library, version, work):
    soname = os.path.basename(os.path.realpath(library))
    # libtirenv.so.0.1.0 -> libtirenv.so.0: the name the extension's DT_NEEDED asks for
    major = ".".join(soname.split(".")[:3])
    stage = os.path.join(work, "stage")
    shutil.rmtree(stage, ignore_errors=True)
    pkg = os.path.join(stage, "tirenv")
    os.makedirs(pkg)
    libdir = os.path.join(work, "lib")
    shutil.rmtree(libdir, ignore_errors=True)
    os.makedirs(libdir)
    # Link against a copy under its soname only, so that no build directory is recorded.
    shutil.copyfile(library, os.path.join(libdir, major))
    os.symlink(major, os.path.join(libdir, "libtirenv.so"))
    ffi = tirenv_build.make_builder(include_dirs, [libdir], rpath=["$ORIGIN"])
    built = ffi.compile(tmpdir=os.path.join(work, "cffi"), verbose=False)
    shutil.copyfile(built, os.path.join(pkg, os.path.basename(built)))
    shutil.copyfile(library, os.path.join(pkg, major))
    for name in sorted(os.listdir(os.path.join(HERE, "tirenv"))):
        if name.endswith(".py"):
            shutil.copyfile(os.path.join(HERE, "tirenv", name), os.path.join(pkg, name))

    tag = wheel_tag()
    info = f"tirenv-{version}.dist-info"
    files = {}
    for name in sorted(os.listdir(pkg)):
        with open(os.path.join(pkg, name), "rb") as f:
            files[f"tirenv/{name}"] = f.read()
    files[f"{info}/METADATA"] = metadata(version).encode()
    # The licence travels with the library it covers, where setuptools puts it (its
    # License-File lines above); python/LICENSE and NOTICE are the repository's copies.
    for name in ("LICENSE", "NOTICE"):
        with open(os.path.join(HERE, name), "rb") as f:
            files[f"{info}/{name}"] = f.read()
    files[f"{info}/WHEEL"] = (f"Wheel-Version: 1.0\nGenerator: tirenv make_wheel.py\n"
                              f"Root-Is-Purelib: false\nTag: {tag}\n").encode()
    files[f"{info}/top_level.txt"] = b"tirenv\n"
    record = [record_line(n, d) for n, d in files.items()] + [f"{info}/RECORD,,"]
    files[f"{info}/RECORD"] = ("\n".join(record) + "\n").encode()

    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, f"tirenv-{version}-{tag}.whl")
    with zipfile.ZipFile(path + ".tmp", "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            zi = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            executable = name.endswith(".so") or ".so." in name
            zi.external_attr = (0o755 if executable else 0o644) << 16
            zi.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(zi, data)
    os.replace(path + ".tmp", path)
    print(path)


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True, help="directory that receives the wheel")
    ap.add_argument("--include", action="append", required=True, help="tirenv's headers")
    ap.add_argument("--library", required=True, help="libtirenv.so.X.Y.Z to carry")
    ap.add_argument("--version", required=True, help="the project's version")
    ap.add_argument("--work", required=True, help="scratch directory")
    a = ap.parse_args()
    build(os.path.abspath(a.out), [os.path.abspath(d) for d in a.include],
          os.path.abspath(a.library), a.version, os.path.abspath(a.work))
