# Microcontroller builds of the mote core and its firmware example.
#
#   make cross          core + firmware example for Cortex-M0+, Cortex-M4F and
#                       RV32IMAC, then a table of .text/.data/.bss and the
#                       worst-case stack per target
#   make test-embedded  render on emulated boards (qemu) and compare with the
#                       host, the LCD path, the unaligned trap, the stack
#                       bound, the instruction counter (embedded/test-embedded.sh)
#   make bench-embedded instructions per frame (embedded/bench.mk)
#   make switch-sizes   the flash each MOTE_ENABLE_* switch saves on
#                       Cortex-M0+, as a markdown table (docs/embedded.md)
#
# The cross compilers see no C library: -nostdinc -nostdlib, the compiler's
# own freestanding headers, embedded/include/string.h and libgcc for soft
# float and 64-bit division. The core is built with its defaults for -Os
# (one generic span loop, small flash) and the firmware with
# -DMOTE_MAX_DRAWS=8 (a small mote_device).
#
# Two archives per target: libmote.a with every feature, and libmote-fw.a,
# the firmware profile, with the features the example does not use left out
# (CROSS_PROFILE, see MOTE_ENABLE_* in mote.h). The firmware links the
# profile, and so does the host reference it is compared with.
#
# The firmware comes in variants, one ELF each, so that its static buffers
# are sized for what it renders: $(CROSS_DIR)/TARGET/SCENE-ROWS[-lcd]/
# (embedded/firmware/main.c: ROWS a band, 240 the whole frame; -lcd through
# the fake LCD), beside the same source built for the host in
# $(CROSS_DIR)/host/SCENE-ROWS[-lcd]/ (and host-fixed/, the integer vertex
# stage's).

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
CROSS_START.rv32imac      := embedded/riscv/start.S embedded/riscv/trap.c
CROSS_LD.cortex-m0plus    := embedded/arm/cortex-m.ld
CROSS_LD.cortex-m4f       := embedded/arm/cortex-m.ld
CROSS_LD.rv32imac         := embedded/riscv/rv32.ld

# Same options that decide pixels as the host build (-ffp-contract=off: the
# M4F has fused multiply-add and must not use it), then size options.
# -fstack-usage and -fcallgraph-info write each object's frame sizes and
# calls beside it (.su, .ci) for embedded/stack-usage.sh; the code is the
# same without them.
CROSS_CFLAGS := -std=c99 -Os -g -ffp-contract=off -ffreestanding -nostdinc \
                -ffunction-sections -fdata-sections $(WARN) \
                -fstack-usage -fcallgraph-info=su \
                -Iinclude -Isrc -Iembedded/include \
                -DMOTE_MAX_DRAWS=8
CROSS_CORE_FLAGS := -DMOTE_SPECIALISE_SPANS=0
# MOTE_CROSS_FIXED=0 or 1 (in the environment, with a BUILD of its own)
# builds every target with the float or the integer vertex stage instead
# of each one's default, to compare them: `MOTE_CROSS_FIXED=0 make
# bench-embedded BUILD=build-float`.
ifneq ($(MOTE_CROSS_FIXED),)
CROSS_CFLAGS += -DMOTE_FIXED_VERTEX=$(MOTE_CROSS_FIXED)
endif
# MOTE_CROSS_FLAGS (in the environment, with a BUILD of its own): more
# options for the targets and their host references alike, to measure
# one: `MOTE_CROSS_FLAGS=-DMOTE_VERTEX_CACHE=16 make bench-embedded
# BUILD=build-cache16`.
CROSS_CFLAGS += $(MOTE_CROSS_FLAGS)
CROSS_PROFILE := -DMOTE_ENABLE_LINES=0 -DMOTE_ENABLE_BINNING=0 -DMOTE_ENABLE_BILINEAR=0 \
                 -DMOTE_ENABLE_SUBSPAN=0 -DMOTE_ENABLE_VERTEX_COLORS=0 -DMOTE_ENABLE_LIGHT_FALLOFF=0 \
                 -DMOTE_ENABLE_ORTHOGRAPHIC=0 -DMOTE_ENABLE_EMISSIVE=0 -DMOTE_ENABLE_ALPHA_TEST=0 \
                 -DMOTE_ENABLE_BLEND=0 -DMOTE_ENABLE_SPECULAR=0 -DMOTE_ENABLE_FOG=0 -DMOTE_ENABLE_MIPMAPS=0 \
                 -DMOTE_ENABLE_EMISSIVE_MAP=0 -DMOTE_ENABLE_OPACITY_MAP=0 -DMOTE_ENABLE_SPECULAR_MAP=0
