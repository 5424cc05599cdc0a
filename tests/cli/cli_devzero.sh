#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# /dev/zero as each input file, under a memory limit: every reader stops at its line cap (or
# its size cap) with a message naming the file, exit 2, in bounded memory and time. Before
# these caps the CSV, .tir and .veh readers grew one line past 4 GB, and under a limit said
# "no header line" or took the empty file. The limit is ulimit -v 1 GB, or under
# AddressSanitizer (which reserves terabytes of address space) its own cap on one
# allocation, 512 MB, with a failed allocation returned to the program.
. "$(dirname "$0")/../lib/clilib.sh"

if ldd "$bin" 2>/dev/null | grep -q libasan; then
    limit="ASAN_OPTIONS=allocator_may_return_null=1:max_allocation_size_mb=512"
    echo "# AddressSanitizer build: $limit"
    capped() { env ASAN_OPTIONS=allocator_may_return_null=1:max_allocation_size_mb=512 timeout 60 "$@"; }
else
    echo "# memory limit: ulimit -v 1000000 (1 GB)"
    capped() { (ulimit -v 1000000 && exec timeout 60 "$@"); }
fi

# A data set whose manifest, or whose source.txt, is /dev/zero.
mkdir manifest source
ln -s /dev/zero manifest/cases.csv
printf 'case,split,contact_length_m,load_N,L_m,H_m,log,curve\nA,train,0.3,13000,0.1,0.05,,A.csv\n' \
    >source/cases.csv
ln -s /dev/zero source/source.txt

# zero_fails WHAT FILE CMD...: exit 2 and one message naming FILE, line 1, and the cap.
zero_fails() {
    what=$1 file=$2
    shift 2
    run capped "$@"
    check "$what: exit 2 naming $file and the line cap" \
        '[ $rc -eq 2 ] && grep -q "^tirenv: $file:1: line longer than 65536 characters" err &&
         [ "$(wc -l <err)" -eq 1 ]'
}

zero_fails "envelope --profile /dev/zero" /dev/zero \
    "$bin" envelope --model springs --load 13000 --profile /dev/zero -o out.csv
zero_fails "envelope --stream --profile /dev/zero" /dev/zero \
    "$bin" envelope --model springs --load 13000 --profile /dev/zero --stream -o out.csv
zero_fails "convert --profile /dev/zero" /dev/zero "$bin" convert --profile /dev/zero -o out.csv
zero_fails "flat --tire /dev/zero" /dev/zero "$bin" flat --tire /dev/zero
zero_fails "ride --vehicle /dev/zero" /dev/zero \
    "$bin" ride --vehicle /dev/zero --cleat 0.1,0.05 --speed 2
zero_fails "import --log /dev/zero" /dev/zero \
    "$bin" import --log /dev/zero --cleat 0.1,0.05 --load 13000
zero_fails "dataset list with cases.csv -> /dev/zero" manifest/cases.csv \
    "$bin" dataset list manifest
zero_fails "dataset list with source.txt -> /dev/zero" source/source.txt \
    "$bin" dataset list source
check "no output file was left" 'no_file out.csv'

# The network's reader (jansson) stops at its NUL byte, or at the 64 MiB cap.
run capped "$bin" predict --nn /dev/zero --cleat 0.1,0.05 --contact-length 0.3
check "predict --nn /dev/zero: exit 2 naming the file" \
    '[ $rc -eq 2 ] && grep -q "^tirenv: /dev/zero" err'

clilib_done
