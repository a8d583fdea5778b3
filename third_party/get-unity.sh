#!/bin/sh
# Puts Unity into DEST (third_party/unity): DEST/src/unity.c, unity.h,
# unity_internals.h, and DEST/examples/unity_config.h (which the cjson copy
# of unity_internals.h includes as "../examples/unity_config.h").
# Unity is not packaged by Debian, but Debian's cjson source package carries
# an upstream copy under tests/unity/src. Order of preference:
#   1. UNITY_DIR, a folder that holds unity.c (your own copy);
#   2. the orig tarball of the cjson source package, via `apt-get source`;
#      when the system's apt has no deb-src lines (a stock Debian 12 has
#      none), through deb-src twins of its deb sources in a private apt
#      state in a temporary folder: no root needed, /etc/apt left untouched.
set -eu
DEST=${1:-third_party/unity}
[ -f "$DEST/src/unity.c" ] && exit 0
mkdir -p "$DEST/src" "$DEST/examples"

if [ -n "${UNITY_DIR:-}" ]; then
    if [ -f "$UNITY_DIR/unity.c" ]; then
        cp "$UNITY_DIR"/unity.c "$UNITY_DIR"/unity.h "$UNITY_DIR"/unity_internals.h "$DEST"/src/
        # the config header is optional upstream: an empty one will do
        [ -f "$UNITY_DIR/../examples/unity_config.h" ] && cp "$UNITY_DIR/../examples/unity_config.h" "$DEST/examples/" \
            || : > "$DEST/examples/unity_config.h"
        exit 0
    fi
    echo "error: UNITY_DIR=$UNITY_DIR holds no unity.c" >&2
    exit 1
fi

fail() {
    echo "error: could not obtain Unity: $1" >&2
    echo "  either set UNITY_DIR to a folder with unity.c, unity.h, unity_internals.h" >&2
    echo "  or run this again with network (deb.debian.org or your Debian mirror)" >&2
    exit 1
}

command -v apt-get >/dev/null 2>&1 || fail "no apt-get on this machine"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
if ! apt-get source --download-only -qq cjson >/dev/null 2>&1; then
    # deb-src twins of the configured deb sources (deb822 and one-line styles)
    mkdir -p apt/parts apt/lists/partial apt/cache/archives/partial
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        sed 's/^Types: deb$/Types: deb-src/' "$f" > "apt/parts/$(basename "$f")"
    done
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
        [ -f "$f" ] || continue
        grep '^deb ' "$f" | sed 's/^deb /deb-src /' >> apt/parts/deb-src.list || true
    done
    set -- -o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$work/apt/parts" \
        -o Dir::State::Lists="$work/apt/lists" -o Dir::Cache="$work/apt/cache"
    # a source without deb-src (a third-party repository) fails its part of
    # the update alone: what counts is whether cjson's source comes
    apt-get "$@" update -qq >/dev/null 2>&1 || true
    apt-get "$@" source --download-only -qq cjson >/dev/null 2>&1 || fail "apt-get source cjson failed (no network?)"
fi
tarball=$(ls cjson_*.orig.tar.* 2>/dev/null | head -n 1)
[ -n "$tarball" ] || fail "the cjson source package has no orig tarball"
tar xf "$tarball" --wildcards '*/tests/unity/src/unity*' '*/tests/unity/examples/unity_config.h' \
    || fail "no tests/unity/src in $tarball"
src=$(dirname "$(find . -path '*/tests/unity/src/unity.c' | head -n 1)")
cd - >/dev/null
cp "$work/$src"/unity.c "$work/$src"/unity.h "$work/$src"/unity_internals.h "$DEST"/src/
cp "$work/$src"/../examples/unity_config.h "$DEST"/examples/
echo "third_party/get-unity.sh: Unity from $tarball -> $DEST"
