#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# -o through a symbolic link in a sticky world-writable directory (/tmp's mode 1777) obeys
# the kernel's protected_symlinks rule, which following the link by hand used to bypass:
# a link owned by another user, in a directory that user does not own, is not
# followed; the file it points at is left alone. A link of our own there is followed. Needs
# root (to give a link another owner: chown -h); otherwise reported as skipped (exit 77).
. "$(dirname "$0")/../lib/clilib.sh"

if [ "$(id -u)" -ne 0 ]; then
    echo "# SKIP: not root; a link owned by another user needs chown -h"
    exit 77
fi
rigid="envelope --model rigid --cleat 0.1,0.05 --load 13000 --dx 0.05"
mkdir sticky
chmod 1777 sticky
echo precious >victim.csv
ln -s ../victim.csv sticky/theirs.csv
chown -h 54321:54321 sticky/theirs.csv
run "$bin" $rigid -o sticky/theirs.csv
check "another user's link in a sticky world-writable directory: refused, target kept" \
    '[ $rc -eq 2 ] && grep -q "refusing to follow the symbolic link sticky/theirs.csv" err &&
     grep -q "protected_symlinks" err && [ "$(cat victim.csv)" = precious ] &&
     [ -L sticky/theirs.csv ] && [ -z "$(find . -name "*tmp.*")" ]'

ln -s ../victim.csv sticky/mine.csv
run "$bin" $rigid -o sticky/mine.csv
check "our own link there: followed, the target replaced" \
    '[ $rc -eq 0 ] && [ -L sticky/mine.csv ] && head -n 1 victim.csv | grep -q "^x_m,"'

# The directory's owner's link is followed too, as the kernel allows.
echo precious >victim2.csv
mkdir owned
chmod 1777 owned
chown 54321:54321 owned
ln -s ../victim2.csv owned/owners.csv
chown -h 54321:54321 owned/owners.csv
run "$bin" $rigid -o owned/owners.csv
check "a link of the directory's owner: followed" \
    '[ $rc -eq 0 ] && head -n 1 victim2.csv | grep -q "^x_m,"'

clilib_done
