#!/usr/bin/env bash
# The LAMMPS fetch stops with a message that says what to do when the download fails,
# when the checksum does not match, and when apt-get is missing. A fake apt-get on PATH
# stands in for the registry (no network use).
set -u
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
fetch="$here/tools/fetch_lammps.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0
fail=0
check() {    # name, expected exit (nonzero), regex, output, exit
  if [ "$5" -ne 0 ] && echo "$4" | grep -qE "$3"; then
    echo "PASS $1"
    pass=$((pass + 1))
  else
    echo "FAIL $1 (exit $5): $4"
    fail=$((fail + 1))
  fi
}

mkdir -p "$tmp/bin"
# 1. download fails
cat > "$tmp/bin/apt-get" << 'EOS'
#!/bin/sh
[ "$1" = source ] && { echo "E: Failed to fetch" >&2; exit 100; }
exit 0
EOS
chmod +x "$tmp/bin/apt-get"
out=$(PATH="$tmp/bin:$PATH" bash "$fetch" "$tmp/cache1" 2>&1)
check "failed download" 1 "download of lammps_20260704\+dfsg.orig.tar.gz failed.*place the tarball" "$out" $?

# 2. wrong checksum
cat > "$tmp/bin/apt-get" << 'EOS'
#!/bin/sh
[ "$1" = source ] && echo "not a tarball" > lammps_20260704+dfsg.orig.tar.gz
exit 0
EOS
out=$(PATH="$tmp/bin:$PATH" bash "$fetch" "$tmp/cache2" 2>&1)
check "wrong checksum" 1 "checksum mismatch.*expected sha256 cddbc45a.*delete it and re-run" "$out" $?

# 3. no apt-get: a PATH with the basic tools only
mkdir -p "$tmp/nobin"
for t in bash sh grep awk sha256sum head mkdir rm tar find mv touch cat printf echo; do
  p=$(command -v "$t") && ln -sf "$p" "$tmp/nobin/$t"
done
out=$(PATH="$tmp/nobin" bash "$fetch" "$tmp/cache3" 2>&1)
check "missing apt-get" 1 "apt-get not found" "$out" $?

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
