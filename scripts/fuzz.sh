#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang, build-fuzz/) and runs each for SECONDS (default 60)
# from its committed seeds (fuzz/corpus/<t>, fuzz/regressions/<t>), with its dictionary.
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]     targets: datagram scenario kinds objects model input pcap checkpoint
# Prints executions, exec/s and findings per target; exits 1 when any target found something
# (crash, sanitizer report, leak, timeout, out-of-memory): the input is left in
# build-fuzz/findings/<t>/ — make it a regression (fuzz/regressions/<t>/) with its fix.
# Stopped by SIGINT (Ctrl-C; pkill -INT -f build-fuzz/fuzz/fuzz_<t> for a run in the background)
# with no finding: "interrupted", exit 2, the executions so far printed.
# A slow unit (one input over 10 s of wall clock) is listed, not a failure: replay it alone
# (build-fuzz/fuzz/fuzz_<t> FILE); on this machine whole-VM stalls of 17-18 s have made both
# running fuzzers report one at the same second (2 Dec 00:45:35, inputs that run in 0.2-0.5 s).
# New coverage goes to build-fuzz/corpus/<t> (not committed). Runs at nice 19 when NPSNET_FUZZ_NICE
# is unset (the fuzzer then takes only idle CPU); NPSNET_FUZZ_JOBS=N runs N targets at a time.
# NPSNET_FUZZ_RUNS=N (CI): a repeatable run instead, N inputs per target from the committed seeds
# alone with random seed 1 (SECONDS still caps it), so CI finds what a local run of it finds.
# NPSNET_FUZZ_FORK=N: libFuzzer's fork mode, N child processes fuzzing one target at once (its
# corpus merged between jobs), for a long run on several cores; executions are the children's
# total. With NPSNET_FUZZ_RUNS it stops after that many in all, but is no longer repeatable
# (which child runs which input depends on timing). NPSNET_FUZZ_BUILD=DIR builds and runs in DIR
# instead of build-fuzz/ (a second tree, so one long run keeps its binary while another builds).
set -euo pipefail
cd "$(dirname "$0")/.."
B="${NPSNET_FUZZ_BUILD:-build-fuzz}"
secs="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(datagram scenario kinds objects model input pcap checkpoint)
nice_cmd=(nice -n "${NPSNET_FUZZ_NICE:-19}")
if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz: clang++ not found (bash scripts/install-deps.sh installs clang)" >&2
  exit 2
fi
source scripts/ccache.sh
# With ccache, two things made every object miss from a clone in another folder: the coverage
# ignore list is named by its absolute path, which ccache hashes as text (it does not rewrite this
# option under CCACHE_BASEDIR), so its content is hashed instead; and a clang precompiled header
# holds the clone's paths and is not itself cached (its hash differs in every clone), so this tree
# has none (NPSNET_PCH=OFF).
pch=()
if [ "$ccache_on" = 1 ]; then
  export CCACHE_IGNOREOPTIONS="-fsanitize-coverage-ignorelist=*" CCACHE_EXTRAFILES="$PWD/fuzz/coverage-ignore.txt"
  pch=(-DNPSNET_PCH=OFF)
fi
CC=clang CXX=clang++ cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${ccache_args[@]}" "${pch[@]}" -DNPSNET_FUZZ=ON \
  -DNPSNET_TESTS=OFF -DNPSNET_BENCH=OFF -DNPSNET_RENDER=OFF >/dev/null
cmake --build "$B" -j2 --target "${targets[@]/#/fuzz_}"

