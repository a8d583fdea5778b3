# mote-render's command line, run by tests/tools/mote_render.sh as part of
# `make test` (BIN: where the built tool is).

test-build: $(MOTE_RENDER)
TEST_EXTRA += tests/tools/mote_render.sh
test: export BIN := $(BIN)
