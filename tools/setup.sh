#!/usr/bin/env bash
# One-stop setup for the ESPH package on Debian 12 (run as root, or with the packages installed):
#   1. installs the Debian packages needed (compilers, CMake, Ninja, Open MPI, Eigen, GoogleTest, ...)
#   2. fetches the pinned LAMMPS source (tools/fetch_lammps.sh) into a cache outside the work tree
#   3. builds that LAMMPS once (PLUGIN, MACHDYN, SPH, OPENMP, MPI + OpenMP, shared library) in the cache,
#      keyed by version and options, so a second setup on the same machine takes seconds
#   4. configures and builds this project in ./build: esphplugin.so, build/lmp (ESPH compiled in),
#      and the test programs
#
# Environment: ESPH_CACHE (default /var/cache/esph), ESPH_JOBS (default: nproc).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache="${ESPH_CACHE:-/var/cache/esph}"
jobs="${ESPH_JOBS:-$(nproc)}"

die() { printf 'setup: ERROR: %s\n' "$*" >&2; exit 1; }
log() { printf 'setup: %s\n' "$*" >&2; }

# ---------- 1. Debian packages ----------
pkgs=(build-essential cmake ninja-build ccache git pkg-config openmpi-bin libopenmpi-dev libeigen3-dev
      googletest libgtest-dev libgmock-dev libpng-dev libjpeg-dev zlib1g-dev python3 python3-numpy
      python3-matplotlib python3-yaml dpkg-dev ca-certificates)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  [ "$(id -u)" -eq 0 ] || die "missing Debian packages: ${missing[*]}; run this script as root or 'apt-get install ${missing[*]}'"
  log "installing Debian packages: ${missing[*]}"
  apt-get update -qq || die "apt-get update failed: check the network and /etc/apt/sources.list*"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" > /dev/null \
    || die "apt-get install ${missing[*]} failed"
fi
for t in cmake ninja mpicxx mpirun g++ ccache; do
  command -v "$t" > /dev/null || die "required tool '$t' not found after installing packages"
done

# ---------- 2. LAMMPS source ----------
lsrc=$("$here/tools/fetch_lammps.sh" "$cache") || die "could not obtain the LAMMPS source"

# ---------- 3. host LAMMPS (no ESPH inside), cached by version + options ----------
opts=(-D CMAKE_BUILD_TYPE=Release -D BUILD_MPI=on -D BUILD_OMP=on -D BUILD_SHARED_LIBS=on
      -D PKG_PLUGIN=on -D PKG_MACHDYN=on -D PKG_SPH=on -D PKG_GRAPHICS=on -D PKG_OPENMP=on -D DOWNLOAD_EIGEN3=off -D WITH_PNG=on -D WITH_JPEG=on
      -D WITH_GZIP=on -D WITH_FFMPEG=off -D LAMMPS_EXCEPTIONS=on)
key=$(printf '%s\n' "20260704+dfsg-2" "$(g++ -dumpfullversion)" "${opts[@]}" | sha256sum | cut -c1-12)
export CCACHE_DIR="${CCACHE_DIR:-$cache/ccache}" CCACHE_BASEDIR="$cache" CCACHE_NOHASHDIR=1
host="$cache/host-$key"
if [ ! -x "$host/install/bin/lmp" ]; then
  log "building LAMMPS (host, key $key) in $host: about 8 minutes on 2 cores the first time"
  cmake -S "$lsrc/cmake" -B "$host/build" -G Ninja "${opts[@]}" -D CMAKE_CXX_COMPILER_LAUNCHER=ccache \
    -D CMAKE_INSTALL_PREFIX="$host/install" > "$host.configure.log" 2>&1 \
    || die "configuring LAMMPS failed, see $host.configure.log"
  cmake --build "$host/build" -j "$jobs" > "$host.build.log" 2>&1 || die "building LAMMPS failed, see $host.build.log"
  cmake --install "$host/build" > /dev/null || die "installing LAMMPS into $host/install failed"
fi
log "host LAMMPS: $host/install/bin/lmp"

# ---------- 4. this project ----------
cmake -S "$here" -B "$here/build" -G Ninja -D CMAKE_BUILD_TYPE=Release \
  -D LAMMPS_SOURCE_DIR="$lsrc/src" -D LAMMPS_HOST_PREFIX="$host/install" -D ESPH_CACHE="$cache" \
  -D CMAKE_CXX_COMPILER_LAUNCHER=ccache > "$here/build.configure.log" 2>&1 \
  || { tail -n 30 "$here/build.configure.log" >&2; die "configuring the project failed (log: build.configure.log)"; }
cmake --build "$here/build" -j "$jobs" || die "building the project failed"
log "done: build/lmp (ESPH compiled in), build/plugin/esphplugin.so (plugin for $host/install/bin/lmp)"
