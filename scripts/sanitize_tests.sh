#!/usr/bin/env bash
# The core's ROS-free gtests (every test/test_*.cpp that includes no ROS header, the sphere_sim
# ones included, running a sanitized sphere_sim) built with clang under AddressSanitizer (leaks
# included) and UndefinedBehaviorSanitizer, then run: any report fails its test, so the expected
# outcome is every test passing with 0 reports. The build is test/fuzz/CMakeLists.txt with
# -DSANITIZED_TESTS=ON, in build-fuzz/, sharing the sanitized core with scripts/fuzz.sh.
# Not part of scripts/run_tests.sh (the CI): it is a second full build (every gtest compiled again
# with clang and the sanitizers, about 12 minutes on a busy 2-core machine, after the sanitized
# core that fuzz.sh also builds) and the sanitized gtests run for about 27 minutes; run it by hand.
# Exit status: ctest's (0: every test passed).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$SR_ROOT"
build=$SR_ROOT/build-fuzz

build_sanitized_tests() {
  mkdir -p "$build"
  cmake -S test/fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DSANITIZED_TESTS=ON \
    > "$build/configure.log" 2>&1 || { cat "$build/configure.log"; return 1; }
  make -C "$build" -j2 -k --no-print-directory sanitized_tests > "$build/make_tests.log" 2>&1 \
    || { tail -40 "$build/make_tests.log"; return 1; }
}
run_sanitized_tests() {
  # halt_on_error: the first report ends the test (and fails it); UBSan prints its stack.
  ASAN_OPTIONS=detect_leaks=1:halt_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$build" -j2 --output-on-failure --timeout 1800
}
sr_step "build the core's gtests with ASan + UBSan (build-fuzz/)" build_sanitized_tests
sr_step "run them" run_sanitized_tests
