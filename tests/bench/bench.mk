# `make bench`: mote's speed against its error, per mode, beside Mesa's
# llvmpipe (OSMesa), with thread scaling and the savings of each shortcut.
# Tables on stdout; $(OUT)/bench/bench.csv, bench.md and pareto.png.
# The target installs what it needs itself (gnuplot-nox, libosmesa6-dev);
# without OSMesa the llvmpipe comparison is skipped with the reason, without
# gnuplot the plot is. BENCH_ARGS passes options (--cap S, --frames N, ...).
#
# `make profile`: where a frame's instructions go, by stage (fills, setup,
# vertex stage, culling and binning, clear), counted by Callgrind on the
# grid and on Suzanne at both sizes (tests/bench/profile.sh, which holds
# that default; installs valgrind). PROFILE_SCENES picks other scenes.

BENCH_DIR     := $(BUILD)/bench
BENCH_BIN     := $(BENCH_DIR)/mote-bench
BENCH_OUT     := $(OUT)/bench
BENCH_PKGS    := gnuplot-nox libosmesa6-dev
BENCH_ARGS    ?=
BENCH_REF_SRC := $(sort $(wildcard tests/ref/*.c))
BENCH_REF_OBJ := $(patsubst tests/ref/%.c,$(BENCH_DIR)/ref/%.o,$(BENCH_REF_SRC))
# The bench's adapter to the reference renderer exists only beside it.
BENCH_REF_ON  := $(if $(and $(BENCH_REF_SRC),$(wildcard tests/bench/bench_ref.c)),1)
# Decided when used (after the packages are installed), so `=` not `:=`.
BENCH_OSMESA   = $(shell test -f /usr/include/GL/osmesa.h && pkg-config --exists osmesa 2>/dev/null && echo osmesa || echo none)
BENCH_CFLAGS   = $(CFLAGS) -Itests -Itests/bench -DMOTE_SOURCE_DIR=\"$(CURDIR)\" \
                 $(if $(BENCH_REF_ON),-DBENCH_HAVE_REF)
BENCH_OBJ      = $(BENCH_DIR)/bench.o $(BENCH_DIR)/gl-$(BENCH_OSMESA).o \
                 $(if $(BENCH_REF_ON),$(BENCH_DIR)/bench_ref.o $(BENCH_REF_OBJ))

.PHONY: bench bench-run bench-build profile

profile:
	@MOTE_EXTRA_PACKAGES=valgrind sh third_party/setup.sh
	@$(MAKE) --no-print-directory bench-build
	sh tests/bench/profile.sh $(BENCH_BIN) $(PROFILE_SCENES)

bench:
	@for p in $(BENCH_PKGS); do \
	    MOTE_EXTRA_PACKAGES="$$p" sh third_party/setup.sh \
	        || echo "bench: could not install $$p; going on without it"; \
	done
	@$(MAKE) --no-print-directory bench-run

# The GL backend is chosen by what is installed. The Makefile's .SECONDARY
# means a missing gl-*.o alone does not relink mote-bench, so a change of
# backend (OSMesa installed after a first build) removes the binary.
bench-build: $(LIB)
	@mkdir -p $(BENCH_DIR)
	@if [ "$$(cat $(BENCH_DIR)/gl-backend 2>/dev/null)" != "$(BENCH_OSMESA)" ]; then \
	    rm -f $(BENCH_BIN); echo "$(BENCH_OSMESA)" > $(BENCH_DIR)/gl-backend; fi
	@$(MAKE) --no-print-directory $(BENCH_BIN)

bench-run: bench-build
	@mkdir -p $(BENCH_OUT)
	$(BENCH_BIN) --out $(BENCH_OUT) $(BENCH_ARGS)
	@if command -v gnuplot >/dev/null 2>&1; then \
	    gnuplot -e "dir='$(BENCH_OUT)'" tests/bench/pareto.gp && echo "wrote $(BENCH_OUT)/pareto.png"; \
	else echo "bench: gnuplot is not installed: no $(BENCH_OUT)/pareto.png"; fi

$(BENCH_BIN): $(BENCH_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(LDFLAGS) $(BENCH_OBJ) $(LIB) $(LDLIBS) $(if $(filter osmesa,$(BENCH_OSMESA)),-lOSMesa) -o $@

$(BENCH_DIR)/bench.o: tests/bench/bench.c tests/bench/bench.h $(wildcard include/mote/*.h tests/bench/*.h tests/ref/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -c $< -o $@

$(BENCH_DIR)/bench_ref.o: tests/bench/bench_ref.c tests/bench/bench.h $(wildcard include/mote/*.h tests/ref/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -c $< -o $@

$(BENCH_DIR)/gl-osmesa.o: tests/bench/gl.c tests/bench/bench.h $(wildcard include/mote/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -DBENCH_OSMESA -c $< -o $@

$(BENCH_DIR)/gl-none.o: tests/bench/gl.c tests/bench/bench.h $(wildcard include/mote/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -c $< -o $@

$(BENCH_DIR)/ref/%.o: tests/ref/%.c $(wildcard tests/ref/*.h include/mote/*.h) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -c $< -o $@
