#!/usr/bin/env bash
# Every writer on a full file system (issue 40): a 48 kB tmpfs, mounted in a private mount
# namespace (unshare: root or unprivileged user namespaces), fills up under each output in turn.
# Each must exit 1 with a message that names the file and says why, and leave nothing: no
# truncated file, no temporary file. Where no tmpfs can be mounted the test prints SKIP with
# the reason (ctest reports it skipped); cli.render.video_cut_short covers the video there with
# a file-size limit.
# Usage: full_disk_test.sh CLOTHLAB SCENES_DIR WORKDIR
set -uo pipefail
clothlab=$1 scenes=$2 work=$3

if [[ ${FULL_DISK_INSIDE:-} != 1 ]]; then
  rm -rf "$work" && mkdir -p "$work/disk" || exit 1
  if ! unshare --user --map-root-user --mount true 2>/dev/null &&
    ! unshare --mount true 2>/dev/null; then
    echo "SKIP: cannot make a mount namespace here (unshare refused: no user namespaces and" \
      "not root), so no small tmpfs can be mounted"
    exit 0
  fi
  flags=(--user --map-root-user --mount)
  unshare "${flags[@]}" true 2>/dev/null || flags=(--mount)
  FULL_DISK_INSIDE=1 exec unshare "${flags[@]}" bash "$0" "$@"
fi

disk=$work/disk
if ! mount -t tmpfs -o size=48k tmpfs "$disk" 2>"$work/mount.log"; then
  echo "SKIP: mounting a tmpfs was refused: $(head -1 "$work/mount.log")"
  exit 0
fi
failures=0

# run_case NAME MESSAGE_REGEX COMMAND...: expects exit 1, the message, and an empty disk after
# (directories the command made may stay, empty).
run_case() {
  local name=$1 regex=$2
  shift 2
  (cd "$disk" && "$@") >"$work/$name.log" 2>&1
  local rc=$? left
  left=$(find "$disk" -type f)
  if [[ $rc != 1 ]]; then
    echo "FAIL $name: exit status $rc, expected 1"; failures=$((failures + 1))
  elif ! grep -Eq "$regex" "$work/$name.log"; then
    echo "FAIL $name: no message matching /$regex/"; failures=$((failures + 1))
  elif [[ -n $left ]]; then
    echo "FAIL $name: left $left"; failures=$((failures + 1))
  else
    echo "ok $name: $(grep -E "$regex" "$work/$name.log" | head -1)"
  fi
  [[ $rc == 1 && -z $left ]] || sed 's/^/  | /' "$work/$name.log"
  rm -rf "${disk:?}"/*
}

run_case trace "cannot write trace file 't\.csv': No space left on device" \
  "$clothlab" trace "$scenes/default.toml" --duration 20 --out t.csv --quiet
run_case video "incomplete video for 'v\.mp4'.*nothing was kept" \
  "$clothlab" render "$scenes/default.toml" --frames 200 --size 320x240 --video v.mp4 --quiet
run_case frames "cannot write 'f/frame_00000\.png': No space left on device" \
  "$clothlab" render "$scenes/default.toml" --frames 100 --size 320x240 --out f --quiet
run_case music "'m\.wav'.*No space left on device" \
  "$clothlab" render "$scenes/dance.toml" --frames 1 --size 32x32 --out f --music-out m.wav --quiet
umount "$disk"
echo "$failures failure(s)"
[[ $failures == 0 ]]
