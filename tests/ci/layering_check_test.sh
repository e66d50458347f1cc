#!/usr/bin/env bash
# ci/layering passes on the checkout and fails, naming file:line, the include or link and the rule,
# on a copy of the stage folders with a deliberately wrong include (back up, across parts, from an
# undeclared stage) or a deliberately wrong CMake link (back up, the truth linking the emulators,
# a source compiled in another stage's target, a stage without a target), and (exit 2) on rules
# with a cycle or an exception.
# Usage: layering_check_test.sh SOURCE_DIR
set -euo pipefail
src="$1"
check="$src/ci/layering"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "layering_check_test: FAIL: $*" >&2; exit 1; }

# expect STATUS PATTERN ARGS...: ci/layering ARGS exits STATUS and its output matches PATTERN
expect() {
  local want="$1" pattern="$2" status=0
  shift 2
  "$check" "$@" >"$tmp/out" 2>&1 || status=$?
  ((status == want)) || { cat "$tmp/out" >&2; fail "exit $status, expected $want ($pattern)"; }
  grep -Eq -- "$pattern" "$tmp/out" || { cat "$tmp/out" >&2; fail "no line matches: $pattern"; }
}

# The checkout itself: clean, its known exceptions all found
expect 0 '^ci/layering: clean; .* 0 cycles .* stage targets' "$src"

# A copy of the stage folders' sources, their CMakeLists.txt and the rules
tree="$tmp/tree"
mkdir -p "$tree/ci"
(cd "$src" && find harness firmware_emu estimator \( -name '*.cc' -o -name '*.h' -o -name CMakeLists.txt \) -print0 |
  tar --null -cf - -T -) | tar -xf - -C "$tree"
cp "$src/ci/layering.rules" "$tree/ci/"
expect 0 '^ci/layering: clean' "$tree"
restore() { cp "$src/$1" "$tree/$1"; }

# The ground truth includes the engine: back up, and run reaches truth, so it closes a cycle
f=harness/truth/src/path.cc
echo '#include "hil/harness/engine/engine.h"' >>"$tree/$f"
line=$(wc -l <"$tree/$f")
expect 1 "^$f:$line: #include \"hil/harness/engine/engine.h\": goes back up: harness/engine .*closes a cycle" "$tree"
expect 1 '^ci/layering: 1 layering errors' "$tree"
restore "$f"

# An emulator includes the harness: across parts, back up
first=("$tree"/firmware_emu/src/gnss/*.cc)
f="${first[0]#"$tree"/}"
sed -i '1i #include "hil/harness/scenario/scenario.h"' "$tree/$f"
expect 1 "^$f:1: #include \"hil/harness/scenario/scenario.h\": goes back up: harness/scenario" "$tree"
restore "$f"

# An include of a stage declared above (not yet reached), and one of a stage below that the
# including stage does not declare
f=harness/src/links/capture_format.cc
sed -i '1i #include "hil/harness/validate/validate.h"' "$tree/$f"
expect 1 "^$f:1: .*harness/validate/validate.h\": goes back up: harness/validate" "$tree"
restore "$f"
first=("$tree"/firmware_emu/src/lidar/*.cc)
f="${first[0]#"$tree"/}"
sed -i '1i #include "hil/firmware_emu/link/pty_port.h"' "$tree/$f"
expect 1 "^$f:1: .*: firmware_emu/lidar may not include firmware_emu/link" "$tree"
restore "$f"

# A stage the rules do not know
mkdir -p "$tree/harness/src/newstage"
echo '#include "hil/harness/engine/engine.h"' >"$tree/harness/src/newstage/new.cc"
expect 1 '^harness/src/newstage/new.cc:1: .*stage harness/newstage is not in' "$tree"
rm -r "$tree/harness/src/newstage"

# A stage target that links a stage above it (core, the lowest harness stage, links the run)
f=harness/src/core/CMakeLists.txt
printf 'target_link_libraries(hil_harness_core PRIVATE\n  hil_harness_run)\n' >>"$tree/$f"
line=$(($(wc -l <"$tree/$f") - 1))
expect 1 "^$f:$line: hil_harness_core links hil_harness_run \(stage harness/run\): goes back up: harness/run reaches harness/core" "$tree"
expect 1 '^ci/layering: 1 layering errors' "$tree"
restore "$f"

# The ground truth links the emulators (the aggregate: every firmware_emu stage) instead of their core
f=harness/CMakeLists.txt
sed -i 's/PUBLIC hil_firmware_emu_core/PUBLIC hil::firmware_emu/' "$tree/$f"
expect 1 "^$f:[0-9]+: hil_truth links hil::firmware_emu \(stage firmware_emu/mcu\): harness/truth does not declare firmware_emu/mcu" "$tree"
restore "$f"

# A component links one it does not declare, below it in the table (lidar: mcu and world only)
f=firmware_emu/src/lidar/CMakeLists.txt
sed -i 's/PUBLIC hil_firmware_emu_mcu/PUBLIC hil_firmware_emu_link hil_firmware_emu_mcu/' "$tree/$f"
expect 1 "^$f:[0-9]+: hil_firmware_emu_lidar links hil_firmware_emu_link \(stage firmware_emu/link\): firmware_emu/lidar does not declare" "$tree"
restore "$f"

# A stage's source compiled into another stage's target, and a stage left without a target
f=harness/src/core/CMakeLists.txt
printf 'target_sources(hil_harness_core PRIVATE ../run/run.cc)\n' >>"$tree/$f"
expect 1 "^$f:[0-9]+: hil_harness_core \(stage harness/core\) compiles ../run/run.cc, a source of stage harness/run" "$tree"
restore "$f"
f=harness/src/suite/CMakeLists.txt
sed -i 's/hil_harness_suite/hil_harness_suite_all/g' "$tree/$f"
expect 1 "layering.rules:[0-9]+: stage harness/suite has no CMake target of its own" "$tree"
restore "$f"
expect 0 '^ci/layering: clean' "$tree"

# Rules that list a stage above the one declaring it (a cycle in the table): exit 2
printf 'a/x: a/y\na/y:\n' >"$tmp/bad.rules"
expect 2 'bad.rules:1: a/x lists a/y, which is not declared above it' --rules "$tmp/bad.rules" "$tree"

# Rules with an exception (the list of known wrong-way includes is gone): exit 2
cp "$src/ci/layering.rules" "$tmp/except.rules"
echo 'except harness/src/links/capture_format.cc hil/harness/run/run_guard.h' >>"$tmp/except.rules"
expect 2 'except.rules:[0-9]+: a rule is `STAGE: STAGE...` \(no exceptions' --rules "$tmp/except.rules" "$tree"

echo "layering_check_test: all cases pass"
