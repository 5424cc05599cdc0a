#!/bin/sh
# The documented install of the Python module, checked as a user does it, offline: install
# libtirenv into a temporary prefix (cmake --install), make a virtual environment that sees
# Debian's python3-cffi and python3-numpy, 'pip install --no-build-isolation --no-index
# ./python' against the prefix found through pkg-config, then import it from elsewhere (no
# PYTHONPATH, no LD_LIBRARY_PATH) and compute a curve equal to the installed CLI's.
#   sh python/tests/install.sh CMAKE BUILD_DIR SOURCE_DIR PYTHON
# SPDX-License-Identifier: Apache-2.0
set -u
cmake=$1 build=$2 src=$3 python=$4
unset PYTHONPATH LD_LIBRARY_PATH TIRENV_INCLUDE_DIR TIRENV_LIBRARY_DIR TIRENV_DATA
# shellcheck source=tests/lib/tap_venv.sh
. "$(dirname "$0")/../../tests/lib/tap_venv.sh"
tap_begin pyinstall
prefix=$tmp/prefix
check "cmake --install into a temporary prefix" "$cmake" --install "$build" --prefix "$prefix"
libdir=$(dirname "$(find "$prefix" -name tirenv.pc | head -1)")
tap_venv "a virtual environment with Debian's packages (their pip too)" "$python" "$tmp/venv" \
    --without-pip
cp -R "$src/python" "$tmp/src"  # pip builds in the tree it is given: not in the clone
check "pip install --no-build-isolation --no-index ./python against the prefix" \
    env PKG_CONFIG_PATH="$libdir" "$tmp/venv/bin/python" -m pip install -q \
    --no-build-isolation --no-index "$tmp/src"
cd "$tmp" || exit 2
check "import tirenv from outside the source and build trees" \
    "$tmp/venv/bin/python" -c "import tirenv, sys; assert tirenv.__file__.startswith('$tmp/venv'), tirenv.__file__"
"$prefix/bin/tirenv" envelope --model springs --cleat 0.3,0.1 --contact-length 0.38 \
    -o "$tmp/cli.csv" 2>/dev/null
cat >"$tmp/curve.py" <<'PY'
import sys, tirenv
m = tirenv.Model("springs")
m.set(tirenv.Profile.cleat(0.3, 0.1), m.load_for_contact_length(0.38))
rows = ["%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d" % tuple(r.tolist()) for r in m.sweep()]
cli = open(sys.argv[1]).read().splitlines()[1:]
assert rows == cli, "the installed module's curve differs from the installed CLI's"
print(len(rows), "rows equal")
PY
check "its springs curve over a cleat is the installed tirenv envelope's" \
    "$tmp/venv/bin/python" "$tmp/curve.py" "$tmp/cli.csv"
tap_end
