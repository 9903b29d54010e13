#!/bin/bash
# snapshot_space.sh CHECK_SNAPSHOTS REFERENCE_DIR OUT_DIR -- APP DECK ARGS...
#
# A run cut short after its snapshot appends but before its next checkpoint, continued, cut
# again: runs APP to t = 1, keeps that checkpoint, continues to the end time of ARGS, then
# twice puts the t = 1 checkpoint back and restarts, so that each restart drops the
# snapshots after t = 1 and writes them again. snapshots.h5 must then hold the same
# snapshots as REFERENCE_DIR's uninterrupted run (check_snapshots same) and be no larger
# than it (the dropped snapshots' space given back; cut in place it grows by their size
# at every restart).
set -eu
if [ "${1:-}" = "--help" ] || [ $# -lt 5 ]; then
  sed -n '2,10p' "$0"
  exit 2
fi
check=$1 reference=$2 out=$3
shift 4
rm -rf "$out" "$out.t1"
"$@" --output "$out" --set "Time integration/End time=1" > /dev/null
cp "$out/checkpoint.h5" "$out.t1"
"$@" --restart "$out" > /dev/null
for cut in 1 2; do
  cp "$out.t1" "$out/checkpoint.h5"
  "$@" --restart "$out" > /dev/null
done
"$check" same "$reference/snapshots.h5" "$out/snapshots.h5"
size=$(stat -c %s "$out/snapshots.h5")
uninterrupted=$(stat -c %s "$reference/snapshots.h5")
echo "snapshots.h5: $size bytes after two cut restarts; $uninterrupted bytes uninterrupted"
if [ "$size" -gt "$uninterrupted" ]; then
  echo "snapshot_space: FAIL: the restarts left the space of the snapshots they dropped in the file"
  exit 1
fi
echo "snapshot_space: OK"
