#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# bench_og1_throughput.sh [BUILD_DIR] [RUNS]: MB/s of Slocum binaries -> OG1.0
# end to end (glider-convert --format og1 with the flight-model products: decode,
# merge, phases, flight model, NetCDF-4 write), on every real deployment of
# tests/data/real/dbd. Reports the wall time (best and median of RUNS) and the
# CPU time (user + sys, mean over RUNS: what the machine's load does not change).
# A benchmark, not a test: it judges nothing.
set -eu
root=$(cd "$(dirname "$0")/../../.." && pwd)
build=${1:-$root/build/release}; runs=${2:-20}
convert=$build/tools/files/convert/glider-convert
out=$(mktemp -d); trap 'rm -rf "$out"' EXIT
for dir in "$root"/tests/data/real/dbd/*/; do
  name=$(basename "$dir")
  bytes=$(cat "$dir"/*.[de]bd | wc -c)
  run="$convert --quiet --format og1 --metadata $root/tests/netcdf/data/comet.toml \
       --vehicle $root/boards/vehicles/slocum_shallow.toml --out $out/$name.nc $dir"
  : > "$out/wall"
  cpu=$( { /usr/bin/time -f "%U %S" sh -c "
      i=0; while [ \$i -lt $runs ]; do
        s=\$(date +%s.%N); $run 2>/dev/null; e=\$(date +%s.%N)
        echo \"\$e - \$s\" | bc -l >> $out/wall; i=\$((i + 1)); done" ; } 2>&1 | tail -1)
  sort -g "$out/wall" | awk -v name="$name" -v bytes="$bytes" -v cpu="$cpu" -v runs="$runs" '
    { t[NR] = $1 } END { split(cpu, c, " "); per = (c[1] + c[2]) / runs; mb = bytes / 1e6;
      printf "%s: %.2f MB of binaries; wall best %.3f s (%.0f MB/s), median %.3f s (%.0f MB/s); " \
             "CPU %.4f s per run (%.0f MB/s); %d runs\n",
             name, mb, t[1], mb / t[1], t[int((NR + 1) / 2)], mb / t[int((NR + 1) / 2)], per, mb / per, NR }'
done
