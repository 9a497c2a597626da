#!/usr/bin/env bash
# Renders a report page in headless Chromium to a screenshot, to check by eye that the figures and
# tables of `rollerdyn report` look right. The page must need no network: Chromium runs with
# networking features off, and the page is loaded from a file:// URL.
# Installs chromium (Debian package) if missing.
# Usage: bash scripts/check-report.sh DIR [HEIGHT]   (DIR holds report.html; writes DIR/report.png,
#        1200 px wide, HEIGHT px tall, default 3000; e.g. 16000 to see every figure)
set -euo pipefail
dir="${1:?usage: bash scripts/check-report.sh DIR  (the --out folder of rollerdyn report)}"
height="${2:-3000}"
page="$(cd "$dir" && pwd)/report.html"
[ -f "$page" ] || { echo "check-report: no report.html in $dir" >&2; exit 2; }

if ! command -v chromium >/dev/null 2>&1; then
  echo "check-report: installing chromium"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq chromium >/dev/null
fi

profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
shot="$(cd "$dir" && pwd)/report.png"
rm -f "$shot"
timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --screenshot="$shot" --window-size=1200,"$height" "file://$page" \
  >/dev/null 2>&1 || true
if [ ! -s "$shot" ]; then
  echo "check-report: chromium wrote no screenshot" >&2
  exit 1
fi
echo "check-report: $shot ($(stat -c %s "$shot") bytes): open it and check the figures and tables"