CROSS_LDFLAGS := -nostdlib -Wl,--gc-sections

# Scenes the firmware can be built with, baked at FW_SIZE: NAME and its
# file; FW_BAKE.NAME adds mote-bake options. Suzanne is the tutorial's
# (../shared/assets, not in the repository), its 512x512 texture baked at
# 128x128; suzannec is the same baked with --compact (mote_compact).
FW_SIZE           := 320x240
FW_FULL_ROWS      := 240
FW_SCENE.cube     := embedded/scene/cube.babylon
FW_SCENE.suzanne  := ../shared/assets/monkey.babylon
FW_BAKE.suzanne   := --texture-size 128x128
FW_SCENE.suzannec := $(FW_SCENE.suzanne)
FW_BAKE.suzannec  := --texture-size 128x128 --compact
FW_SCENE.box      := assets/cube.babylon
FW_SCENE.sphere   := assets/sphere.babylon
FW_SCENE.torus    := assets/torus.babylon
FW_SCENE.demo     := assets/demo.babylon
FW_SCENES         := cube suzanne suzannec box sphere torus demo

# The example `make cross` sizes, the variants test-embedded runs, and
# those bench-embedded counts (Suzanne when ../shared/assets has it).
FW_EXAMPLE          := cube-30
FW_TEST_VARIANTS    := cube-30 cube-16-lcd
FW_BENCH_SCENES     := $(if $(wildcard $(FW_SCENE.suzanne)),suzanne suzannec) cube box sphere torus demo
FW_BENCH_ROWS       := 16 30 $(FW_FULL_ROWS)
FW_BENCH_VARIANTS   := $(foreach s,$(FW_BENCH_SCENES),$(foreach r,$(FW_BENCH_ROWS),$(s)-$(r))) \
                       $(word 1,$(FW_BENCH_SCENES))-30-replay

FW_SRC    := embedded/firmware/platform_semihost.c embedded/firmware/util.c \
             embedded/firmware/mini_libc.c embedded/firmware/lcd.c embedded/firmware/lcd_fake.c
FW_HOST_SRC := embedded/firmware/platform_host.c embedded/firmware/util.c \
             embedded/firmware/lcd.c embedded/firmware/lcd_fake.c
