#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# check_cdl.sh CHECK_NC CDL OUT.nc: builds a NetCDF-4 file from CDL with the
# NetCDF library's ncgen and checks it (the checker's output and exit code).
set -u
command -v ncgen >/dev/null || { echo "SKIPPED: no ncgen (netcdf-bin)"; exit 77; }
ncgen -4 -o "$3" "$2" || exit 2
exec "$1" "$3"
