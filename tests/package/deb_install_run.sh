#!/usr/bin/env bash
# Installs the navd and hil packages of DIR into a scratch root with dpkg --root (the scratch root's
# own dpkg database: the host's libraries stand in for the declared dependencies, hence
# --force-depends), runs the installed hil on its embedded default scenario (it finds the installed
# navd beside itself), checks the run passed and left its report, then removes both packages and
# checks that nothing of theirs is left but the configuration dpkg keeps until a purge.
# Usage: deb_install_run.sh DIR VERSION
set -euo pipefail
dir="$1" version="$2"
arch="$(dpkg --print-architecture)"
hil_deb="$dir/hil_${version}_${arch}.deb" navd_deb="$dir/navd_${version}_${arch}.deb"
for f in "$hil_deb" "$navd_deb"; do
  [ -f "$f" ] || { echo "deb_install_run: $f missing (deb_build makes it)" >&2; exit 1; }
done
root="$(mktemp -d "${TMPDIR:-/tmp}/hil-deb-root.XXXXXX")"
trap 'rm -rf "$root"' EXIT
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates" "$root/var/lib/dpkg/triggers"
touch "$root/var/lib/dpkg/status" "$root/var/lib/dpkg/available"
dpkg_root=(dpkg --root="$root" --log=/dev/null --force-depends --force-not-root)

"${dpkg_root[@]}" -i "$navd_deb" "$hil_deb"
dpkg-query --admindir="$root/var/lib/dpkg" -W -f='${Package} ${Version} ${Status}\n' hil navd
for f in usr/bin/hil usr/bin/navd usr/share/hil/scenarios/default.yaml etc/navd/navd.conf \
         usr/lib/systemd/system/navd.service; do
  [ -e "$root/$f" ] || { echo "deb_install_run: /$f not installed" >&2; exit 1; }
done
grep -qx "ExecStart=/usr/bin/navd --config /etc/navd/navd.conf" "$root/usr/lib/systemd/system/navd.service"

# the installed hil, default scenario (run folder in the scratch root)
"$root/usr/bin/hil" run --out "$root/run"
grep -q '"pass": *true' "$root/run/report.json" || { echo "deb_install_run: run did not pass" >&2; exit 1; }
grep -q "\"command\": *\"$root/usr/bin/navd --config" "$root/run/report.json" ||
  { echo "deb_install_run: the run did not use the installed navd" >&2; exit 1; }

"${dpkg_root[@]}" -r hil navd
for f in usr/bin/hil usr/bin/navd usr/share/hil; do
  [ ! -e "$root/$f" ] || { echo "deb_install_run: /$f left after removal" >&2; exit 1; }
done
echo "deb_install_run: installed, ran the default scenario (pass), removed"
