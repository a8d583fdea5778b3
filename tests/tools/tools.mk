# The command lines of mote-render and mote-bake, run by
# tests/tools/mote_render.sh and tests/tools/mote_bake.sh as part of
# `make test` (BIN: where the built tools are).

test-build: $(BIN)/mote-render $(BIN)/mote-bake
TEST_EXTRA += tests/tools/mote_render.sh tests/tools/mote_bake.sh
test: export BIN := $(BIN)
