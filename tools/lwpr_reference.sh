#!/usr/bin/env bash
# Makes the fixture of the LWPR replay test (src/learn/lwpr/reference_replay.rs) in
# tests/data/lwpr_reference/:
#
#   stream.txt                  the pattern stream of a 175-trial LWPR run (seed 1, the
#                               shipped configs/lwpr.conf): 7,222 adjusted 5-input patterns,
#                               recorded by examples/lwpr_patterns.rs
#   defaults.txt                the reference library fed that stream at its defaults
#   init_D_200_w_gen_0.2.txt    the same with init_D 200 and w_gen 0.2
#
# Each library file has a line per pattern with the three outputs' receptive-field counts
# and, after every 5th pattern, the library's predictions at the next pattern's input
# (tools/lwpr_reference_driver.c, which uses only the library's public API).
#
# The reference is Klanke and Vijayakumar's LWPR library, v1.2.6 (LGPL; its repository is
# ipab-slmc/lwpr on GitHub). Build it the usual way (./configure --prefix=DIR && make
# install) and point LWPR_PREFIX at DIR; or set LWPR_CFLAGS and LWPR_LIBS to compile the
# driver against another build of it. The library's code is never copied into this
# repository.
#
# How the committed fixture was made: the library's update and prediction path (lwpr.c,
# lwpr_aux.c, lwpr_math.c) was reconstructed under /tmp from that repository as a single
# file with the API the driver calls (single-threaded, five inputs), compiled with
# gcc -O2 together with the driver, and run by this script with
#   LWPR_CFLAGS="-I/tmp/lwpr_ref/lib" LWPR_LIBS="/tmp/lwpr_ref/lib/lwpr_subset.c -lm"
# Checked afterwards against the whole library built from its unmodified sources (lwpr.c,
# lwpr_aux.c, lwpr_math.c, lwpr_mem.c, lwpr_binio.c at commit 9ce3ca9, with a
# lwpr_config.h of NUM_THREADS 1, no expat, no SSE; gcc 12.2 -O2): the driver writes both
# library files byte for byte.
#
# Run from the repository root: bash tools/lwpr_reference.sh. The test reads the files;
# it never runs this script.
set -euo pipefail

TRIALS=175
SEED=1
EVERY=5
OUT=tests/data/lwpr_reference
if [[ -z "${LWPR_CFLAGS:-}" || -z "${LWPR_LIBS:-}" ]]; then
    : "${LWPR_PREFIX:?set LWPR_PREFIX (or LWPR_CFLAGS and LWPR_LIBS): see the header of this script}"
    LWPR_CFLAGS="-I$LWPR_PREFIX/include"
    LWPR_LIBS="$LWPR_PREFIX/lib/liblwpr.a -lm -lpthread"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cargo build --release --example lwpr_patterns
# shellcheck disable=SC2086 # the flags are lists of words
gcc -O2 $LWPR_CFLAGS -o "$work/driver" tools/lwpr_reference_driver.c $LWPR_LIBS
mkdir -p "$OUT"
"${CARGO_TARGET_DIR:-target}/release/examples/lwpr_patterns" "$TRIALS" "$SEED" >"$OUT/stream.txt"
"$work/driver" "$OUT/stream.txt" 25 0.1 "$EVERY" >"$OUT/defaults.txt"
"$work/driver" "$OUT/stream.txt" 200 0.2 "$EVERY" >"$OUT/init_D_200_w_gen_0.2.txt"
wc -c "$OUT"/*.txt
