#!/usr/bin/env bash
# Unpacks the navd and hil packages of DIR with dpkg -x into a scratch root (no package database,
# nothing installed on the machine) and, from there, with no path of the checkout:
#  - checks that every file a shipped scenario names (closed_loop.path_file, include:) is in the
#    package, found the way hil finds it (beside the scenario, then PREFIX/share/hil/scenarios/lib);
#  - runs the installed closed-loop scenario closed_loop/diff_drive_serial.yaml (--short: 45 s
#    of emulated time, virtual mode) with the installed hil, navd and guidanced, and checks that it
#    passed, that its controller was the installed guidanced on the installed path file, and that
#    nothing in its report names the checkout;
#  - checks every manual page: lexgrog's NAME line is "<page> - <description>" and the page as man
#    shows it holds no "???" (help2man's stand-in for a character it could not convert).
# Usage: deb_closed_loop_run.sh DIR VERSION SOURCE_DIR
set -euo pipefail
dir="$1" version="$2" source_dir="$3"
arch="$(dpkg --print-architecture)"
fail() { echo "deb_closed_loop_run: $*" >&2; exit 1; }
root="$(mktemp -d "${TMPDIR:-/tmp}/hil-deb-x.XXXXXX")"
trap 'rm -rf "$root"' EXIT
for p in navd hil; do
  deb="$dir/${p}_${version}_${arch}.deb"
  [ -f "$deb" ] || fail "$deb missing (deb_build makes it)"
  dpkg -x "$deb" "$root"
done
for f in usr/bin/hil usr/bin/navd usr/bin/guidanced usr/share/hil/paths/ab_line_east_300m.path \
         usr/share/hil/scenarios/closed_loop/diff_drive_serial.yaml; do
  [ -e "$root/$f" ] || fail "/$f not in the packages"
done

# every file the shipped scenarios name, resolved inside the root
scenarios="$root/usr/share/hil/scenarios"
checked=0
while IFS= read -r -d '' y; do
  here="$(dirname "$y")"
  while IFS= read -r v; do
    [ -f "$here/$v" ] || fail "${y#"$root"}: path_file $v is not in the packages"
    checked=$((checked + 1))
  done < <(sed -n 's/^ *path_file: *\([^ #]*\).*/\1/p' "$y")
  while IFS= read -r v; do
    [ -f "$here/$v" ] || [ -f "$scenarios/lib/$v" ] ||
      fail "${y#"$root"}: include $v is not in the packages"
    checked=$((checked + 1))
  done < <(sed -n 's/^ *include: *\[\(.*\)\].*/\1/p' "$y" | tr ',' '\n' | tr -d ' ')
done < <(find "$scenarios" -name '*.yaml' -print0)
((checked > 0)) || fail "no path_file or include found in the installed scenarios"
echo "deb_closed_loop_run: $checked files named by the installed scenarios are in the packages"

# the closed loop from the unpacked root, outside the checkout, with no scenario library override
cd "$root"
rc=0
env -u HIL_SCENARIO_LIB -u HIL_SOURCE_DIR -u HIL_BIN_DIR "$root/usr/bin/hil" run \
  "$scenarios/closed_loop/diff_drive_serial.yaml" --short --no-html --out "$root/run" \
  >"$root/hil.log" 2>&1 || rc=$?
tail -n 25 "$root/hil.log"
report="$root/run/report.json"
[ -f "$report" ] || fail "no report.json (hil exit $rc)"
((rc == 0)) || fail "the installed closed loop did not pass (hil exit $rc)"
grep -q '"pass": *true' "$report" || fail "report.json: not a pass"
controller="$(grep -o '"controller_command": *"[^"]*"' "$report")"
ctl_exe="$(sed 's/^"controller_command": *"\(exec \)\{0,1\}\([^ ]*\) .*/\2/' <<<"$controller")"
ctl_path="$(realpath -m "$(sed 's/.* --path \([^ ]*\) .*/\1/' <<<"$controller")")"
[ "$ctl_exe" = "$root/usr/bin/guidanced" ] && [ "$ctl_path" = "$(realpath "$root")/usr/share/hil/paths/ab_line_east_300m.path" ] ||
  fail "the controller was not the installed guidanced on the installed path: $controller"
! grep -q "$source_dir" "$report" || fail "report.json names the checkout $source_dir"

# manual pages
pages=0
for page in "$root"/usr/share/man/man*/*.gz; do
  name="$(basename "$page")"
  name="${name%%.*}"
  line="$(lexgrog "$page" | sed 's/^[^:]*: *//')"
  [[ "$line" == "\"$name - "* ]] || fail "$page: lexgrog NAME line $line (expected \"$name - …\")"
  [[ "$line" != *'???'* ]] || fail "$page: lexgrog NAME line $line"
  ! MANWIDTH=100 man -l "$page" 2>/dev/null | grep -n '???' ||
    fail "$(basename "$page"): the page shows ??? (above)"
  echo "deb_closed_loop_run: $(basename "$page"): $line"
  pages=$((pages + 1))
done
((pages == 3)) || fail "$pages manual pages, expected 3 (hil.1, guidanced.1, navd.8)"
echo "deb_closed_loop_run: unpacked, ran closed_loop/diff_drive_serial --short from the packages (pass), $pages manual pages checked"
