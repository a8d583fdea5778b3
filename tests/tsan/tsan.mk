# ThreadSanitizer check of the parallel path (tests/tsan/tsan_parallel.c).
#
#   make tsan          build both programs below and run them; ends with
#                      "N passed, M failed"
#   make tsan-build    only build them
#
# $(TSAN_BUILD)/gcc/tsan_parallel: the library and the test built with
#   $(CC) -fsanitize=thread (the runtime, libtsan, comes with GCC), tiles
#   run on the test's pthread pool, which ThreadSanitizer understands;
#   GCC's OpenMP runtime is not instrumented, so OpenMP is left out.
# $(TSAN_BUILD)/clang-openmp/tsan_parallel: the same with clang, -fopenmp
#   and LLVM's OpenMP runtime, whose synchronisation LLVM's Archer tool
#   (libarcher.so, loaded through OMP_TOOL_LIBRARIES) describes to
#   ThreadSanitizer: the tests run through src/host/parallel.c's loop.
# clang, libomp and the TSan runtimes are installed (Debian) when missing.

TSAN_BUILD   ?= build-tsan
TSAN_CC      ?= gcc
TSAN_CLANG   ?= clang
TSAN_GCC     := $(TSAN_BUILD)/gcc
TSAN_OMP     := $(TSAN_BUILD)/clang-openmp
TSAN_FLAGS   := -fsanitize=thread -fno-omit-frame-pointer
# The generic pixel loop alone (which loop fills a tile does not change
# what a thread touches; the specialised ones take minutes to instrument).
TSAN_CFLAGS   = $(BASEFLAGS) $(PKG_CFLAGS) $(TSAN_FLAGS) -I$(UNITY_DIR_LOCAL)/src -Itests \
                -DMOTE_SOURCE_DIR=\"$(CURDIR)\" -DMOTE_SPECIALISE_SPANS=0
TSAN_SRC     := $(CORE_SRC) $(IO_SRC) tests/support/scenes.c
TSAN_BINS    := $(TSAN_GCC)/tsan_parallel $(TSAN_OMP)/tsan_parallel
# Every report is printed (halt_on_error=0, the default) and fails the
# test that ran. ignore_noninstrumented_modules is Archer's advice (the
# OpenMP runtime is not instrumented); mote's code all is.
TSAN_ENV      = TSAN_OPTIONS="ignore_noninstrumented_modules=1 $(TSAN_OPTIONS)" \
                OMP_TOOL_LIBRARIES="$$(cat $(TSAN_OMP)/archer)"

.PHONY: tsan tsan-build
.PRECIOUS: $(TSAN_GCC)/obj/%.o $(TSAN_OMP)/obj/%.o

tsan: tsan-build
	@$(TSAN_ENV) sh tests/run.sh $(TSAN_BINS)

tsan-build: $(TSAN_BINS)

# Archer lives beside libomp, in LLVM's lib folder above clang's resources
TSAN_ARCHER   = "$$($(TSAN_CLANG) -print-resource-dir)/../../libarcher.so"

# A compiler that links -fsanitize=thread, and for the OpenMP build one
# with libomp and Archer; the file archer names the tool's library.
$(TSAN_GCC)/.ok: | $(DEPS_OK)
	@mkdir -p $(dir $@)
	@printf 'int main(void) { return 0; }\n' > $(dir $@)probe.c
	@$(TSAN_CC) -fsanitize=thread $(dir $@)probe.c -o $(dir $@)probe 2>/dev/null || \
	    MOTE_EXTRA_PACKAGES="libtsan2" sh third_party/setup.sh
	@$(TSAN_CC) -fsanitize=thread $(dir $@)probe.c -o $(dir $@)probe || \
	    { echo "error: $(TSAN_CC) cannot link -fsanitize=thread" >&2; exit 1; }
	@touch $@

$(TSAN_OMP)/.ok: | $(DEPS_OK)
	@mkdir -p $(dir $@)
	@printf '#include <omp.h>\nint main(void) { return omp_get_max_threads() < 1; }\n' > $(dir $@)probe.c
	@{ $(TSAN_CLANG) -fopenmp -fsanitize=thread $(dir $@)probe.c -o $(dir $@)probe 2>/dev/null \
	   && [ -f $(TSAN_ARCHER) ]; } || \
	    MOTE_EXTRA_PACKAGES="clang libomp-dev libclang-rt-dev" sh third_party/setup.sh
	@$(TSAN_CLANG) -fopenmp -fsanitize=thread $(dir $@)probe.c -o $(dir $@)probe || \
	    { echo "error: $(TSAN_CLANG) cannot link -fopenmp -fsanitize=thread" >&2; exit 1; }
	@a=$$(realpath -e $(TSAN_ARCHER)) || \
	    { echo "error: no libarcher.so beside $(TSAN_CLANG)'s libomp" >&2; exit 1; }; \
	    echo "$$a" > $(dir $@)archer
	@touch $@

$(TSAN_GCC)/obj/src/core/%.o $(TSAN_OMP)/obj/src/core/%.o: TSAN_OPT := $(CORE_OPT)
$(TSAN_GCC)/obj/%.o: %.c $(wildcard include/mote/*.h src/core/*.h src/io/*.h tests/support/*.h) | $(TSAN_GCC)/.ok $(UNITY_OK)
	@mkdir -p $(dir $@)
	$(TSAN_CC) $(TSAN_CFLAGS) $(TSAN_OPT) -c $< -o $@

$(TSAN_OMP)/obj/%.o: %.c $(wildcard include/mote/*.h src/core/*.h src/io/*.h tests/support/*.h) | $(TSAN_OMP)/.ok $(UNITY_OK)
	@mkdir -p $(dir $@)
	$(TSAN_CLANG) $(TSAN_CFLAGS) -fopenmp $(TSAN_OPT) -c $< -o $@

$(TSAN_GCC)/unity.o: $(UNITY_OK) | $(TSAN_GCC)/.ok
	$(TSAN_CC) -std=c99 -O2 -g $(TSAN_FLAGS) -c $< -o $@

$(TSAN_OMP)/unity.o: $(UNITY_OK) | $(TSAN_OMP)/.ok
	$(TSAN_CLANG) -std=c99 -O2 -g $(TSAN_FLAGS) -c $< -o $@

TSAN_OBJ = $(patsubst %.c,$(1)/obj/%.o,$(TSAN_SRC) tests/tsan/tsan_parallel.c) $(1)/unity.o

$(TSAN_GCC)/tsan_parallel: $(call TSAN_OBJ,$(TSAN_GCC)) | $(TSAN_GCC)/.ok
	$(TSAN_CC) $(TSAN_FLAGS) $^ $(PKG_LIBS) -lm -pthread -o $@

$(TSAN_OMP)/tsan_parallel: $(call TSAN_OBJ,$(TSAN_OMP)) | $(TSAN_OMP)/.ok
	$(TSAN_CLANG) $(TSAN_FLAGS) -fopenmp $^ $(PKG_LIBS) -lm -pthread -o $@
