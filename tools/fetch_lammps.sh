#!/usr/bin/env bash
# Fetch the pinned LAMMPS source (Debian source package lammps 20260704+dfsg-2, suite sid)
# into a cache directory outside the work tree, verify its checksum and unpack it.
#
#   tools/fetch_lammps.sh CACHE_DIR      -> prints the unpacked source directory
#
# The sid deb-src entry is derived from the machine's own apt sources (the first Debian
# archive URI found there); no registry host name is written in this repository.
set -euo pipefail

LAMMPS_DEB_VERSION="20260704+dfsg-2"
LAMMPS_TARBALL="lammps_20260704+dfsg.orig.tar.gz"
LAMMPS_SHA256="cddbc45a047416bd48a4a0b87f24a5b61b3446982b74d18cafe619c22b17eb62"

cache="${1:?usage: fetch_lammps.sh CACHE_DIR}"
mkdir -p "$cache"
src="$cache/lammps-20260704"

die() { printf 'fetch_lammps: ERROR: %s\n' "$*" >&2; exit 1; }
log() { printf 'fetch_lammps: %s\n' "$*" >&2; }

if [ -f "$src/.unpacked-ok" ]; then
  echo "$src"
  exit 0
fi

tarball="$cache/$LAMMPS_TARBALL"
if [ ! -f "$tarball" ] || ! echo "$LAMMPS_SHA256  $tarball" | sha256sum -c --status; then
  rm -f "$tarball"
  command -v apt-get > /dev/null || die "apt-get not found: this setup needs Debian's apt to fetch the LAMMPS source package"
  # derive a deb-src entry for sid from the machine's existing Debian archive URI
  uri=$(grep -rhoE '^(URIs:|deb)[[:space:]]+[^[:space:]]+' /etc/apt/sources.list /etc/apt/sources.list.d/*.sources \
          /etc/apt/sources.list.d/*.list 2> /dev/null | awk '{print $2}' | grep -E '/debian/?$' | head -n 1 || true)
  [ -n "$uri" ] || die "no Debian archive URI found in /etc/apt/sources.list*; add a 'deb-src <mirror> sid main' entry by hand and re-run"
  list=/etc/apt/sources.list.d/esph-lammps-sid-src.sources
  if [ ! -f "$list" ]; then
    log "adding deb-src entry for sid (URI from existing apt sources) in $list"
    printf 'Types: deb-src\nURIs: %s\nSuites: sid\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
      "$uri" > "$list"
  fi
  apt-get update -qq -o Dir::Etc::sourcelist="$list" -o Dir::Etc::sourceparts=- -o APT::Get::List-Cleanup=0 \
    || die "apt-get update for the sid deb-src entry failed (network or mirror problem); retry, or put $LAMMPS_TARBALL into $cache by hand"
  log "downloading lammps=$LAMMPS_DEB_VERSION source (about 213 MB)"
  ( cd "$cache" && apt-get source --download-only "lammps=$LAMMPS_DEB_VERSION" > "$cache/apt-source.log" 2>&1 ) || true
  [ -f "$tarball" ] || die "download of $LAMMPS_TARBALL failed (see $cache/apt-source.log); check the network, or place the tarball in $cache by hand"
  echo "$LAMMPS_SHA256  $tarball" | sha256sum -c --status \
    || die "checksum mismatch for $tarball (expected sha256 $LAMMPS_SHA256); delete it and re-run, do not build from an unverified tarball"
fi
log "checksum ok: $LAMMPS_TARBALL"

rm -rf "$src" "$cache/unpack.tmp"
mkdir -p "$cache/unpack.tmp"
tar -xzf "$tarball" -C "$cache/unpack.tmp" || die "could not unpack $tarball"
# the Debian orig tarball unpacks flat; an upstream one has a top folder: accept both
if [ -f "$cache/unpack.tmp/cmake/CMakeLists.txt" ]; then
  mv "$cache/unpack.tmp" "$src"
else
  top=$(find "$cache/unpack.tmp" -mindepth 1 -maxdepth 1 -type d | head -n 1)
  [ -n "$top" ] && [ -f "$top/cmake/CMakeLists.txt" ] || die "unpacked tarball has no cmake/CMakeLists.txt"
  mv "$top" "$src"
  rm -rf "$cache/unpack.tmp"
fi
touch "$src/.unpacked-ok"
echo "$src"
