#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# ncdump_golden.sh CONVERT GOLDEN OUTDIR METADATA VEHICLE INPUT...: the NetCDF
# library's own header dump (ncdump -h) of an OG1.0 conversion equals GOLDEN.
# date_created is pinned by SOURCE_DATE_EPOCH; the history attribute (the
# command line, with this machine's paths) is left out of the comparison.
# Regenerate: GLIDER_UPDATE_GOLDEN=1.
set -eu
convert=$1; golden=$2; outdir=$3; metadata=$4; vehicle=$5; shift 5
command -v ncdump >/dev/null || { echo "SKIPPED: no ncdump (netcdf-bin)"; exit 77; }
mkdir -p "$outdir"
SOURCE_DATE_EPOCH=1700000000 "$convert" --quiet --format og1 --metadata "$metadata" --vehicle "$vehicle" \
  --out "$outdir/golden.nc" "$@"
ncdump -h "$outdir/golden.nc" | grep -v ':history = ' > "$outdir/golden.cdl"
if [ "${GLIDER_UPDATE_GOLDEN:-0}" = 1 ]; then cp "$outdir/golden.cdl" "$golden"; fi
diff -u "$golden" "$outdir/golden.cdl"
echo "PASS: header identical to $golden"
