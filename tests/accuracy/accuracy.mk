# `make accuracy`: every mode's error against the reference renderer
# (tests/ref), on the built-in test scenes, the project's assets/*.babylon
# and ../shared/assets/monkey.babylon when present. Prints a table, then
# the same with the integer vertex stage (tests/fixed/fixed.mk's library).

ACC_BIN := $(BUILD)/accuracy/accuracy
ACC_FIXED_BIN := $(BUILD)/accuracy/accuracy-fixed
ACC_SRC := tests/accuracy/accuracy.c tests/ref/ref.c tests/support/testutil.c tests/support/scenes.c

.PHONY: accuracy
accuracy: $(ACC_BIN) $(ACC_FIXED_BIN)
	$(ACC_BIN)
	@echo
	$(ACC_FIXED_BIN)

$(ACC_BIN): $(ACC_SRC) $(wildcard tests/ref/*.h tests/support/*.h include/mote/*.h) $(LIB) | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -Itests -DMOTE_SOURCE_DIR=\"$(CURDIR)\" $(ACC_SRC) $(LIB) $(LDFLAGS) $(LDLIBS) -o $@

$(ACC_FIXED_BIN): $(ACC_SRC) $(wildcard tests/ref/*.h tests/support/*.h include/mote/*.h) $(BUILD)/fixed/libmote.a | $(DEPS_OK)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -DMOTE_FIXED_VERTEX=1 -Itests -DMOTE_SOURCE_DIR=\"$(CURDIR)\" $(ACC_SRC) $(BUILD)/fixed/libmote.a $(LDFLAGS) $(LDLIBS) -o $@