run_one() {
  local t="$1" dir="$B/runs/$1" seeds=(fuzz/corpus/"$1") out="$B/corpus/$1" repeat=()
  [ -d "fuzz/regressions/$1" ] && seeds+=("fuzz/regressions/$1")
  if [ -n "${NPSNET_FUZZ_RUNS:-}" ]; then
    out="$dir/corpus" && rm -rf "$out"
    repeat=(-runs="$NPSNET_FUZZ_RUNS" -seed=1)
  fi
  mkdir -p "$dir" "$out" "$B/findings/$t"
  local fork=()
  [ -n "${NPSNET_FUZZ_FORK:-}" ] && fork=(-fork="$NPSNET_FUZZ_FORK")
  local dict=()
  [ -f "fuzz/dict/$t.dict" ] && dict=(-dict="fuzz/dict/$t.dict")
  # -max_len: a datagram, capture or file up to 64 KiB (the node's receive buffer); the text
  # tables (scenario, kinds, objects) up to 16 KiB, above their largest seed: past that libFuzzer
  # grows them into thousands of repeated lines, and the rate fell fourfold (scenario: 3,300 -> 850
  # exec/s as its inputs reached 34 KB) for no new coverage.
  local max_len=65536
  case "$t" in scenario | kinds | objects) max_len=16384 ;; esac
  # -rss_limit_mb: a leak or runaway allocation is a finding; -timeout: a hang (s per input,
  # wall clock: 60, past the machine's observed stalls, where 10 ended a 9.1 million-input run
  # on an input that runs in 0.2-0.5 s).
  # malloc_context_size=0: no stack unwound at each allocation (a sixth of the time); a finding's
  # report then lacks where its memory was allocated: replay it ($B/fuzz/fuzz_<t> FILE)
  # without the option for that.
  set +e
  ASAN_OPTIONS=detect_leaks=1:malloc_context_size=0 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "${nice_cmd[@]}" "$B/fuzz/fuzz_$t" -max_total_time="$secs" -timeout=60 -rss_limit_mb=2048 \
      -max_len="$max_len" -print_final_stats=1 "${dict[@]}" "${repeat[@]}" "${fork[@]}" -artifact_prefix="$B/findings/$t/" \
      "$out" "${seeds[@]}" >"$dir/log" 2>&1
  local rc=$?
  set -e
  local execs="" speed="" took=""
  if [ -n "${fork[*]}" ]; then  # fork mode: the last status line's total (a child's stats may be in the log too)
    read -r execs took < <(sed -n 's/^#\([0-9]*\): cov:.* time: \([0-9]*\)s.*/\1 \2/p' "$dir/log" | tail -1) || true
    [ -n "$execs" ] && [ "${took:-0}" -gt 0 ] && speed=$((execs / took))
  else
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
    speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log" | tail -1)
  fi
  local found slow
  found=$(find "$B/findings/$t" -type f ! -name 'slow-unit-*' -newer "$dir/log.start" 2>/dev/null | wc -l)
  slow=$(find "$B/findings/$t" -type f -name 'slow-unit-*' -newer "$dir/log.start" 2>/dev/null | wc -l)
  printf 'fuzz %-9s %10s executions %7s exec/s  %d finding(s)  exit %d\n' "$t" "${execs:-?}" "${speed:-?}" \
    "$found" "$rc"
  [ "$slow" -eq 0 ] || printf '    %d slow unit(s) (over 10 s; not a failure, replay alone): %s/findings/%s/slow-unit-*\n' "$slow" "$B" "$t"
  # 72: libFuzzer stopped by SIGINT (Ctrl-C, or pkill -INT to end a long run): not a finding
  # when it left none; said so, and the script's status says "interrupted".
  if [ "$rc" -eq 72 ] && [ "$found" -eq 0 ]; then
    echo "    interrupted (SIGINT) with no findings; the executions above ran"
    return 2
  fi
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$dir/log" | head -8 | sed 's/^/    /'
    return 1
  fi
}

status=0  # 0 clean, 2 interrupted without findings, 1 findings (the worst of the targets')
note() { if [ "$1" -eq 1 ] || [ "$status" -eq 0 ]; then status=$1; fi; }
jobs_n="${NPSNET_FUZZ_JOBS:-1}"
pids=()
for t in "${targets[@]}"; do
  mkdir -p "$B/runs/$t" && touch "$B/runs/$t/log.start"
  if [ "$jobs_n" -gt 1 ]; then
    run_one "$t" > "$B/runs/$t/summary" & pids+=($!)
    if [ ${#pids[@]} -ge "$jobs_n" ]; then wait "${pids[0]}" || note $?; pids=("${pids[@]:1}"); fi
  else
    run_one "$t" || note $?
  fi
done
for p in "${pids[@]}"; do wait "$p" || note $?; done
if [ "$jobs_n" -gt 1 ]; then for t in "${targets[@]}"; do cat "$B/runs/$t/summary"; done; fi
case $status in
  0) echo "fuzz: no findings" ;;
  2) echo "fuzz: interrupted, no findings" ;;
  *) echo "fuzz: FINDINGS (see above)" ;;
esac
exit $status
