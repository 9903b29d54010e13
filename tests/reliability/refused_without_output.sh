#!/usr/bin/env bash
# Usage: refused_without_output.sh OUTPUT_DIR COMMAND [ARGS...]
# Runs COMMAND ARGS --output OUTPUT_DIR (the directory removed first) and exits with its exit
# code; prints a line a test can refuse (NOT_MATCHES "output directory .* was written") when
# the command created the directory, i.e. wrote something before it refused its input.
dir=$1
shift
rm -rf "$dir"
"$@" --output "$dir"
rc=$?
if [[ -e $dir ]]; then
  echo "refused_without_output: the output directory $dir was written"
fi
exit $rc
