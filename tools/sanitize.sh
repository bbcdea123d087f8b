#!/bin/bash
# The ESPH tests once under AddressSanitizer and UndefinedBehaviorSanitizer.
#
# Builds the plugin, the unit tests and the LAMMPS library tests with
# -fsanitize=address,undefined -fno-omit-frame-pointer in a separate build directory
# (build-asan, no compiled-in lmp), then runs
#   1. the unit tests (test_esph_units)
#   2. the LAMMPS library tests (test_esph_lammps, test_plugin_load: sanitized
#      executables on the host liblammps, the sanitized plugin loaded into them)
#   3. the plugin autoload check and the bad-input suite with the host lmp, which is not
#      sanitized: the ASan runtime is preloaded (LD_PRELOAD) so that the sanitized plugin
#      can be loaded into it
# Any sanitizer report fails the run: UBSan stops at the first report
# (halt_on_error=1), the bad-input runner fails a case whose output holds one.
# tools/asan.supp suppresses one report from inside Open MPI (see there).
# Leak checking is off (ASAN_OPTIONS=detect_leaks=0): Open MPI and LAMMPS's own
# allocations at exit drown the output in leak reports that are not ESPH's.
#
# usage: tools/sanitize.sh [BUILD_DIR]     (default build-asan; about 5 minutes on 2 cores)
# environment: LAMMPS_SOURCE_DIR, LAMMPS_HOST_PREFIX (default: the setup's cache), JOBS (2)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
bdir=${1:-$root/build-asan}
cache=${ESPH_CACHE:-/var/cache/esph}
src=${LAMMPS_SOURCE_DIR:-$cache/lammps-20260704/src}
host=${LAMMPS_HOST_PREFIX:-$(ls -d "$cache"/host-*/install 2>/dev/null | head -n 1)}
jobs=${JOBS:-2}
python=/usr/bin/python3
[ -f "$src/lammps.h" ] || { echo "sanitize.sh: no LAMMPS source in $src" >&2; exit 1; }
[ -x "$host/bin/lmp" ] || { echo "sanitize.sh: no host LAMMPS in '$host'" >&2; exit 1; }

flags="-fsanitize=address,undefined -fno-omit-frame-pointer"
launcher=()
command -v ccache > /dev/null && launcher=(-D CMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$bdir" -G Ninja -D CMAKE_BUILD_TYPE=RelWithDebInfo \
  -D LAMMPS_SOURCE_DIR="$src" -D LAMMPS_HOST_PREFIX="$host" -D ESPH_BUILD_LMP=OFF \
  -D CMAKE_CXX_FLAGS="$flags" -D CMAKE_EXE_LINKER_FLAGS="$flags" \
  -D CMAKE_MODULE_LINKER_FLAGS="$flags" -D CMAKE_SHARED_LINKER_FLAGS="$flags" \
  "${launcher[@]}" > "$bdir.configure.log"
cmake --build "$bdir" -j "$jobs"

# tools/asan.supp: Open MPI's own use-after-free in MPI_Abort (not ESPH, not LAMMPS)
export ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:abort_on_error=0:suppressions=$root/tools/asan.supp
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export OMPI_MCA_rmaps_base_oversubscribe=1
asan=$(g++ -print-file-name=libasan.so)
status=0

echo "== unit tests"
"$bdir/tests/test_esph_units" --gtest_brief=1 || status=1

echo "== LAMMPS library tests"
(cd "$bdir/tests" && LAMMPS_PLUGIN_PATH="$bdir/plugin" ESPH_REQUIRE_PLUGIN=1 \
  ./test_esph_lammps --gtest_brief=1) || status=1
(cd "$bdir/tests" && env -u LAMMPS_PLUGIN_PATH ./test_plugin_load --gtest_brief=1) || status=1

# host lmp with the sanitized plugin: the ASan runtime first
wrapper="$bdir/lmp-asan"
cat > "$wrapper" << EOF
#!/bin/sh
LD_PRELOAD=$asan LD_LIBRARY_PATH=$host/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH} \\
  LAMMPS_PLUGIN_PATH=$bdir/plugin exec $host/bin/lmp "\$@"
EOF
chmod +x "$wrapper"

echo "== plugin autoload into the host lmp"
"$python" "$root/tests/physics/check_autoload.py" "$wrapper" "$bdir/plugin" || status=1

echo "== bad-input suite"
"$python" "$root/tests/badinput/run_badinput.py" --lmp "$wrapper" --mpirun mpirun \
  --jobs "$jobs" --timeout 120 --workdir "$bdir/badinput" || status=1

if [ $status -eq 0 ]; then
  echo "sanitize.sh: clean (ASan + UBSan, leak checking off)"
else
  echo "sanitize.sh: FAILED (see above)"
fi
exit $status
