#!/usr/bin/env bash
# A run stopped by SIGTERM or SIGINT leaves no temporary file and no partial output (issue 21).
# Usage: kill_test.sh CLOTHLAB SCENE WORKDIR. Each case starts a long run, lets it write for a
# moment, sends the signal, and checks that the process died of it and left nothing behind.
set -uo pipefail
clothlab=$1 scene=$2 work=$3
set -m  # background jobs get their own process group, so SIGINT is not ignored in them
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0

# run_case NAME SIGNAL WAIT_SECONDS TEMP_GLOB OUTPUT COMMAND...
run_case() {
  local name=$1 signal=$2 wait=$3 glob=$4 output=$5
  shift 5
  "$@" >"$work/$name.log" 2>&1 &
  local pid=$!
  # Wait until the temporary file exists (the run is under way), at most WAIT seconds.
  for _ in $(seq 1 $((wait * 10))); do
    compgen -G "$work/$glob" >/dev/null && break
    sleep 0.1
  done
  local seen=no
  compgen -G "$work/$glob" >/dev/null && seen=yes
  kill -s "$signal" "$pid"
  wait "$pid"
  local rc=$?
  local left
  left=$(compgen -G "$work/$glob" || true)
  if [[ $seen != yes ]]; then
    echo "FAIL $name: no temporary file $glob appeared within $wait s"; failures=$((failures + 1))
  elif ((rc < 128)); then
    echo "FAIL $name: exit status $rc, expected death by SIG$signal"; failures=$((failures + 1))
  elif [[ -n $left ]]; then
    echo "FAIL $name: left $left"; failures=$((failures + 1))
  elif [[ -e $work/$output ]]; then
    echo "FAIL $name: wrote a partial $output"; failures=$((failures + 1))
  else
    echo "ok   $name: SIG$signal, exit $rc, no temporary file left"
  fi
}

run_case trace_term TERM 20 'k.csv.tmp.*' k.csv \
  "$clothlab" trace "$scene" --duration 1000 --out "$work/k.csv"
run_case trace_int INT 20 'k.csv.tmp.*' k.csv \
  "$clothlab" trace "$scene" --duration 1000 --out "$work/k.csv"
run_case video_term TERM 60 'k.mp4.tmp.*' k.mp4 \
  "$clothlab" render "$scene" --frames 100000 --size 64x64 --quiet --out "$work/frames" \
  --video "$work/k.mp4"
dance=$(dirname "$scene")/dance.toml
run_case video_music_int INT 60 'm.mp4.tmp.*.wav' m.mp4 \
  "$clothlab" render "$dance" --frames 100000 --size 64x64 --quiet --out "$work/frames" \
  --video "$work/m.mp4"
exit $((failures > 0))
