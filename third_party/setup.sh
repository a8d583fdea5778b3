#!/bin/sh
# Installs what mote builds against, from Debian packages, when missing:
#   a C compiler (gcc, when $CC, cc by default, is not found) and the C
#   library's headers (libc6-dev, which gcc only recommends), pkg-config,
#   cglm (libcglm-dev), cJSON (libcjson-dev), stb (libstb-dev), and
#   meshoptimizer (libmeshoptimizer-dev, for mote-bake; it has no
#   pkg-config file: its header is looked for).
# Extra packages can be asked for with MOTE_EXTRA_PACKAGES="pkg ...".
# Nothing is downloaded from anywhere else and nothing is committed.
set -eu

# A parallel make (-j) can start two of these at once: apt-get takes one.
if [ -z "${MOTE_SETUP_LOCKED:-}" ] && command -v flock >/dev/null 2>&1; then
    export MOTE_SETUP_LOCKED=1
    exec flock "${TMPDIR:-/tmp}/mote-setup.lock" sh "$0" "$@"
fi

need=""
cc=${CC:-cc}; cc=${cc%% *}
if ! command -v "$cc" >/dev/null 2>&1; then
    case $cc in *clang*) need="$need clang" ;; *) need="$need gcc" ;; esac
fi
[ -f /usr/include/stdio.h ] || need="$need libc6-dev"
[ -f /usr/include/meshoptimizer.h ] || need="$need libmeshoptimizer-dev"
command -v pkg-config >/dev/null 2>&1 || need="$need pkg-config"
for pair in cglm:libcglm-dev libcjson:libcjson-dev stb:libstb-dev; do
    mod=${pair%%:*}; pkg=${pair#*:}
    if ! command -v pkg-config >/dev/null 2>&1 || ! pkg-config --exists "$mod"; then
        need="$need $pkg"
    fi
done
for pkg in ${MOTE_EXTRA_PACKAGES:-}; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need="$need $pkg"
done

[ -z "$need" ] && exit 0

# (a machine that has never run apt-get update, as a container image, knows
# no package yet: the printed command updates first)
if [ "$(id -u)" -ne 0 ] || ! command -v apt-get >/dev/null 2>&1; then
    echo "error: missing:$need" >&2
    echo "  install them as root:  apt-get update && apt-get install$need" >&2
    exit 1
fi
echo "third_party/setup.sh: installing:$need"
export DEBIAN_FRONTEND=noninteractive
if ! apt-get install -y -qq $need >/dev/null 2>&1; then
    apt-get update -qq
    apt-get install -y -qq $need || {
        echo "error: apt-get could not install:$need (no network?)" >&2
        echo "  install them as root:  apt-get update && apt-get install$need" >&2
        exit 1
    }
fi
