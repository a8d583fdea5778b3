# Microcontroller builds of the mote core and its firmware example.
#
#   make cross          core + firmware example for Cortex-M0+, Cortex-M4F and
#                       RV32IMAC, then a table of .text/.data/.bss per target
#   make test-embedded  render the example on emulated Cortex-M boards (qemu)
#                       and compare its frame hash with the host's
#
# The cross compilers see no C library: -nostdinc -nostdlib, the compiler's
# own freestanding headers, embedded/include/string.h, a folder holding only
# a link to the host's cglm headers, and libgcc for soft float and 64-bit
# division. The core is built with -DMOTE_SPECIALISE_SPANS=0 (one generic
# span loop, small flash) and the firmware with -DMOTE_MAX_DRAWS=8 (a small
# mote_device).
#
# Two archives per target: libmote.a with every feature, and libmote-fw.a,
# the firmware profile, with the features the example does not use left out
# (CROSS_PROFILE, see MOTE_ENABLE_* in mote.h). The firmware links the
# profile; the host reference it is compared with has every feature.

CROSS_DIR     := $(BUILD)/cross
CROSS_TARGETS := cortex-m0plus cortex-m4f rv32imac

CROSS_CC.cortex-m0plus   := arm-none-eabi-gcc
CROSS_ARCH.cortex-m0plus := -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft
CROSS_CC.cortex-m4f      := arm-none-eabi-gcc
CROSS_ARCH.cortex-m4f    := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
CROSS_CC.rv32imac        := riscv64-unknown-elf-gcc
CROSS_ARCH.rv32imac      := -march=rv32imac -mabi=ilp32

CROSS_START.cortex-m0plus := embedded/arm/startup.c
CROSS_START.cortex-m4f    := embedded/arm/startup.c
CROSS_START.rv32imac      := embedded/riscv/start.S
CROSS_LD.cortex-m0plus    := embedded/arm/cortex-m.ld
CROSS_LD.cortex-m4f       := embedded/arm/cortex-m.ld
CROSS_LD.rv32imac         := embedded/riscv/rv32.ld

# Same options that decide pixels as the host build (-ffp-contract=off: the
# M4F has fused multiply-add and must not use it), then size options.
CROSS_CFLAGS := -std=c99 -Os -g -ffp-contract=off -ffreestanding -nostdinc \
                -ffunction-sections -fdata-sections $(WARN) \
                -Iinclude -Isrc -Iembedded/include -I$(CROSS_DIR)/sysinclude \
                -DMOTE_MAX_DRAWS=8
CROSS_CORE_FLAGS := -DMOTE_SPECIALISE_SPANS=0
CROSS_PROFILE := -DMOTE_ENABLE_LINES=0 -DMOTE_ENABLE_BINNING=0 -DMOTE_ENABLE_BILINEAR=0 \
                 -DMOTE_ENABLE_SUBSPAN=0 -DMOTE_ENABLE_VERTEX_COLORS=0 -DMOTE_ENABLE_LIGHT_FALLOFF=0 \
                 -DMOTE_ENABLE_ORTHOGRAPHIC=0 -DMOTE_ENABLE_EMISSIVE=0
CROSS_LDFLAGS := -nostdlib -Wl,--gc-sections

# The firmware example's scene, baked at build time.
FW_SCENE  ?= embedded/scene/cube.babylon
FW_SIZE   ?= 320x240
FW_HEADER := $(CROSS_DIR)/scene/scene.h
FW_SRC    := embedded/firmware/main.c embedded/firmware/platform_semihost.c \
             embedded/firmware/mini_libc.c
