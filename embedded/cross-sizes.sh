#!/bin/sh
# Prints .text/.data/.bss of each cross target: the core archive as
# compiled with every feature (libmote.a) and in the firmware profile
# (libmote-fw.a, MOTE_ENABLE_* features the example does not use left
# out), and the linked firmware example split by where the bytes come from
# (after --gc-sections), read from the link map:
#   core      the mote core objects the example keeps (libmote-fw.a)
#   libgcc    soft-float and 64-bit helpers the core and example pull in
#   example   startup, semihosting, mini libc, main and the baked scene
# .text here is everything in flash (code and read-only data).
# usage: cross-sizes.sh CROSS_DIR TARGET...
set -eu
dir=$1; shift

# Sums input sections by archive from a GNU ld map: text, data, bss for
# libmote.a, libgcc.a and everything else.
map_sizes() {
    awk '
    /^Linker script and memory map/ { on = 1; next }
    !on { next }
    function hex(s,   v, i, c) {
        v = 0; s = tolower(substr(s, 3))
        for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
        return v
    }
    function add(name, size, file,   part, kind) {
        if (file ~ /libmote(-fw)?\.a\(/) part = "core"
        else if (file ~ /libgcc\.a\(/) part = "libgcc"
        else part = "example"
        if (name ~ /^\.(text|rodata|srodata|ARM\.exidx)/) kind = "text"
        else if (name ~ /^\.(data|sdata)/) kind = "data"
        else if (name ~ /^\.(bss|sbss)/ || name == "COMMON") kind = "bss"
        else return
        sum[part, kind] += hex(size)
    }
    /^ [.A-Za-z_]/ {
        if (NF >= 4 && $2 ~ /^0x/ && $3 ~ /^0x/) { add($1, $3, $4); pending = ""; next }
        if (NF == 1) { pending = $1; next }
    }
    /^ +0x/ && pending != "" {
        if (NF >= 3 && $2 ~ /^0x/) add(pending, $2, $3)
        pending = ""; next
    }
    { pending = "" }
    END {
        split("core libgcc example", parts, " ")
        for (i = 1; i <= 3; i++)
            printf "%s %d %d %d\n", parts[i], sum[parts[i], "text"], sum[parts[i], "data"], sum[parts[i], "bss"]
    }' "$1"
}

printf '%-14s %-28s %7s %6s %6s\n' target part .text .data .bss
for t in "$@"; do
    case $t in
        rv32*) size=riscv64-unknown-elf-size ;;
        *) size=arm-none-eabi-size ;;
    esac
    $size -t "$dir/$t/libmote.a" | awk -v t="$t" 'END { printf "%-14s %-28s %7d %6d %6d\n", t, "core, all of libmote.a", $1, $2, $3 }'
    $size -t "$dir/$t/libmote-fw.a" | awk -v t="$t" 'END { printf "%-14s %-28s %7d %6d %6d\n", t, "core, firmware profile (.a)", $1, $2, $3 }'
    map_sizes "$dir/$t/mote-firmware.map" | while read -r part text data bss; do
        printf '%-14s %-28s %7d %6d %6d\n' "$t" "firmware: $part" "$text" "$data" "$bss"
    done
    $size "$dir/$t/mote-firmware.elf" | awk -v t="$t" 'NR == 2 { printf "%-14s %-28s %7d %6d %6d\n", t, "firmware: total (ELF)", $1, $2, $3 }'
done
