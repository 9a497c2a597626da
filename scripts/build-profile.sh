#!/usr/bin/env bash
# Where the build's CPU time goes: configures a fresh build folder whose compiler and linker run
# under /usr/bin/time (this script is its own launcher), builds everything once and prints the
# CPU seconds (user + sys) per part (src/<layer>, tests, the Python module, benchmarks,
# precompiled headers, links), the slowest files and the links. CPU, not wall: the figures hold
# on a shared machine. docs/development.md ("How long things take") quotes its output.
# Usage: bash scripts/build-profile.sh [BUILD_DIR (default build-profile)] [extra cmake arguments]
set -euo pipefail
if [ "${1:-}" = "--launch" ]; then   # as the compiler/linker launcher: time one command
  shift
  t=$(mktemp)
  rc=0
  /usr/bin/time -f "%U %S %e" -o "$t" "$@" || rc=$?
  kind=link out="" src="" prev=""
  for a in "$@"; do
    [ "$prev" = "-o" ] && out=$a
    [ "$a" = "-c" ] && kind=compile
    case "$a" in *.cpp|*.cc|*.cxx) src=$a ;; esac
    prev=$a
  done
  [ $kind = compile ] && [ -n "$src" ] && out=$src
  echo "$(tail -1 "$t") $kind $out" >> "$ROLLERDYN_PROFILE_LOG"
  rm -f "$t"
  exit $rc
fi
cd "$(dirname "$0")/.."
dir=${1:-build-profile}
shift || true
self="$(pwd)/scripts/build-profile.sh"
rm -rf "$dir"
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER_LAUNCHER=$self;--launch" \
      "-DCMAKE_CXX_LINKER_LAUNCHER=$self;--launch" "$@" > /dev/null
export ROLLERDYN_PROFILE_LOG="$(pwd)/$dir/profile.log"
start=$(date +%s)
nice -n 10 cmake --build "$dir" -j"$(nproc)" > "$dir/build.log"
echo "wall $(( $(date +%s) - start )) s on $(nproc) processors (load average now: $(cut -d' ' -f1-3 /proc/loadavg))"
/usr/bin/python3 - "$ROLLERDYN_PROFILE_LOG" "$(pwd)/" <<'PY'
import collections, re, sys
rows = []
for line in open(sys.argv[1]):
    f = line.split(None, 4)
    if len(f) == 5:
        rows.append((float(f[0]) + float(f[1]), f[3], f[4].strip().replace(sys.argv[2], "")))
def part(kind, target):
    name = target.rsplit("/", 1)[-1]
    if kind == "link":
        return "link: tests" if name.startswith("test_") else "link: benchmarks" if name.startswith("bench_") else "link: " + name
    if "cmake_pch" in target:
        return "precompiled headers"
    m = re.match(r"(src|tests|benchmarks)/([^/]+)/", target)
    if not m:
        return "other"
    return {"tests": "tests", "benchmarks": "benchmarks"}.get(m.group(1), "src/" + m.group(2))
total = collections.defaultdict(float)
count = collections.Counter()
for cpu, kind, target in rows:
    total[part(kind, target)] += cpu
    count[part(kind, target)] += 1
print(f"CPU {sum(total.values()):.0f} s in {len(rows)} commands")
for p, cpu in sorted(total.items(), key=lambda x: -x[1]):
    print(f"{cpu:8.1f} s  {count[p]:4d}  {p}")
print("slowest files:")
for cpu, kind, target in sorted((r for r in rows if r[1] == "compile"), key=lambda r: -r[0])[:20]:
    print(f"{cpu:8.1f} s  {target}")
PY
