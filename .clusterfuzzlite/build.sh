#!/bin/bash -eu
# Builds the libFuzzer target scenario_fuzzer the way ClusterFuzzLite and OSS-Fuzz call a
# project's build.sh: with their $CXX, $CXXFLAGS (sanitizer and coverage flags), the fuzzing
# engine in $LIB_FUZZING_ENGINE (-fsanitize=fuzzer, or an engine library such as AFL++'s) and the
# output directory $OUT; docs/fleet.md. Also used by `bash .ci/quickstart test` with stand-in
# values (MG_BUILD_DIR and MG_BUILD_TESTS=ON let that stage build the test suite in the same tree,
# MG_FUZZ_INSTRUMENT=ON instruments the libraries and the fuzzer for coverage, not the tests, and
# MG_UNITY_BUILD=ON builds it as a unity build).
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MG_BUILD_DIR:-${WORK:-/tmp}/mergeguard-fuzz-build}
: "${CXX:?}" "${LIB_FUZZING_ENGINE:?}" "${OUT:?}"
CXXFLAGS=${CXXFLAGS:-}

cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_CXX_FLAGS="$CXXFLAGS" -DMG_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DMG_BUILD_TESTS="${MG_BUILD_TESTS:-OFF}" -DMG_BUILD_BENCH=OFF -DMG_FUZZ_INSTRUMENT="${MG_FUZZ_INSTRUMENT:-OFF}" \
  -DMG_UNITY_BUILD="${MG_UNITY_BUILD:-OFF}"
cmake --build "$build_dir" --target scenario_fuzzer -j"$(nproc)"
mkdir -p "$OUT"
cp "$build_dir/scenario_fuzzer" "$OUT/"
# Seed corpus: the curated scenarios, the hostile inputs and the corpus cases (JSON inputs go
# through the strict loaders, docs/fuzzing.md "Coverage-guided fuzzing").
if command -v zip > /dev/null; then
  rm -f "$OUT/scenario_fuzzer_seed_corpus.zip"
  zip -q -j "$OUT/scenario_fuzzer_seed_corpus.zip" "$repo"/corpus/scenarios/*.json "$repo"/tests/hostile/*.json \
    "$repo"/corpus/cases/*.json "$repo"/tests/hostile/recordings/*.xml
fi
