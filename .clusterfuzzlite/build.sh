#!/bin/bash -eu
# Builds the libFuzzer targets, one per input type, the way ClusterFuzzLite and OSS-Fuzz call a
# project's build.sh: with their $CXX, $CXXFLAGS (sanitizer and coverage flags), the fuzzing
# engine in $LIB_FUZZING_ENGINE (-fsanitize=fuzzer, or an engine library such as AFL++'s) and the
# output directory $OUT; docs/fleet.md. Each target goes to $OUT with its seed corpus
# (<target>_seed_corpus.zip) and its dictionary (<target>.dict), the names OSS-Fuzz looks for.
# The seed corpora are also left unzipped in <build dir>/seed_corpus/<target>/.
# Also used by `bash .ci/quickstart test` with stand-in values (MG_BUILD_DIR and MG_BUILD_TESTS=ON
# let that stage build the test suite in the same tree, MG_FUZZ_INSTRUMENT=ON instruments the
# libraries and the fuzz targets for coverage, not the tests, and MG_UNITY_BUILD=ON builds it as a
# unity build).
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MG_BUILD_DIR:-${WORK:-/tmp}/mergeguard-fuzz-build}
: "${CXX:?}" "${LIB_FUZZING_ENGINE:?}" "${OUT:?}"
# Absolute, since the seed corpora are gathered from the repository's root.
mkdir -p "$build_dir" "$OUT"
build_dir=$(cd "$build_dir" && pwd)
OUT=$(cd "$OUT" && pwd)
CXXFLAGS=${CXXFLAGS:-}

# target, its source directory (where its .dict and <target>_seeds/ are), then the repository's
# own inputs that seed it too (files or directories, relative to the repository).
targets=(
  "scenario_fuzzer fuzz"
  "json_loader_fuzzer fuzz corpus/scenarios corpus/cases tests/hostile/*.json tests/hostile/traces docs/audit_profile.default.json"
  "commonroad_fuzzer src/recording tests/hostile/recordings"
)

cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_CXX_FLAGS="$CXXFLAGS" -DMG_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DMG_BUILD_TESTS="${MG_BUILD_TESTS:-OFF}" -DMG_BUILD_BENCH=OFF -DMG_FUZZ_INSTRUMENT="${MG_FUZZ_INSTRUMENT:-OFF}" \
  -DMG_UNITY_BUILD="${MG_UNITY_BUILD:-OFF}"
names=()
for t in "${targets[@]}"; do names+=("${t%% *}"); done
cmake --build "$build_dir" --target "${names[@]}" -j"$(nproc)"

cd "$repo"
for t in "${targets[@]}"; do
  read -r name dir inputs <<< "$t"
  cp "$build_dir/$name" "$OUT/"
  cp "$dir/$name.dict" "$OUT/$name.dict"
  # One flat directory, each file named after its path so that equal names (tests/hostile/empty.json,
  # tests/hostile/traces/empty.json) stay apart.
  seeds="$build_dir/seed_corpus/$name"
  rm -rf "$seeds"
  mkdir -p "$seeds"
  # shellcheck disable=SC2086  # $inputs is a list of paths and globs
  find "$dir/${name}_seeds" $inputs -type f | while read -r f; do cp "$f" "$seeds/${f//\//_}"; done
  rm -f "$OUT/${name}_seed_corpus.zip"
  if command -v zip > /dev/null; then
    (cd "$seeds" && zip -q -r "$OUT/${name}_seed_corpus.zip" .)
  else
    (cd "$seeds" && python3 -m zipfile -c "$OUT/${name}_seed_corpus.zip" ./*)
  fi
done
