#!/bin/bash
# The tension remedy of issue 17 at fine resolution: the pre-stressed spinning disc
# (REFERENCES 4C, examples/spinning_disc) at b/dx 80 for a quarter turn with h = 1.0, 1.3
# and 1.5 dx (doc/hard_cases.md 10). About 3-5 minutes per case on one core.
#   bash bench/tension_disc.sh [build/lmp] [bdx]
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
lmp=$(realpath "${1:-$here/build/lmp}")
bdx=${2:-80}
work=$(mktemp -d)
cp "$here/examples/spinning_disc/in.spinning_disc" "$work/"
cd "$work"
for hdx in 1.0 1.3 1.5; do
  "$lmp" -in in.spinning_disc -var bdx "$bdx" -var hdx "$hdx" -var thermo_every 1000 \
    -log "log.$hdx" -screen none
  echo "TENSION_DISC hdx=$hdx $(grep '^SPINNING_DISC' "log.$hdx" | cut -d' ' -f2-) \
loop_s=$(grep 'Loop time' "log.$hdx" | tail -1 | awk '{print $4}')"
done
rm -rf "$work"
