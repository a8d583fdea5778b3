#!/bin/sh
# Worst-case stack of a firmware ELF, from what the compiler says of each
# function and the call graph, without running it:
#   - frames: the larger of -fstack-usage's figure (for the functions
#     compiled from C: the .ci files that -fcallgraph-info=su writes beside
#     each object carry it) and the sum of every stack-pointer decrement in
#     the function's disassembly (push, vpush, stmdb sp!, str/strd with a
#     pre-decrement of sp, sub sp / addi sp,sp,-N), which is at least its
#     deepest frame: libgcc and assembly have no .ci, and -fstack-usage
#     leaves out what a function pushes of an argument it receives partly
#     in registers (a struct passed by value: 8 bytes of one span
#     function's frame on the Cortex-M4F);
#   - calls: the .ci files' edges, with the direct calls and tail calls the
#     disassembly shows (assembly makes calls the compiler does not see);
#   - calls through function pointers: a function that makes one (an edge
#     to __indirect_call in its .ci) may call any function whose address
#     the program takes (a relocation against a function symbol that is
#     not a call or a jump, in any section but debug info, unwind tables
#     and the vector table), so its deepest such call is counted;
#   - recursion: a cycle in the graph has no bound; it is reported and the
#     script fails, as it does for a function whose frame is dynamic.
# Functions are known by their symbol names (an alias, as libgcc has, by
# the name the disassembly gives its address; a call the compiler noted
# to a function the link left out, as a division done inline, is no
# call): two static functions of one name in different files count as
# one, with the larger frame and both sets of calls (never less than
# either).
# The worst case is the deepest path from the entry point, plus, where a
# fault may strike at that depth, the deepest path from the fault handler
# and the frame the hardware stacks (Cortex-M: 32 bytes, 104 with the
# FPU's registers; RISC-V: none).
#
# usage: stack-usage.sh TOOL_PREFIX ELF OBJECT_DIR...
#   prints "N bytes: entry > ... (fault path M + K stacked)"; exit 1 when
#   no bound exists
set -eu
prefix=$1; elf=$2; shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"${prefix}objdump" -d --no-show-raw-insn "$elf" >"$tmp/dis"
"${prefix}nm" "$elf" >"$tmp/syms"
entry=$("${prefix}readelf" -h "$elf" | awk '/Entry point address/ { print $4 }')
objs=$(find "$@" -name '*.o' | sort)
cis=$(find "$@" -name '*.ci' | sort)
# relocations, each line prefixed with its section
for o in $objs; do "${prefix}readelf" -rW "$o"; done |
    awk '/^Relocation section/ { sec = $3; gsub(/\047/, "", sec); next }
         NF >= 5 && $1 ~ /^[0-9a-f]+$/ { print sec, $3, $5 }' >"$tmp/relocs"
cat $cis /dev/null >"$tmp/ci"
case $prefix in
    arm*) if "${prefix}readelf" -A "$elf" | grep -q 'Tag_ABI_VFP_args: VFP registers'; then stacked=104; else stacked=32; fi ;;
    *) stacked=0 ;;
esac

