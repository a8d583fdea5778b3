#!/bin/sh
# Sums a GNU ld link map's input sections by where they come from, after
# --gc-sections: one line each for
#   core      the mote core objects the firmware keeps (libmote(-fw).a)
#   libgcc    soft-float and 64-bit helpers the core and firmware pull in
#   example   startup, semihosting, mini libc, main, the baked scene, ...
# as "PART TEXT DATA BSS" (text: everything in flash, code and read-only
# data). usage: map-sizes.sh FIRMWARE.map
set -eu
awk '
/^Linker script and memory map/ { on = 1; next }
!on { next }
function hex(s,   v, i) {
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
