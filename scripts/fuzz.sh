#!/usr/bin/env bash
# Fuzzes the scene parser and the --set syntax (fuzz/scene_fuzzer.cpp) with libFuzzer for a
# bounded time. Installs clang if missing (Debian: clang, libclang-rt-14-dev), builds in
# build-fuzz/ with -fsanitize=fuzzer,address,undefined, seeds from fuzz/corpus/ (model files, bad
# scenes, --set cases) and grows a working corpus in build-fuzz/corpus/ (fuzz/corpus/ is never
# modified). Crashes, leaks, timeouts and sanitizer reports are saved as build-fuzz/artifacts/*.
# Usage: bash scripts/fuzz.sh [SECONDS]   (default 60). Exit code: 0 clean, non-zero on a finding.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
jobs="${FUZZ_BUILD_JOBS:-1}"

if ! command -v clang++ >/dev/null 2>&1 || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "fuzz: installing clang and libclang-rt-14-dev"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends clang libclang-rt-14-dev >/dev/null
fi

cmake -S . -B build-fuzz -DROLLERDYN_FUZZ=ON -DBUILD_TESTING=OFF -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz --target scene_fuzzer -j"$jobs"

mkdir -p build-fuzz/corpus build-fuzz/artifacts
log="build-fuzz/fuzz-$(date +%Y%m%d-%H%M%S).log"
echo "fuzz: running scene_fuzzer for ${seconds} s, log in $log"
set +e
start=$SECONDS
# -timeout: one input taking over 10 s is a hang; -rss_limit_mb: runaway memory is a finding.
# The working directory is build-fuzz/, so nothing can land anywhere else even by mistake.
(cd build-fuzz && ./fuzz/scene_fuzzer corpus ../fuzz/corpus -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 -artifact_prefix=artifacts/ \
      -dict=../fuzz/scene.dict) >"$log" 2>&1
rc=$?
set -e
execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}' | tail -1)
echo "fuzz: exit code $rc, ${execs:-unknown} executions in $((SECONDS - start)) s (limit ${seconds} s), corpus $(ls build-fuzz/corpus | wc -l) files"
if [ "$rc" -ne 0 ]; then
  echo "fuzz: FINDING, see $log and build-fuzz/artifacts/:"
  grep -E 'ERROR|SUMMARY|Test unit written' "$log" | head -20
fi
exit "$rc"
