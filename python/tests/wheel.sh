#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The wheel of make wheel (python/make_wheel.py) installed as a user installs a wheel: a fresh
# virtual environment that sees Debian's packages (python3 -m venv --system-site-packages,
# its own pip), on a path with a space in it, 'pip install --no-index' of the wheel file, then
# everything run with an empty environment (env -i: no PYTHONPATH, LD_LIBRARY_PATH,
# PKG_CONFIG_PATH) from another directory: the package and the libtirenv it loads are the
# venv's, its extension's run path is $ORIGIN, and its curve over a cleat is the CLI's.
#   sh python/tests/wheel.sh WHEEL_DIR CLI PYTHON
set -u
wheels=$1 cli=$2 python=$3
# shellcheck source=tests/lib/tap_venv.sh
. "$(dirname "$0")/../../tests/lib/tap_venv.sh"
tap_begin wheel
set -- "$wheels"/tirenv-*.whl
check "make wheel wrote one wheel ($*)" test $# -eq 1 -a -f "$1"
wheel=$1
case $(basename "$wheel") in
    tirenv-*-cp3*-cp3*-linux_x86_64.whl) tagged=1 ;;
    *) tagged=0 ;;
esac
check "its tag is the interpreter's own (cpXY-cpXY-linux_x86_64)" test "$tagged" -eq 1
mkdir -p "$tmp/x"
(cd "$tmp/x" && unzip -q "$wheel")
check "it carries libtirenv under its soname beside the extension" \
    sh -c "ls '$tmp'/x/tirenv/libtirenv.so.* && ls '$tmp'/x/tirenv/_native.cpython-3*-x86_64-linux-gnu.so"
check "the extension's RUNPATH is \$ORIGIN and nothing else" \
    sh -c "readelf -d '$tmp'/x/tirenv/_native.*.so | grep -E 'RPATH|RUNPATH' | grep -qxF ' 0x000000000000001d (RUNPATH)            Library runpath: [\$ORIGIN]'"
check "it carries the repository's LICENSE and NOTICE in its .dist-info" \
    sh -c "cmp '$tmp'/x/tirenv-*.dist-info/LICENSE '$(dirname "$0")/../LICENSE' &&
           cmp '$tmp'/x/tirenv-*.dist-info/NOTICE '$(dirname "$0")/../NOTICE'"
venv="$tmp/another place/venv"
tap_venv "a fresh venv: $python -m venv --system-site-packages" "$python" "$venv"
check "pip install --no-index the wheel, with an empty environment" \
    env -i "$venv/bin/python" -m pip install -q --no-index "$wheel"
"$cli" envelope --model springs --cleat 0.3,0.1 --contact-length 0.38 -o "$tmp/cli.csv" \
    2>/dev/null
cat >"$tmp/use.py" <<'PY'
import sys
import tirenv
venv = sys.argv[1]
assert tirenv.__file__.startswith(venv), tirenv.__file__
loaded = [l.split(None, 5)[-1].strip() for l in open("/proc/self/maps") if "libtirenv" in l]
assert loaded and all(p.startswith(venv) for p in loaded), loaded
assert tirenv.__version__ == sys.argv[3], (tirenv.__version__, sys.argv[3])
m = tirenv.Model("springs")
m.set(tirenv.Profile.cleat(0.3, 0.1), m.load_for_contact_length(0.38))
rows = ["%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d" % tuple(r.tolist()) for r in m.sweep()]
assert rows == open(sys.argv[2]).read().splitlines()[1:], "the curve differs from the CLI's"
print(len(rows), "rows equal; libtirenv from", loaded[0])
PY
version=$("$cli" --version | awk '{print $2}')
cd / || exit 2
check "imported with env -i from /: the venv's package and libtirenv, version $version, the CLI's curve" \
    env -i "$venv/bin/python" "$tmp/use.py" "$venv" "$tmp/cli.csv" "$version"
sed 's/^/# /' "$tmp/log"
tap_end
