# mote - build, demo and test. `make help` lists the targets.
#
# Everything a target needs is installed or fetched by the target itself
# (third_party/setup.sh): Debian packages through apt-get, Unity from the
# Debian cjson source package. Area-specific rules live in the *.mk files
# included at the end (examples/, tests/, tests/bench/, tests/fuzz/, embedded/).

CC       ?= gcc
AR       ?= ar
PREFIX   ?= /usr/local
OPENMP   ?= 1
SAN      ?= 0
SIMD     ?= 1
BUILD    ?= build
OUT      ?= out

PKGS     := cglm libcjson stb
DEPS_OK  := $(BUILD)/.deps-ok

WARN     := -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Werror
# -ffp-contract=off: no fused multiply-add, so float results (and therefore
# pixels) are the same bytes on x86-64, ARM and RISC-V.
BASEFLAGS := -std=c99 -O2 -g -ffp-contract=off $(WARN) -Iinclude -Isrc
PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS   = $(shell pkg-config --libs libcjson stb 2>/dev/null)

ifeq ($(OPENMP),1)
OMPFLAGS := -fopenmp
endif
# SAN=1: ASan+UBSan, with the generic pixel loop alone: instrumenting
# span.c's specialised loops (hundreds of inlined copies of one body) takes
# GCC minutes a build; they run under ASan+UBSan in `make fuzz` instead.
ifeq ($(SAN),1)
SANFLAGS := -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer -fno-sanitize-recover=all
SANDEFS  := -DMOTE_SPECIALISE_SPANS=0
BUILD    := build-san
DEPS_OK  := $(BUILD)/.deps-ok
endif

# SIMD=0: the scalar pixel loops alone (the vector ones draw the same
# bytes; `make test SIMD=0` tests the scalar build), in its own folder
ifeq ($(SIMD),0)
SIMDFLAGS := -DMOTE_SIMD=0
BUILD    := $(BUILD)-scalar
DEPS_OK  := $(BUILD)/.deps-ok
endif

CFLAGS   += $(BASEFLAGS) $(PKG_CFLAGS) $(OMPFLAGS) $(SANFLAGS) $(SANDEFS) $(SIMDFLAGS)
# The core is the hot code, built at -O3: GCC then unrolls setup's loops
# over attributes and plane components and the vertex stage's small loops
# (dense grid: 10% fewer instructions). Same pixels: the pixel stage is
# integer, and no -O level reorders float arithmetic.
CORE_OPT ?= -O3
LDFLAGS  += $(OMPFLAGS) $(SANFLAGS)
LDLIBS   += $(PKG_LIBS) -lm

CORE_SRC := $(wildcard src/core/*.c)
IO_SRC   := $(wildcard src/io/*.c) $(wildcard src/host/*.c)
LIB_OBJ  := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(CORE_SRC) $(IO_SRC))
LIB      := $(BUILD)/libmote.a
BIN      := $(BUILD)/bin

.PHONY: all lib deps demo test clean install help freestanding
.DEFAULT_GOAL := all
# keep intermediate objects (test and example objects are chained rules)
.SECONDARY:

all: lib examples

lib: $(LIB)

deps: $(DEPS_OK)

$(DEPS_OK):
	@CC="$(CC)" sh third_party/setup.sh
	@mkdir -p $(dir $@) && touch $@

$(BUILD)/obj/core/%.o: CFLAGS += $(CORE_OPT)
$(BUILD)/obj/%.o: src/%.c $(wildcard include/mote/*.h src/core/*.h src/io/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

# The core must stay freestanding: compile it as a bare-metal target would.
freestanding: | $(DEPS_OK)
	$(CC) -std=c99 -ffreestanding -fsyntax-only $(WARN) -Iinclude -Isrc $(CORE_SRC)

install: lib
	install -d $(DESTDIR)$(PREFIX)/include/mote $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/mote/*.h $(DESTDIR)$(PREFIX)/include/mote/
	install -m 644 $(LIB) $(DESTDIR)$(PREFIX)/lib/
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBS@|$(PKG_LIBS) -lm $(OMPFLAGS)|' \
	    mote.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/mote.pc

clean:
	rm -rf build build-san $(TSAN_BUILD) $(OUT)

help:
	@echo "make            build libmote.a, the examples and mote-render"
	@echo "make demo       render the demo scene and the chapter examples to $(OUT)/*.png"
	@echo "make test       build and run the Unity test suite (SAN=1: with ASan+UBSan)"
	@echo "make bench      time against error, tables and plot (tests/bench)"
	@echo "make profile    where a frame's instructions go, by stage (Callgrind)"
	@echo "make accuracy   error of every mode against the reference renderer"
	@echo "make render-matrix  a hash per configuration (RENDER_MATRIX_REF=file compares)"
	@echo "make cross      build the core for Cortex-M0+, Cortex-M4F and RV32IMAC, sizes and stack"
	@echo "make switch-sizes  flash each MOTE_ENABLE_* switch saves on Cortex-M0+ (markdown)"
	@echo "make test-embedded  render on emulated M0+, M4F and RV32 boards (qemu) and compare"
	@echo "make bench-embedded  instructions per frame on the emulated boards, RAM, flash"
	@echo "make fuzz       run each libFuzzer target (FUZZ_SECONDS=60)"
	@echo "make valgrind   the examples and mote-render under valgrind memcheck"
	@echo "make tsan       the parallel path under ThreadSanitizer (pthreads, and OpenMP via clang)"
	@echo "make assets     regenerate assets/ with tools/gen_assets.c"
	@echo "make install PREFIX=/usr/local   headers, libmote.a and mote.pc"
	@echo "make clean      remove build outputs"
	@echo "Options: OPENMP=0 (no OpenMP), SAN=1 (sanitizers), CC=clang"

-include $(sort $(wildcard examples/*.mk tools/*.mk tests/*.mk tests/*/*.mk embedded/*.mk))