awk -v entry="$entry" -v stacked="$stacked" '
function bare(t) { sub(/.*:/, "", t); return t }
function regs(list,   n, i, parts, r, a, bytes) {
    gsub(/[{}]/, "", list); n = split(list, parts, /, */); bytes = 0
    for (i = 1; i <= n; i++) {
        r = parts[i]
        if (r ~ /^[ds][0-9]+-[ds][0-9]+$/) {
            split(r, a, "-")
            bytes += (r ~ /^d/ ? 8 : 4) * (substr(a[2], 2) - substr(a[1], 2) + 1)
        } else bytes += (r ~ /^d/ ? 8 : 4)
    }
    return bytes
}
# ---- disassembly: functions, their sp decrements, direct calls ----
FILENAME == ARGV[1] {
    if ($0 ~ /^[0-9a-f]+ <[^>]+>:$/) {
        cur = $2; sub(/^</, "", cur); sub(/>:$/, "", cur)
        addr = $1; sub(/^0+/, "", addr); at[addr] = cur
        in_elf[cur] = 1; dis_frame[cur] += 0; next
    }
    if (cur == "" || $0 !~ /^ *[0-9a-f]+:\t/) next
    split($0, fld, "\t"); op = fld[2]; args = fld[3]
    if (op ~ /^(push|push\.w|vpush)$/) dis_frame[cur] += regs(args)
    else if (op ~ /^stmdb(\.w)?$/ && args ~ /^sp!, /) dis_frame[cur] += regs(substr(args, 5))
    else if (op ~ /^(sub|subw|sub\.w)$/ && args ~ /^sp, (sp, )?#[0-9]+/) {
        n = args; sub(/.*#/, "", n); dis_frame[cur] += n + 0
    } else if (op ~ /^str[a-z]*(\.w)?$/ && args ~ /\[sp, #-[0-9]+\]!/) {
        n = args; sub(/.*#-/, "", n); sub(/\].*/, "", n); dis_frame[cur] += n + 0
    } else if (op ~ /^(c\.)?addi?(16sp)?$/ && args ~ /^sp, ?sp, ?-[0-9]+$/) {
        n = args; sub(/.*-/, "", n); dis_frame[cur] += n + 0
    }
    # a call or a tail call: a branch to the start of a function (a
    # branch to its own start is a loop)
    if (op ~ /^(bl|blx|b|b\.n|b\.w|b[a-z][a-z](\.n|\.w)?|jal|j|c\.j|c\.jal|jalr|tail|call)$/ &&
        match($0, /<[^>+]+>$/)) {
        g = substr($0, RSTART + 1, RLENGTH - 2)
        if (g != cur) raw[++nraw] = cur SUBSEP g
    }
    next
}
# ---- the symbol table: every name of every function ----
FILENAME == ARGV[2] { a = $1; sub(/^0+/, "", a); if (NF == 3) sym_addr[$3] = a; next }
# ---- .ci files: frames of C functions, their calls, indirect calls ----
FILENAME == ARGV[3] {
    if ($0 ~ /^node:/ && match($0, /title: "[^"]*"/)) {
        t = bare(substr($0, RSTART + 8, RLENGTH - 9))
        if (match($0, /[0-9]+ bytes \([a-z,]+\)/)) {
            s = substr($0, RSTART, RLENGTH); n = s + 0
            if (!(t in ci_frame) || n > ci_frame[t]) ci_frame[t] = n
            if (s ~ /dynamic/ && s !~ /bounded/) dynamic[t] = 1
        }
    } else if ($0 ~ /^edge:/) {
        match($0, /sourcename: "[^"]*"/); src = bare(substr($0, RSTART + 13, RLENGTH - 14))
        match($0, /targetname: "[^"]*"/); dst = bare(substr($0, RSTART + 13, RLENGTH - 14))
        if (dst == "__indirect_call") indirect_raw[src] = 1
        else raw[++nraw] = src SUBSEP dst
    }
    next
}
# ---- relocations: functions whose address is taken ----
{
    if ($1 ~ /debug|exidx|vectors/ || $2 ~ /(CALL|JUMP|JAL|BRANCH|RELAX|ALIGN|V4BX|PREL31)/) next
    taken_raw[$3] = 1
}
# The function a name stands for in the ELF, "" when it is not linked.
function canon(n) {
    if (n in in_elf) return n
    if ((n in sym_addr) && (sym_addr[n] in at)) return at[sym_addr[n]]
    return ""
}
function frame(f) { return (f in frame_of) && frame_of[f] > dis_frame[f] ? frame_of[f] : dis_frame[f] + 0 }
function depth(f,   best, list, n, i, g, gd) {
    if (state[f] == 2) return memo[f]
    if (state[f] == 1) { if (cycle == "") cycle = f; return 0 }
    state[f] = 1
    best = 0; via[f] = ""
    n = split(calls[f], list, " ")
    for (i = 1; i <= n; i++) {
        gd = depth(list[i])
        if (gd > best) { best = gd; via[f] = list[i] }
    }
    if (f in indirect)
        for (g in taken) {
            gd = depth(g)
            if (gd > best) { best = gd; via[f] = g " (through a pointer)" }
        }
    state[f] = 2
    memo[f] = frame(f) + best
    return memo[f]
}
function path(f,   s, g) {
    s = f " " frame(f)
    while (via[f] != "") { g = via[f]; s = s " > " g; sub(/ \(.*/, "", g); f = g; s = s " " frame(f) }
    return s
}
END {
    for (t in ci_frame) if ((c = canon(t)) != "" && (!(c in frame_of) || ci_frame[t] > frame_of[c])) frame_of[c] = ci_frame[t]
    for (t in dynamic) if ((c = canon(t)) != "") dyn = dyn " " c
    for (t in indirect_raw) if ((c = canon(t)) != "") indirect[c] = 1
    for (t in taken_raw) if ((c = canon(t)) != "") taken[c] = 1
    for (i = 1; i <= nraw; i++) {
        split(raw[i], p, SUBSEP); f = canon(p[1]); g = canon(p[2])
        if (f == "" || g == "" || ((f, g) in edge)) continue
        edge[f, g] = 1; calls[f] = calls[f] " " g
    }
    # the entry address without the Thumb bit
    e = entry; sub(/^0x0*/, "", e)
    if (e ~ /[13579bdf]$/) e = substr(e, 1, length(e) - 1) sprintf("%x", index("0123456789abcdef", substr(e, length(e))) - 2)
    root = at[e]
    if (root == "") { print "stack-usage: no function at the entry point " entry > "/dev/stderr"; exit 1 }
    main_depth = depth(root)
    fault_depth = 0
    for (h in in_elf) if (h ~ /^(fault_handler|trap_entry)$/) { d = depth(h); if (d > fault_depth) { fault_depth = d; fh = h } }
    if (cycle != "") { print "stack-usage: recursion through " cycle ": no bound" > "/dev/stderr"; bad = 1 }
    if (dyn != "") { print "stack-usage: frames of unbounded size:" dyn > "/dev/stderr"; bad = 1 }
    if (bad) exit 1
    printf "%d bytes: %s (fault path %d + %d stacked)\n", main_depth + fault_depth + (fh != "" ? stacked : 0),
           path(root), fault_depth, fh != "" ? stacked : 0
}' "$tmp/dis" "$tmp/syms" "$tmp/ci" "$tmp/relocs"
