# The vector pixel loops (src/core/span_simd.h). x86-64: the unit tests
# hold SSE2 and AVX2 to the scalar loops (tests/test_spans.c), and
# `make test SIMD=0` tests the scalar build alone. AArch64: `make
# test-neon` (part of make test) cross-builds the render matrix for NEON
# and runs it under qemu-aarch64 (tests/simd/neon.sh, which installs
# gcc-aarch64-linux-gnu and qemu-user as root when they are missing).
# (Included by the top Makefile's tests/*/*.mk, beside tests/tests.mk.)

.PHONY: test-neon
test-neon: | $(DEPS_OK)
	@BUILD=$(BUILD) sh tests/run.sh tests/simd/neon.sh

# Not in the sanitizer build (SAN=1): nothing of it is instrumented.
ifneq ($(SAN),1)
TEST_EXTRA += tests/simd/neon.sh
endif
