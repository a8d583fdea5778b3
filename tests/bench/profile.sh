#!/bin/sh
# profile.sh BENCH [SCENE ...]: where mote's instructions go, by stage, for
# each scene (a prefix of a mote-bench scene name), textured with nearest
# texels on one thread: Callgrind counts the instructions run inside
# mote_begin, mote_draw and mote_end, and tests/bench/profile.awk sums them
# by stage. Counts are exact and the same on every run of one build, so
# they compare builds where times on a shared machine are too noisy.
# PROFILE_FRAMES (default 20) frames are counted, and mote-bench's two
# warm-up frames before them (the first one clears the whole frame), all of
# them however slow valgrind runs: mote-bench's time cap (2 s a run) once
# cut the grid to 10 frames on a slower day, other angles of the turn.
set -eu
if [ $# -lt 1 ] || [ ! -x "$1" ]; then
    echo "usage: profile.sh MOTE-BENCH [SCENE ...]" >&2
    exit 2
fi
bench=$1
shift
if ! command -v valgrind >/dev/null 2>&1; then
    echo "profile: valgrind is not installed (make profile installs it: apt-get install valgrind)" >&2
    exit 1
fi
[ $# -gt 0 ] || set -- grid monkey-1920 monkey-640
dir=$(dirname "$0")
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# count SCENE: Callgrind over mote-bench drawing SCENE; prints the name of
# the scene mote-bench drew (empty when it has none of that name)
count() {
    if ! valgrind --tool=callgrind --callgrind-out-file="$out/cg" --compress-strings=no --compress-pos=no \
            --toggle-collect=mote_begin --toggle-collect=mote_draw --toggle-collect=mote_end \
            "$bench" --scene "$1" --mode tex-nearest --threads 1 --frames "${PROFILE_FRAMES:-20}" --cap 100000 \
            >"$out/log" 2>&1; then
        cat "$out/log" >&2
        echo "profile: $1: valgrind failed" >&2
        exit 1
    fi
    sed -n 's/^  scene \([^ ]*\).*/\1/p' "$out/log" | head -n 1
}
for scene in "$@"; do
    name=$(count "$scene") || exit 1
    case $scene in monkey*)
        if [ -z "$name" ]; then  # mote-bench draws its torus where Suzanne's files are absent
            stand_in=torus${scene#monkey}
            echo "profile: $scene: Suzanne (../shared/assets/monkey.babylon) is absent; profiling $stand_in, the generated torus that stands in for it"
            name=$(count "$stand_in") || exit 1
        fi ;;
    esac
    if [ -z "$name" ]; then
        echo "profile: skipped $scene: mote-bench has no scene of that name here"
        echo
        continue
    fi
    awk -v scene="$name" -f "$dir/profile.awk" "$out/cg"
    echo
done
