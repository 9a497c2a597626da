#!/usr/bin/env bash
# Renders a report page in headless Chromium, to check by eye that the mechanism animation, the
# interactive time plots, the figures and the tables of `rollerdyn report` look right, and prints
# what the page's own scripts recorded (script errors, charts drawn, figures decoded, the frame
# shown). The page must need no network: Chromium runs with networking features off, and the page
# is loaded from a file:// URL. Installs chromium (Debian package) if missing.
# Usage: bash scripts/check-report.sh DIR [HEIGHT] [T]
#   DIR holds report.html; writes DIR/report.png, 1200 px wide, HEIGHT px tall (default 3000;
#   e.g. 16000 to see every figure). T (seconds): show the mechanism paused at t = T (the page's
#   #t=T address); without it the animation plays for about 2 s first.
set -euo pipefail
dir="${1:?usage: bash scripts/check-report.sh DIR [HEIGHT] [T]  (the --out folder of rollerdyn report)}"
height="${2:-3000}"
at="${3:-}"
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
url="file://$page"
[ -n "$at" ] && url="$url#t=$at"
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --hide-scrollbars
       --disable-background-networking --disable-component-update --disable-sync
       --user-data-dir="$profile" --virtual-time-budget=2000)
timeout 120 chromium "${flags[@]}" --screenshot="$shot" --window-size=1200,"$height" "$url" >/dev/null 2>&1 || true
if [ ! -s "$shot" ]; then
  echo "check-report: chromium wrote no screenshot" >&2
  exit 1
fi
echo "check-report: $shot ($(stat -c %s "$shot") bytes): open it and check the animation, plots, figures and tables"

dom="$(timeout 120 chromium "${flags[@]}" --dump-dom "$url" 2>/dev/null || true)"
attr() { { grep -o "$1" <<<"$dom" || true; } | head -1 | sed 's/.*="\(.*\)"/\1/'; }
errors="$(attr 'data-script-errors="[^"]*"')"
echo "check-report: shown t = $(attr '<section id="mechanism"[^>]*data-t="[^"]*"') s;" \
     "charts drawn $(attr 'data-painted="[^"]*"')/$(attr 'data-charts="[^"]*"');" \
     "figures decoded $(attr 'data-figures="[^"]*"'); script errors: ${errors:-none}"
[ -z "$errors" ]