FW_DEPS   := $(wildcard embedded/firmware/*.h embedded/include/*.h include/mote/*.h src/core/*.h) embedded/cross.mk

CROSS_CGLM := $(CROSS_DIR)/sysinclude/cglm

.PHONY: cross cross-build test-embedded embedded-firmware

cross: cross-build
	@sh embedded/cross-sizes.sh $(CROSS_DIR) $(CROSS_TARGETS)

$(CROSS_CGLM): | $(DEPS_OK)
	@mkdir -p $(dir $@)
	ln -sfn $$(pkg-config --variable=includedir cglm)/cglm $@

# One target's rules: core objects and archive, firmware objects, the ELF
# (with a link map, for the per-archive sizes) and its listing of sizes.
define CROSS_TARGET_RULES
CROSS_CORE_OBJ.$(1) := $$(patsubst src/core/%.c,$(CROSS_DIR)/$(1)/core/%.o,$$(CORE_SRC))
CROSS_PROF_OBJ.$(1) := $$(patsubst src/core/%.c,$(CROSS_DIR)/$(1)/core-fw/%.o,$$(CORE_SRC))
CROSS_FW_OBJ.$(1)   := $$(patsubst embedded/%,$(CROSS_DIR)/$(1)/fw/%.o,$$(FW_SRC) $$(CROSS_START.$(1)))

$(CROSS_DIR)/$(1)/core/%.o: src/core/%.c $$(wildcard include/mote/*.h src/core/*.h embedded/include/*.h) embedded/cross.mk | $(CROSS_CGLM)
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_CORE_FLAGS) \
	    -isystem $$$$($$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) -print-file-name=include) -c $$< -o $$@

$(CROSS_DIR)/$(1)/core-fw/%.o: src/core/%.c $$(wildcard include/mote/*.h src/core/*.h embedded/include/*.h) embedded/cross.mk | $(CROSS_CGLM)
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_CORE_FLAGS) $$(CROSS_PROFILE) \
	    -isystem $$$$($$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) -print-file-name=include) -c $$< -o $$@

$(CROSS_DIR)/$(1)/fw/%.o: embedded/% $(FW_HEADER) $$(FW_DEPS) | $(CROSS_CGLM)
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_PROFILE) -Iembedded/firmware -I$(dir $(FW_HEADER)) \
	    -isystem $$$$($$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) -print-file-name=include) -c $$< -o $$@

$(CROSS_DIR)/$(1)/libmote.a: $$(CROSS_CORE_OBJ.$(1))
	@rm -f $$@
	$$(CROSS_CC.$(1):gcc=ar) rcs $$@ $$^

$(CROSS_DIR)/$(1)/libmote-fw.a: $$(CROSS_PROF_OBJ.$(1))
	@rm -f $$@
	$$(CROSS_CC.$(1):gcc=ar) rcs $$@ $$^

$(CROSS_DIR)/$(1)/mote-firmware.elf: $$(CROSS_FW_OBJ.$(1)) $(CROSS_DIR)/$(1)/libmote-fw.a $$(CROSS_LD.$(1))
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_LDFLAGS) -T $$(CROSS_LD.$(1)) \
	    -Wl,-Map=$(CROSS_DIR)/$(1)/mote-firmware.map $$(CROSS_FW_OBJ.$(1)) \
	    $(CROSS_DIR)/$(1)/libmote-fw.a -lgcc -o $$@
endef
$(foreach t,$(CROSS_TARGETS),$(eval $(call CROSS_TARGET_RULES,$(t))))

cross-build: $(foreach t,$(CROSS_TARGETS),$(CROSS_DIR)/$(t)/libmote.a $(CROSS_DIR)/$(t)/libmote-fw.a \
                                           $(CROSS_DIR)/$(t)/mote-firmware.elf)

# The same firmware source on the host, with the same baked header and
# MOTE_MAX_DRAWS, for the reference hash. The core is compiled in (not
# libmote.a, whose mote_device has the default MOTE_MAX_DRAWS), keeps its
# specialised spans and every feature, so the comparison also checks them
# against the generic loop and the firmware profile the targets use.
$(CROSS_DIR)/host/mote-firmware: embedded/firmware/main.c embedded/firmware/platform_host.c \
        $(CORE_SRC) $(FW_HEADER) $(FW_DEPS) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -O2 -ffp-contract=off $(WARN) -Iinclude -Isrc -Iembedded/firmware \
	    -I$(dir $(FW_HEADER)) $$(pkg-config --cflags cglm) -DMOTE_MAX_DRAWS=8 \
	    embedded/firmware/main.c embedded/firmware/platform_host.c $(CORE_SRC) -o $@

embedded-firmware: $(CROSS_DIR)/cortex-m0plus/mote-firmware.elf \
        $(CROSS_DIR)/cortex-m4f/mote-firmware.elf $(CROSS_DIR)/host/mote-firmware

test-embedded:
	@MOTE_BUILD=$(BUILD) sh embedded/test-embedded.sh

TEST_EXTRA += embedded/test-embedded.sh
export MOTE_BUILD := $(BUILD)

$(FW_HEADER): $(FW_SCENE) $(BIN)/mote-bake
	@mkdir -p $(dir $@)
	$(BIN)/mote-bake $(FW_SCENE) -o $@ --name scene --format rgb565 --size $(FW_SIZE)

# GCC would turn the mini libc's loops into calls to memcpy and memset
# (themselves, on the targets; the host's, in its test).
MINI_LIBC_FLAGS := -fno-tree-loop-distribute-patterns
$(CROSS_DIR)/%/fw/firmware/mini_libc.c.o: CROSS_CFLAGS += $(MINI_LIBC_FLAGS)