FW_DEPS   := $(wildcard embedded/firmware/*.h embedded/include/*.h include/mote/*.h src/core/*.h) embedded/cross.mk

.PHONY: cross cross-build switch-sizes test-embedded $(foreach t,$(CROSS_TARGETS) host,fw-test-$(t))

cross: cross-build
	@sh embedded/cross-sizes.sh $(CROSS_DIR) $(FW_EXAMPLE) $(CROSS_TARGETS)

# The core as libmote.a for Cortex-M0+ is compiled, once per switch.
switch-sizes:
	@sh embedded/switch-sizes.sh $(CROSS_DIR)/switch-sizes $(CROSS_CC.cortex-m0plus) \
	    $(CROSS_ARCH.cortex-m0plus) $(CROSS_CFLAGS) \
	    -isystem "$$($(CROSS_CC.cortex-m0plus) $(CROSS_ARCH.cortex-m0plus) -print-file-name=include)"

# A scene baked once for every target and the host.
define FW_SCENE_RULES
$(CROSS_DIR)/scene/$(1)/scene.h: $(FW_SCENE.$(1)) $(BIN)/mote-bake
	@mkdir -p $$(dir $$@)
	$(BIN)/mote-bake $(FW_SCENE.$(1)) -o $$@ --name scene --format rgb565 --size $(FW_SIZE) $(FW_BAKE.$(1))
endef
$(foreach s,$(FW_SCENES),$(eval $(call FW_SCENE_RULES,$(s))))

# The parts of a variant's name: scene, rows, then tags: lcd drives the LCD.
fw_scene = $(word 1,$(subst -, ,$(1)))
fw_rows  = $(word 2,$(subst -, ,$(1)))
fw_lcd   = $(if $(filter lcd,$(subst -, ,$(1))),1,0)
# 0 for a "replay" variant: bands without band bins, each replaying the frame.
fw_bins  = $(if $(filter replay,$(subst -, ,$(1))),0,1)
# RAM budget of a variant: 64 KB for bands, more for a whole frame.
fw_ram   = $(if $(filter $(FW_FULL_ROWS),$(call fw_rows,$(1))),384K,64K)

# One target's rules: core objects and archives, the firmware's shared
# objects, the self-test (embedded/tests/selftest.c).
define CROSS_TARGET_RULES
CROSS_CORE_OBJ.$(1) := $$(patsubst src/core/%.c,$(CROSS_DIR)/$(1)/core/%.o,$$(CORE_SRC))
CROSS_PROF_OBJ.$(1) := $$(patsubst src/core/%.c,$(CROSS_DIR)/$(1)/core-fw/%.o,$$(CORE_SRC))
CROSS_FW_OBJ.$(1)   := $$(patsubst embedded/%,$(CROSS_DIR)/$(1)/fw/%.o,$$(FW_SRC) $$(CROSS_START.$(1)))
CROSS_INCLUDE.$(1)   = -isystem $$$$($$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) -print-file-name=include)

$(CROSS_DIR)/$(1)/core/%.o: src/core/%.c $$(wildcard include/mote/*.h src/core/*.h embedded/include/*.h) embedded/cross.mk
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_INCLUDE.$(1)) -c $$< -o $$@

$(CROSS_DIR)/$(1)/core-fw/%.o: src/core/%.c $$(wildcard include/mote/*.h src/core/*.h embedded/include/*.h) embedded/cross.mk
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_PROFILE) \
	    $$(CROSS_INCLUDE.$(1)) -c $$< -o $$@

$(CROSS_DIR)/$(1)/fw/%.o: embedded/% $$(FW_DEPS)
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_PROFILE) -Iembedded/firmware \
	    $$(CROSS_INCLUDE.$(1)) -c $$< -o $$@

$(CROSS_DIR)/$(1)/libmote.a: $$(CROSS_CORE_OBJ.$(1))
	@rm -f $$@
	$$(CROSS_CC.$(1):gcc=ar) rcs $$@ $$^

$(CROSS_DIR)/$(1)/libmote-fw.a: $$(CROSS_PROF_OBJ.$(1))
	@rm -f $$@
	$$(CROSS_CC.$(1):gcc=ar) rcs $$@ $$^

$(CROSS_DIR)/$(1)/selftest/selftest.elf: $(CROSS_DIR)/$(1)/fw/tests/selftest.c.o $$(CROSS_FW_OBJ.$(1)) $$(CROSS_LD.$(1))
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_LDFLAGS) -T $$(CROSS_LD.$(1)) \
	    $$(filter %.o,$$^) -lgcc -o $$@

fw-test-$(1): $$(foreach v,$$(FW_TEST_VARIANTS),$(CROSS_DIR)/$(1)/$$(v)/mote-firmware.elf) \
        $(CROSS_DIR)/$(1)/selftest/selftest.elf $(CROSS_DIR)/$(1)/libmote-fw.a
endef
$(foreach t,$(CROSS_TARGETS),$(eval $(call CROSS_TARGET_RULES,$(t))))

# One variant on one target: main.c built for it, and the ELF with its link
# map (for the per-archive sizes).
define FW_VARIANT_RULES
$(CROSS_DIR)/$(1)/$(2)/main.o: embedded/firmware/main.c $(CROSS_DIR)/scene/$(call fw_scene,$(2))/scene.h \
        $$(FW_DEPS)
	@mkdir -p $$(dir $$@)
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_CFLAGS) $$(CROSS_PROFILE) -Iembedded/firmware \
	    -I$(CROSS_DIR)/scene/$(call fw_scene,$(2)) -DFW_BAND=$(call fw_rows,$(2)) -DFW_LCD=$(call fw_lcd,$(2)) -DFW_BINS=$(call fw_bins,$(2)) \
	    $$(CROSS_INCLUDE.$(1)) -c $$< -o $$@

$(CROSS_DIR)/$(1)/$(2)/mote-firmware.elf: $(CROSS_DIR)/$(1)/$(2)/main.o $$(CROSS_FW_OBJ.$(1)) \
        $(CROSS_DIR)/$(1)/libmote-fw.a $$(CROSS_LD.$(1))
	$$(CROSS_CC.$(1)) $$(CROSS_ARCH.$(1)) $$(CROSS_LDFLAGS) -T $$(CROSS_LD.$(1)) \
	    -Wl,--defsym=fw_ram_size=$(call fw_ram,$(2)) -Wl,-Map=$(CROSS_DIR)/$(1)/$(2)/mote-firmware.map \
	    $(CROSS_DIR)/$(1)/$(2)/main.o $$(CROSS_FW_OBJ.$(1)) $(CROSS_DIR)/$(1)/libmote-fw.a -lgcc -o $$@
endef

# The same firmware source on the host, with the same baked header,
# MOTE_MAX_DRAWS and firmware profile: the reference hash of the same
# configuration (a scene with emissive colours, which the profile leaves
# out, draws otherwise with every feature). Its core (not libmote.a, whose
# mote_device has the default MOTE_MAX_DRAWS) keeps its specialised spans,
# so the comparison also checks them against the targets' generic loop.
# Two references: host/ with the float vertex stage (the Cortex-M4F's),
# host-fixed/ with the integer one (MOTE_FIXED_VERTEX, the default where
# there is no FPU: Cortex-M0+ and RV32IMAC; embedded/boards.sh's
# board_host says which a target is compared with).
CROSS_HOSTS := host host-fixed
CROSS_HOST_CFLAGS := -std=c99 -O2 -ffp-contract=off $(WARN) -Iinclude -Isrc -DMOTE_MAX_DRAWS=8 $(CROSS_PROFILE) \
                     $(MOTE_CROSS_FLAGS)
CROSS_HOST_FLAG.host       := -DMOTE_FIXED_VERTEX=0
CROSS_HOST_FLAG.host-fixed := -DMOTE_FIXED_VERTEX=1

define FW_HOST_CORE_RULES
CROSS_HOST_CORE.$(1) := $$(patsubst src/core/%.c,$(CROSS_DIR)/$(1)/core/%.o,$$(CORE_SRC))
$(CROSS_DIR)/$(1)/core/%.o: src/core/%.c $$(wildcard include/mote/*.h src/core/*.h) embedded/cross.mk | $(DEPS_OK)
	@mkdir -p $$(dir $$@)
	$(CC) $(CROSS_HOST_CFLAGS) $(CROSS_HOST_FLAG.$(1)) -c $$< -o $$@
endef
$(foreach h,$(CROSS_HOSTS),$(eval $(call FW_HOST_CORE_RULES,$(h))))

define FW_HOST_VARIANT_RULES
$(CROSS_DIR)/$(2)/$(1)/mote-firmware: embedded/firmware/main.c $(FW_HOST_SRC) $$(CROSS_HOST_CORE.$(2)) \
        $(CROSS_DIR)/scene/$(call fw_scene,$(1))/scene.h $(FW_DEPS)
	@mkdir -p $$(dir $$@)
	$(CC) $(CROSS_HOST_CFLAGS) $(CROSS_HOST_FLAG.$(2)) -Iembedded/firmware -I$(CROSS_DIR)/scene/$(call fw_scene,$(1)) \
	    -DFW_BAND=$(call fw_rows,$(1)) -DFW_LCD=$(call fw_lcd,$(1)) -DFW_BINS=$(call fw_bins,$(1)) \
	    embedded/firmware/main.c $(FW_HOST_SRC) $$(CROSS_HOST_CORE.$(2)) -o $$@
endef

FW_VARIANTS := $(sort $(FW_EXAMPLE) $(FW_TEST_VARIANTS) $(FW_BENCH_VARIANTS))
$(foreach v,$(FW_VARIANTS),$(foreach t,$(CROSS_TARGETS),$(eval $(call FW_VARIANT_RULES,$(t),$(v)))) \
    $(foreach h,$(CROSS_HOSTS),$(eval $(call FW_HOST_VARIANT_RULES,$(v),$(h)))))

fw-test-host: $(foreach h,$(CROSS_HOSTS),$(foreach v,$(FW_TEST_VARIANTS),$(CROSS_DIR)/$(h)/$(v)/mote-firmware))

cross-build: $(foreach t,$(CROSS_TARGETS),$(CROSS_DIR)/$(t)/libmote.a $(CROSS_DIR)/$(t)/libmote-fw.a \
                                           $(CROSS_DIR)/$(t)/$(FW_EXAMPLE)/mote-firmware.elf)

test-embedded:
	@MOTE_BUILD=$(BUILD) sh embedded/test-embedded.sh

# Not in the sanitizer build (SAN=1): neither the targets' builds nor the
# host references they are compared with are instrumented.
ifneq ($(SAN),1)
TEST_EXTRA += embedded/test-embedded.sh
endif
export MOTE_BUILD := $(BUILD)

# GCC would turn the mini libc's loops into calls to memcpy and memset
# (themselves, on the targets; the host's, in its test).
MINI_LIBC_FLAGS := -fno-tree-loop-distribute-patterns
$(CROSS_DIR)/%/fw/firmware/mini_libc.c.o: CROSS_CFLAGS += $(MINI_LIBC_FLAGS)
