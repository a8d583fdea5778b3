# boards.sh - the emulated boards each cross target runs on, for
# test-embedded.sh and bench-embedded.sh (sourced, POSIX sh):
#   cortex-m0plus  mps2-an385: qemu has no Cortex-M0+ board, so the M0+
#                  build (ARMv6-M code, soft float) runs on the AN385's
#                  Cortex-M3, set to trap unaligned accesses as an M0+ does
#                  (embedded/arm/startup.c)
#   cortex-m4f     mps2-an386 (Cortex-M4 with FPU)
#   rv32imac       virt with a SiFive E31 core (RV32IMAC), no firmware of
#                  qemu's own (-bios none)
# Output goes through semihosting. Needs MOTE_BUILD (the build folder).

# The cross tools' prefix, qemu and its machine options, the packages that
# bring them.
board_tools() {
    case $1 in
        rv32imac) echo riscv64-unknown-elf- ;;
        *) echo arm-none-eabi- ;;
    esac
}
board_qemu() {
    case $1 in
        cortex-m0plus) echo "qemu-system-arm -M mps2-an385" ;;
        cortex-m4f) echo "qemu-system-arm -M mps2-an386" ;;
        rv32imac) echo "qemu-system-riscv32 -M virt -cpu sifive-e31 -bios none" ;;
    esac
}
# The host build a target's frames must equal: the integer vertex stage's
# where the core has no FPU (MOTE_FIXED_VERTEX's default there), else the
# float one's (embedded/cross.mk builds both); MOTE_CROSS_FIXED=0 or 1
# builds every target with that stage (embedded/cross.mk).
board_host() {
    case ${MOTE_CROSS_FIXED:-} in
        0) echo host; return ;;
        1) echo host-fixed; return ;;
    esac
    case $1 in
        cortex-m4f) echo host ;;
        *) echo host-fixed ;;
    esac
}
board_packages() {
    case $1 in
        rv32imac) echo "gcc-riscv64-unknown-elf:riscv64-unknown-elf-gcc qemu-system-misc:qemu-system-riscv32" ;;
        *) echo "gcc-arm-none-eabi:arm-none-eabi-gcc qemu-system-arm:qemu-system-arm" ;;
    esac
}

# Installs the compilers and emulators the targets need where they are
# missing, when root with apt-get can (CI's clean machine: otherwise the
# checks would be skipped there unseen).
boards_install() {
    board_need=""
    for board_target in "$@"; do
        for board_pair in $(board_packages "$board_target"); do
            command -v "${board_pair#*:}" >/dev/null 2>&1 || board_need="$board_need ${board_pair%%:*}"
        done
    done
    if [ -n "$board_need" ] && [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
        MOTE_EXTRA_PACKAGES="$board_need" sh third_party/setup.sh >/dev/null 2>&1 || true
    fi
}

# Empty when the target's tools are here, else what is missing.
board_missing() {
    for board_pair in $(board_packages "$1"); do
        command -v "${board_pair#*:}" >/dev/null 2>&1 ||
            { echo "${board_pair#*:} is not installed (apt-get install ${board_pair%%:*})"; return; }
    done
}

# Runs ELF on the target's board; prints what the firmware printed, and
# with "count", the instruction counter's line (embedded/qemu/insn_count.c,
# between fw_count_start and fw_count_stop; BOARD_PROFILE=FILE: and each
# block's count, for embedded/profile.sh). Exit status: the firmware's.
# (the board_ variables are this file's: sh has no locals)
board_run() {
    board_target=$1; board_elf=$2; board_count=${3:-}
    set -- $(board_qemu "$board_target") -nographic -monitor none -serial none \
        -semihosting-config enable=on,target=native -kernel "$board_elf"
    if [ "$board_count" = count ]; then
        board_log=$(mktemp)
        board_marks=$("$(board_tools "$board_target")nm" "$board_elf" |
            awk '$3 == "fw_count_start" { s = $1 } $3 == "fw_count_stop" { e = $1 } END { print "0x" s ",stop=0x" e }')
        timeout 300 "$@" -plugin "$MOTE_BUILD/qemu/libinsn_count.so,start=$board_marks${BOARD_PROFILE:+,profile=$BOARD_PROFILE}" \
            -d plugin -D "$board_log" 2>&1
        board_rc=$?
        cat "$board_log"
        rm -f "$board_log"
        return $board_rc
    fi
    timeout 300 "$@" 2>&1
}
