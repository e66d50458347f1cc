#!/usr/bin/env bash
# lintian over every .deb in DIR: fails on any error (warnings are printed, and allowed).
# Usage: deb_lintian.sh DIR
set -euo pipefail
shopt -s nullglob
debs=("$1"/*.deb)
((${#debs[@]})) || { echo "deb_lintian: no .deb in $1" >&2; exit 1; }
command -v lintian >/dev/null || { echo "deb_lintian: lintian not found (ci/setup installs it)" >&2; exit 1; }
# lintian leaves its MLDBM caches (mldbm-elf-*) in $TMPDIR: a folder of its own, removed after
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hil-lintian.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
TMPDIR=$tmp lintian --fail-on error --tag-display-limit 0 "${debs[@]}"
echo "deb_lintian: ${#debs[@]} packages, no errors"
