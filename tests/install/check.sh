#!/usr/bin/env bash
# Installs this build into a fresh prefix and uses it as a user would:
# the installed tabletop, run from another folder, finds its own files
# under PREFIX/share/tabletop (not the source tree), shipped scenes by
# name among them; the example programs are named tabletop-example...;
# the headers are included as <tabletop/...> with only PREFIX/include on
# the path (the exported targets name no other folder of ours, and no
# installed header includes one of ours any other way); the consumer
# example (examples/consumer) is configured against the installed CMake
# package, built, and run, its cube sliding the closed-form 0.1019 m; the
# installed Python module, if built, lies where the prefix's Python looks
# (checked for /usr/local without installing there), runs a scenario from
# the prefix and finds a shipped scene's name there.
# Usage: check.sh SOURCE_DIR BUILD_DIR [CMAKE_BUILD_TYPE]
set -euo pipefail
source_dir=$1 build_dir=$2 build_type=${3:-Release}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build_dir" --prefix "$prefix" > "$work/install.log"
for f in bin/tabletop bin/tabletop-example1_single_cube bin/tabletop-example2_two_cubes bin/tabletop-example3_stacked_cubes \
         bin/tabletop-example4_two_spheres lib/libtabletop_sim.a include/tabletop/sim/SceneBuilder.h \
         share/tabletop/scenarios/example1_single_cube.json share/tabletop/scenarios/analytic/free_flight.json \
         share/tabletop/scenarios/hard/tall_stack_10.json share/tabletop/data/tolerance_front.json share/tabletop/data/schema/scenario.schema.json \
         share/tabletop/data/schema/run-output.schema.json \
         lib/cmake/tabletop/tabletopConfig.cmake; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f was not installed"; exit 1; }
done

# Nothing generic in PREFIX/bin: every program is tabletop or tabletop-*.
others=$(find "$prefix/bin" -mindepth 1 ! -name tabletop ! -name 'tabletop-*')
[ -z "$others" ] || { echo "FAIL: installed under a generic name: $others"; exit 1; }
# The exported include folder is PREFIX/include alone, and the installed
# headers include ours only as <tabletop/...>.
ours=$(grep -ho 'INTERFACE_INCLUDE_DIRECTORIES "[^"]*"' "$prefix"/lib/cmake/tabletop/tabletopTargets.cmake \
  | grep -o '${_IMPORT_PREFIX}[^;"]*' | sort -u)
[ "$ours" = '${_IMPORT_PREFIX}/include' ] \
  || { echo "FAIL: the exported targets' include folders in the prefix are not PREFIX/include alone: $ours"; exit 1; }
layers=$(cd "$prefix/include/tabletop" && ls -d */ | tr -d / | paste -sd'|')
unprefixed=$(grep -rnE "#include [\"<]($layers)/" "$prefix/include/tabletop" || true)
[ -z "$unprefixed" ] || { echo "FAIL: installed headers include ours without tabletop/:"; echo "$unprefixed"; exit 1; }

cd "$work"
version=$(env -u TABLETOP_DATA_DIR "$prefix/bin/tabletop" --version)
echo "$version"
grep -qxF "data: $prefix/share/tabletop" <<< "$version" \
  || { echo "FAIL: the installed program does not read its files from $prefix/share/tabletop"; exit 1; }
env -u TABLETOP_DATA_DIR "$prefix/bin/tabletop" bench --cases free_flight --rates 60 --iterations 10 --repeats 1 \
  --modes bullet > bench.txt
grep -q "^free_flight" bench.txt || { echo "FAIL: the installed bench found no shipped scene"; cat bench.txt; exit 1; }
# A shipped scene by name, from the prefix's data.
env -u TABLETOP_DATA_DIR "$prefix/bin/tabletop" list | grep -q "^hard/tall_stack_10 " \
  || { echo "FAIL: the installed list does not name hard/tall_stack_10"; exit 1; }
env -u TABLETOP_DATA_DIR "$prefix/bin/tabletop" run example1_single_cube | head -1 \
  | grep -qF "($prefix/share/tabletop/scenarios/example1_single_cube.json)" \
  || { echo "FAIL: the installed run did not read example1_single_cube from $prefix/share/tabletop"; exit 1; }

cmake -S "$source_dir/examples/consumer" -B consumer -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE="$build_type" > consumer-configure.log \
  || { cat consumer-configure.log; exit 1; }
cmake --build consumer > consumer-build.log || { cat consumer-build.log; exit 1; }
! grep -q -- "$prefix/include/tabletop" consumer/CMakeFiles/slide.dir/flags.make \
  || { echo "FAIL: the consumer was compiled with $prefix/include/tabletop on its path"; exit 1; }
out=$(consumer/slide)
echo "$out"
grep -q "slid 0.1019 m (closed form 0.1019 m)" <<< "$out" || { echo "FAIL: the consumer's cube did not slide 0.1019 m"; exit 1; }
grep -qxF "$out" "$source_dir/docs/library.md" || { echo "FAIL: docs/library.md does not show the consumer's output as it runs"; exit 1; }
# The Python module, where the build made one: imported from the prefix,
# it runs a shipped scenario from the installed data, by path and by name.
module=$(find "$prefix" -name 'tabletop*.so' -path '*python3*' | head -1)
if [ -n "$module" ]; then
  # Where the module went, and that the same rule puts it on sys.path for
  # /usr/local (or into the folder that PYTHONPATH names elsewhere).
  site=$(/usr/bin/python3 "$source_dir/cmake/PythonSiteDir.py" "$prefix")
  [ "$(dirname "$module")" = "$prefix/$site" ] || { echo "FAIL: the module is at $module, not in $prefix/$site"; exit 1; }
  local_site=/usr/local/$(/usr/bin/python3 "$source_dir/cmake/PythonSiteDir.py" /usr/local)
  /usr/bin/python3 -c "import site, sys; sys.exit('$local_site' not in site.getsitepackages())" \
    || { echo "FAIL: installed under /usr/local, the module would be in $local_site, not on python3's path"; exit 1; }
  # A sanitized module needs the sanitizer's runtime loaded first
  # (TABLETOP_PYTHON_PRELOAD, set by tests/CMakeLists.txt in such a build).
  preload=()
  [ -n "${TABLETOP_PYTHON_PRELOAD:-}" ] \
    && preload=(env "LD_PRELOAD=$TABLETOP_PYTHON_PRELOAD" "ASAN_OPTIONS=detect_leaks=0:intercept_tls_get_addr=0")
  out=$(PYTHONPATH=$(dirname "$module") "${preload[@]}" /usr/bin/python3 -c "import tabletop; \
r = tabletop.run('$prefix/share/tabletop/scenarios/example1_single_cube.json'); print(r['state_hash'], r['complete'])")
  echo "python: $out"
  grep -q " True$" <<< "$out" || { echo "FAIL: the installed Python module did not run example 1"; exit 1; }
  file=$(env -u TABLETOP_DATA_DIR PYTHONPATH=$(dirname "$module") "${preload[@]}" /usr/bin/python3 -c "import tabletop; \
print(tabletop.load('example1_single_cube').file)")
  [ "$file" = "$prefix/share/tabletop/scenarios/example1_single_cube.json" ] \
    || { echo "FAIL: the installed Python module read example1_single_cube from $file"; exit 1; }
fi
echo "1 passed, 0 failed"
