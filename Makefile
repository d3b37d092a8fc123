# termpool -- GNU make 4.3, g++ 12, C++20.
#
#   make            build build/termpool
#   make run        build, then start the game (ARGS='--resume' passes arguments)
#   make test       build the binary and the tests, run the tests (TEST_ARGS='[tag]' filters)
#   make check      same as test, in a separate sanitized tree (build/san)
#   make help       list all targets
#
# Every build uses all cores unless -j says otherwise (make -j1 builds one file at a time).

# This file, for the sub-makes of check and ensure-deps (works with make -f too).
THIS_MAKEFILE := $(lastword $(MAKEFILE_LIST))

# All cores by default: a fresh clone builds in half the time on two. A -j on the command
# line wins (GNU make 4.3 lets it override this; later versions show it in MAKEFLAGS here).
ifeq ($(filter -j%,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 2)
endif

CXX     ?= g++
PREFIX  ?= /usr/local
DESTDIR ?=

# Arguments passed to the test binary (Catch2 test specs / options), e.g. TEST_ARGS='[physics]'.
TEST_ARGS  ?=
# Arguments of the game that `make run` starts, e.g. ARGS=--resume.
ARGS       ?=
# Arguments appended to `termpool bench`, e.g. BENCH_ARGS='--breaks 100'.
BENCH_ARGS ?=
# Shots of `make soak` (the stress test's checks, on two threads).
SOAK_SHOTS ?= 1000000

SANFLAGS := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all

# SANITIZE=1 selects the sanitized tree; `make check` sets it for a sub-make.
# g++ 12 with -fsanitize=address reports false -Wmaybe-uninitialized errors inside libstdc++
# (<regex>, pulled in by Catch2), so the sanitized tree drops that one warning; the normal
# -O2 tree still has it.
ifeq ($(SANITIZE),1)
BUILD    := build/san
OPTFLAGS := -O1 -g $(SANFLAGS)
SAN_WARNFLAGS := -Wno-maybe-uninitialized
SAN_LDFLAGS   := $(SANFLAGS)
else
BUILD    := build
OPTFLAGS := -O2
SAN_WARNFLAGS :=
SAN_LDFLAGS   :=
endif

# ICU's normaliser compares the hall's names (src/hall/name_key.cpp); the core does without it.
ICU_CFLAGS   := $(shell pkg-config --cflags icu-uc 2>/dev/null)
# ncursesw as pkg-config describes it (its include folder and libraries, tinfo where split).
CURSES_CFLAGS := $(shell pkg-config --cflags ncursesw 2>/dev/null)
CURSES_LIBS   := $(shell pkg-config --libs ncursesw 2>/dev/null || echo -lncursesw)
ICU_LIBS     := $(shell pkg-config --libs icu-uc 2>/dev/null || echo -licuuc -licudata)

WARNFLAGS    := -Wall -Wextra -Wpedantic -Werror $(SAN_WARNFLAGS)
# The core sees only the public headers: it includes its private ones relative to itself
# ("cloth_model.hpp"), and nothing of src/cli or src/tui can be found from it.
CORE_CPPFLAGS := -Iinclude $(CPPFLAGS)
ALL_CPPFLAGS := -Iinclude -Isrc $(ICU_CFLAGS) $(CPPFLAGS)
# Every build keeps a*b+c as two roundings: GCC (and Clang within an expression) would fuse
# them where the CPU has FMA, and a saved game would replay differently on another build.
# GCC 12's vectorizer fuses even so (the rotation c*x - s*y, s*x + c*y became one
# vfmaddsub with -march=native), so it is off too; it bought the simulator nothing measurable.
FP_FLAGS     := -ffp-contract=off -fno-tree-vectorize
ALL_CXXFLAGS := -std=c++20 $(FP_FLAGS) $(OPTFLAGS) $(WARNFLAGS) $(CXXFLAGS)
DEPFLAGS     := -MMD -MP
ALL_LDFLAGS  := $(SAN_LDFLAGS) $(LDFLAGS)
LDLIBS       += $(CURSES_LIBS) $(ICU_LIBS)

# ---------------------------------------------------------------------------
# Sources and objects (out of tree, mirroring src/ under $(BUILD)/)

# The core is a static library; the commands (src/cli), the front end (src/tui), what the player
# keeps between games (src/player: options, config, names, saves, statistics) and the hall
# (src/hall: its server, state and socket folders) are linked with it into the binary and the
# test binary.
# src/support: the core's own helpers (text lines and numbers, portable sine and cosine, the
# random stream, the state digest), in the library but not in its installed interface.
CORE_SRCS := $(wildcard src/core/*.cpp) $(wildcard src/support/*.cpp)
FILES_SRCS := $(wildcard src/files/*.cpp)
PLAYER_SRCS := $(wildcard src/player/*.cpp)
HALL_SRCS := $(wildcard src/hall/*.cpp)
APP_SRCS  := $(wildcard src/cli/*.cpp) $(wildcard src/tui/*.cpp) $(PLAYER_SRCS) $(FILES_SRCS) \
             $(HALL_SRCS)
MAIN_SRC  := src/main.cpp
# The tests are written for Catch2 v2 (Debian 12's catch2). Where only v3 is installed,
# tests/catch3 gives its header v2's name and Catch2's own main is linked.
CATCH_V3       := $(if $(wildcard /usr/include/catch2/catch.hpp),,$(wildcard /usr/include/catch2/catch_all.hpp))
CATCH_CPPFLAGS := $(if $(CATCH_V3),-Itests/catch3)
CATCH_LIBS     := $(if $(CATCH_V3),$(shell pkg-config --libs catch2-with-main 2>/dev/null || echo -lCatch2Main -lCatch2))
TEST_SRCS := $(wildcard tests/*.cpp)

CORE_OBJS := $(patsubst src/%.cpp,$(BUILD)/%.o,$(CORE_SRCS))
APP_OBJS  := $(patsubst src/%.cpp,$(BUILD)/%.o,$(APP_SRCS))
MAIN_OBJ  := $(BUILD)/main.o
TEST_OBJS := $(patsubst tests/%.cpp,$(BUILD)/tests/%.o,$(TEST_SRCS))
ALL_OBJS  := $(CORE_OBJS) $(APP_OBJS) $(MAIN_OBJ) $(TEST_OBJS)

CORE_LIB := $(BUILD)/libtermpool.a

# The version, from its one home (include/termpool/version.hpp).
version_part = $(shell sed -n 's/^\#define TERMPOOL_VERSION_$(1) \([0-9]*\)$$/\1/p' include/termpool/version.hpp)
VERSION_MAJOR := $(call version_part,MAJOR)
VERSION_MINOR := $(call version_part,MINOR)
VERSION   := $(VERSION_MAJOR).$(VERSION_MINOR).$(call version_part,PATCH)
# Below 1.0 a minor version may change the interface, so the soname carries it.
SONAME    := libtermpool.so.$(if $(filter 0,$(VERSION_MAJOR)),$(VERSION_MAJOR).$(VERSION_MINOR),$(VERSION_MAJOR))
# The shared library and the Python module are built from position-independent objects of
# their own ($(BUILD)/pic), so that the program and the static library keep their code.
PIC_OBJS  := $(patsubst src/%.cpp,$(BUILD)/pic/%.o,$(CORE_SRCS))
SHARED_LIB := $(BUILD)/libtermpool.so.$(VERSION)
LIBDIR    ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
BIN      := $(BUILD)/termpool
TEST_BIN := $(BUILD)/termpool_tests

# The Python module (src/python, pybind11) is the core's PIC objects and its own, for the Python
# that /usr/bin/python3 is (Debian's, with its python3-pybind11 and python3-numpy; PYTHON=...
# picks another). It installs where that Python looks for a PREFIX: Debian's dist-packages for
# /usr and /usr/local, PREFIX/lib/pythonX.Y/site-packages elsewhere; PYTHON_SITE overrides.
PYTHON         ?= /usr/bin/python3
PYTHON_CONFIG  ?= $(PYTHON)-config
PYTHON_VERSION := $(shell $(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null)
PYTHON_SUFFIX  := $(shell $(PYTHON_CONFIG) --extension-suffix 2>/dev/null)
PYTHON_CFLAGS  := $(shell $(PYTHON_CONFIG) --includes 2>/dev/null)
PYTHON_READY   := $(and $(PYTHON_SUFFIX),$(wildcard /usr/include/pybind11/pybind11.h))
PYTHON_SITE    ?= $(if $(filter /usr,$(PREFIX)),$(PYTHON_SITE_USR),$(if \
                  $(filter /usr/local,$(PREFIX)),/usr/local/lib/python$(PYTHON_VERSION)/dist-packages,$(PREFIX)/lib/python$(PYTHON_VERSION)/site-packages))
# Where the module goes for PREFIX /usr (the staged install that the tests use).
PYTHON_SITE_USR := /usr/lib/python3/dist-packages
PYTHON_SRCS    := $(wildcard src/python/*.cpp)
PYTHON_OBJS    := $(patsubst src/%.cpp,$(BUILD)/pic/%.o,$(PYTHON_SRCS))
PYTHON_MODULE  := $(BUILD)/python/termpool$(PYTHON_SUFFIX)

FLAGS_STAMP := $(BUILD)/compile-flags
OBJ_DIRS := $(sort $(patsubst %/,%,$(dir $(ALL_OBJS) $(BIN))))

FORMAT_FILES := $(wildcard src/*.cpp src/*.hpp src/*/*.cpp src/*/*.hpp \
                           include/*/*.hpp include/*/*/*.hpp tests/*.cpp tests/*.hpp \
                           tests/catch3/*/*.hpp doc/examples/*.cpp)

# What the build needs, and what the tests need besides: tmux runs the end-to-end tests, groff
# checks the man page, pytest and NumPy test the Python module, doxygen makes the API reference.
# pkg-config finds ncursesw and ICU. tools/missing-deps names those this machine lacks.
DEB_PACKAGES := g++ make pkg-config libncurses-dev libicu-dev catch2 tmux groff python3-dev \
                pybind11-dev python3-pytest python3-numpy doxygen

# run/test/check install missing dependencies first. The gate is an order-only prerequisite
# of every object, so nothing compiles (even with -j) before `make deps` ends.
ifneq ($(filter run test check,$(MAKECMDGOALS)),)
ifneq ($(shell sh tools/missing-deps $(PYTHON)),)
DEPS_GATE := ensure-deps
endif
endif

# ---------------------------------------------------------------------------

.DEFAULT_GOAL := all
.PHONY: all run test check bench soak deps ensure-deps install uninstall clean format format-check help lib python python-missing docs \
        fuzz fuzz-deps fuzz-run layers FORCE
.DELETE_ON_ERROR:

all: $(BIN)

# The library comes after the objects that use it, as the linker needs.
$(BIN): $(APP_OBJS) $(MAIN_OBJ) $(CORE_LIB) | $(OBJ_DIRS)
	$(CXX) $(ALL_CXXFLAGS) $(ALL_LDFLAGS) $^ -o $@ $(LDLIBS)

$(TEST_BIN): $(APP_OBJS) $(TEST_OBJS) $(CORE_LIB) | $(OBJ_DIRS)
	$(CXX) $(ALL_CXXFLAGS) $(ALL_LDFLAGS) $^ -o $@ $(LDLIBS) $(CATCH_LIBS)

# Written afresh, so that the object of a removed source does not stay in the archive.
$(CORE_LIB): $(CORE_OBJS) | $(OBJ_DIRS)
	rm -f $@
	$(AR) rcs $@ $^

# The tests and core rules have shorter stems than the general one, so make prefers them for
# $(BUILD)/tests/*.o and $(BUILD)/core/*.o. Tests may include the core's private headers
# (core/polynomial.hpp), so they get -Isrc like the front ends.
$(BUILD)/tests/%.o: tests/%.cpp $(FLAGS_STAMP) | $(OBJ_DIRS) $(DEPS_GATE)
	$(CXX) $(ALL_CPPFLAGS) $(CATCH_CPPFLAGS) $(ALL_CXXFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/core/%.o: src/core/%.cpp $(FLAGS_STAMP) | $(OBJ_DIRS) $(DEPS_GATE)
	$(CXX) $(CORE_CPPFLAGS) $(ALL_CXXFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/support/%.o: src/support/%.cpp $(FLAGS_STAMP) | $(OBJ_DIRS) $(DEPS_GATE)
	$(CXX) $(CORE_CPPFLAGS) $(ALL_CXXFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/%.o: src/%.cpp $(FLAGS_STAMP) | $(OBJ_DIRS) $(DEPS_GATE)
	$(CXX) $(ALL_CPPFLAGS) $(ALL_CXXFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/pic/%.o: src/%.cpp $(FLAGS_STAMP) | $(DEPS_GATE)
	@mkdir -p $(dir $@)
	$(CXX) $(CORE_CPPFLAGS) $(ALL_CXXFLAGS) -fPIC $(DEPFLAGS) -c $< -o $@

# pybind11 wants its module's symbols hidden (and says so in a warning otherwise).
$(BUILD)/pic/python/%.o: src/python/%.cpp $(FLAGS_STAMP) | $(DEPS_GATE)
	@mkdir -p $(dir $@)
	$(CXX) -Iinclude -Isrc $(PYTHON_CFLAGS) $(CPPFLAGS) $(ALL_CXXFLAGS) -fPIC -fvisibility=hidden \
	  $(DEPFLAGS) -c $< -o $@

$(PYTHON_MODULE): $(PYTHON_OBJS) $(PIC_OBJS)
	@mkdir -p $(dir $@)
	$(CXX) $(ALL_CXXFLAGS) $(ALL_LDFLAGS) -shared $^ -o $@

# The API reference of the installed headers (doc/Doxyfile), with doc/api.md and doc/python.md:
# build/docs/html/index.html. A public declaration without its /// comment fails it.
docs:
	@mkdir -p $(BUILD)/docs
	TERMPOOL_VERSION=$(VERSION) TERMPOOL_DOCS_DIR=$(BUILD)/docs doxygen doc/Doxyfile
	@if [ -s $(BUILD)/docs/warnings.txt ]; then cat $(BUILD)/docs/warnings.txt >&2; exit 1; fi
	@echo "docs: $(BUILD)/docs/html/index.html"

# The Python module: `make python`, then PYTHONPATH=build/python python3 -c 'import termpool'.
python: $(if $(PYTHON_READY),$(PYTHON_MODULE),python-missing)

python-missing:
	@echo "python: pybind11-dev and python3-dev are needed for $(PYTHON) (make deps installs them)" >&2
	@exit 1

$(SHARED_LIB): $(PIC_OBJS)
	$(CXX) $(ALL_CXXFLAGS) $(ALL_LDFLAGS) -shared -Wl,-soname,$(SONAME) $^ -o $@

# The libraries (what `make install` installs besides the program; it writes termpool.pc for
# the prefix it installs to).
lib: $(CORE_LIB) $(SHARED_LIB)

# Only the files that include curses see its flags (its -D_XOPEN_SOURCE would narrow the
# POSIX of the others).
$(patsubst src/%.cpp,$(BUILD)/%.o,$(shell grep -l 'curses.h>' src/tui/*.cpp)): \
  ALL_CPPFLAGS += $(CURSES_CFLAGS)

$(OBJ_DIRS):
	mkdir -p $@

# The compile flags of this build folder, rewritten only when they change: every object
# depends on it, so a folder built before a flag changed (FP_FLAGS above) is rebuilt, never
# left with objects that play differently.
FLAGS_TEXT := $(CXX) $(ALL_CPPFLAGS) $(ALL_CXXFLAGS) $(PYTHON_CFLAGS)
$(FLAGS_STAMP): FORCE | $(OBJ_DIRS)
	@if [ "$$(cat $@ 2>/dev/null)" != '$(FLAGS_TEXT)' ]; then printf '%s\n' '$(FLAGS_TEXT)' > $@; fi
FORCE:

-include $(ALL_OBJS:.o=.d) $(PIC_OBJS:.o=.d) $(PYTHON_OBJS:.o=.d)

# ---------------------------------------------------------------------------

run: $(BIN)
	exec ./$(BIN) $(ARGS)

# The test binary runs from the repo top; TERMPOOL_BIN tells tests where the CLI binary is.
# tools/run-tests runs the unit tests and the end-to-end tests ([e2e]) as two processes at
# once, and ends with `tests: N passed, M failed`; TEST_ARGS runs one process with them.
# `set -f` keeps a Catch2 tag filter like [physics] from being glob-expanded.
# Before them, `make install` puts everything into $(STAGE) (PREFIX /usr) as a packager would;
# tests/test_install.cpp builds a program and runs a Python script against that copy, and
# tests/test_python.cpp runs the module's own tests (tests/python) with pytest. A sanitized
# module is loaded into an unsanitized Python with the sanitizer runtime preloaded.
STAGE := $(BUILD)/stage
TEST_ENV = TERMPOOL_BIN="$(abspath $(BIN))" TERMPOOL_STAGE="$(abspath $(STAGE))" \
  TERMPOOL_PYTHON="$(PYTHON)" TERMPOOL_PYTHON_PATH="$(abspath $(dir $(PYTHON_MODULE)))" \
  TERMPOOL_PYTHON_SITE="$(patsubst /usr/%,%,$(PYTHON_SITE_USR))" \
  TERMPOOL_SANITIZE_FLAGS="$(SAN_LDFLAGS)" \
  TERMPOOL_PRELOAD="$(if $(SAN_LDFLAGS),$(shell $(CXX) -print-file-name=libasan.so) $(shell $(CXX) -print-file-name=libubsan.so))"
test: $(BIN) $(TEST_BIN) lib $(PYTHON_MODULE)
	rm -rf $(STAGE)
	$(call install_to,$(abspath $(STAGE)),/usr,/usr/lib,/usr/include,$(PYTHON_SITE_USR))
	@set -f; echo "TERMPOOL_BIN=$(abspath $(BIN)) tools/run-tests $(TEST_BIN) $(TEST_ARGS)"; \
	$(TEST_ENV) sh tools/run-tests ./$(TEST_BIN) $(TEST_ARGS)

# LeakSanitizer is told of the one block ncurses keeps by design (tools/lsan.supp).
check:
	@LSAN_OPTIONS=suppressions=$(CURDIR)/tools/lsan.supp \
	$(MAKE) --no-print-directory -f $(THIS_MAKEFILE) SANITIZE=1 test

bench: $(BIN)
	./$(BIN) bench $(BENCH_ARGS)

# The stress test's checks over many more shots, not part of test or CI: 10^5 shots take about
# 40 s on two cores, 10^6 some 7 minutes.
soak: $(TEST_BIN)
	SOAK_SHOTS=$(SOAK_SHOTS) ./$(TEST_BIN) '[soak]'

# Which folder includes which, read from the sources (tests/test_layers.cpp checks the rules).
layers:
	@sh tools/layers

ensure-deps:
	@$(MAKE) --no-print-directory -f $(THIS_MAKEFILE) deps

deps:
	@missing=$$(sh tools/missing-deps $(PYTHON)); \
	if [ -z "$$missing" ]; then \
	  echo "deps: dependencies present ($(DEB_PACKAGES))"; \
	else \
	  if [ "$$(id -u)" -eq 0 ]; then SUDO=; \
	  elif command -v sudo >/dev/null 2>&1; then SUDO="sudo "; \
	  else echo "deps: need root or sudo to install: $$missing" >&2; exit 1; fi; \
	  echo "deps: missing $$missing"; \
	  echo "$${SUDO}apt-get update" && $${SUDO}apt-get update && \
	  echo "$${SUDO}apt-get install -y $(DEB_PACKAGES)" && \
	  $${SUDO}apt-get install -y $(DEB_PACKAGES); \
	fi

# ---------------------------------------------------------------------------
# Fuzzing: libFuzzer targets (tests/fuzz/*.cpp) built with clang, ASan and UBSan.
# `make fuzz` builds them; `make fuzz-run FUZZ_SECONDS=600` runs each that long on its corpus.

FUZZ_CXX      ?= clang++
FUZZ_SECONDS  ?= 600
FUZZ_DIR      := build/fuzz
FUZZ_CORE_FLAGS := -std=c++20 $(FP_FLAGS) -O1 -g -fsanitize=fuzzer-no-link,address,undefined -Iinclude
FUZZ_FLAGS    := $(FUZZ_CORE_FLAGS) -Isrc $(ICU_CFLAGS)
FUZZ_APP_SRCS := src/cli/scenario.cpp src/cli/numbers.cpp \
                 src/player/config.cpp src/files/xdg_dir.cpp src/player/player_name.cpp \
                 src/player/options.cpp src/player/stats_file.cpp src/player/stats_figures.cpp \
                 src/files/keep_aside.cpp src/files/atomic_file.cpp src/files/read_file.cpp \
                 src/player/save_file.cpp \
                 src/hall/protocol.cpp src/hall/name_key.cpp src/hall/server_bounds.cpp
FUZZ_CORE_OBJS := $(patsubst src/%.cpp,$(FUZZ_DIR)/%.o,$(CORE_SRCS))
FUZZ_APP_OBJS := $(patsubst src/%.cpp,$(FUZZ_DIR)/%.o,$(FUZZ_APP_SRCS))
FUZZ_CORE_LIB := $(FUZZ_DIR)/libtermpool.a
FUZZ_TARGETS  := $(patsubst tests/fuzz/%.cpp,$(FUZZ_DIR)/%,$(wildcard tests/fuzz/*.cpp))

fuzz: fuzz-deps $(FUZZ_TARGETS)

fuzz-deps:
	@if ! command -v $(FUZZ_CXX) >/dev/null 2>&1; then \
	  if [ "$$(id -u)" -eq 0 ]; then SUDO=; else SUDO="sudo "; fi; \
	  echo "$${SUDO}apt-get install -y clang libclang-rt-dev" && \
	  $${SUDO}apt-get install -y clang libclang-rt-dev; \
	fi

# The same layers as the normal build: the core with -Iinclude only, as a library.
$(FUZZ_DIR)/core/%.o: src/core/%.cpp
	@mkdir -p $(dir $@)
	$(FUZZ_CXX) $(FUZZ_CORE_FLAGS) -MMD -MP -c $< -o $@

$(FUZZ_DIR)/%.o: src/%.cpp
	@mkdir -p $(dir $@)
	$(FUZZ_CXX) $(FUZZ_FLAGS) -MMD -MP -c $< -o $@

$(FUZZ_CORE_LIB): $(FUZZ_CORE_OBJS)
	rm -f $@
	$(AR) rcs $@ $^

$(FUZZ_DIR)/fuzz_%: tests/fuzz/fuzz_%.cpp $(FUZZ_APP_OBJS) $(FUZZ_CORE_LIB)
	$(FUZZ_CXX) $(FUZZ_FLAGS) -fsanitize=fuzzer $^ -o $@ $(ICU_LIBS)

fuzz-run: fuzz
	@for t in $(FUZZ_TARGETS); do \
	  mkdir -p $$t.corpus; echo "+ $$t -max_total_time=$(FUZZ_SECONDS)"; \
	  $$t -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 $$t.corpus || exit 1; \
	done

-include $(FUZZ_CORE_OBJS:.o=.d) $(FUZZ_APP_OBJS:.o=.d)

# The program and its man page; the library (static and shared, with its soname link and the
# development link), its headers and a termpool.pc for the prefix; the Python module where
# pybind11 is present. One recipe, `install_to ROOT,PREFIX,LIBDIR,INCLUDEDIR,PYTHON_SITE`, for
# `make install` and for the copy `make test` installs and tests. Inline code of the headers
# is compiled by the user's program, so termpool.pc asks for the same rounding as the library
# (-ffp-contract=off). Installed without DESTDIR, ldconfig (as root) makes the new soname known.
define install_to
install -d $(1)$(2)/bin $(1)$(2)/share/man/man6 $(1)$(3)/pkgconfig $(1)$(4)/termpool
install -m 755 $(BIN) $(1)$(2)/bin/termpool
install -m 644 man/termpool.6 $(1)$(2)/share/man/man6/termpool.6
install -m 644 $(CORE_LIB) $(1)$(3)/libtermpool.a
install -m 755 $(SHARED_LIB) $(1)$(3)/libtermpool.so.$(VERSION)
ln -sf libtermpool.so.$(VERSION) $(1)$(3)/$(SONAME)
ln -sf $(SONAME) $(1)$(3)/libtermpool.so
printf '%s\n' 'prefix=$(2)' 'libdir=$(3)' 'includedir=$(4)' '' 'Name: termpool' \
  'Description: event-based pool and snooker physics, referees and matches (C++20)' \
  'Version: $(VERSION)' 'Cflags: -I$${includedir} -ffp-contract=off' \
  'Libs: -L$${libdir} -ltermpool' \
  > $(1)$(3)/pkgconfig/termpool.pc
install -m 644 include/termpool/*.hpp $(1)$(4)/termpool/
$(if $(PYTHON_READY),install -d $(1)$(5) && install -m 644 $(PYTHON_MODULE) $(1)$(5)/,@echo \
  "install: no Python module (pybind11-dev or python3-dev missing; make deps installs them)")
$(if $(1),,-ldconfig $(3) 2>/dev/null)
endef

install: $(BIN) lib $(if $(PYTHON_READY),python)
	$(call install_to,$(DESTDIR),$(PREFIX),$(LIBDIR),$(INCLUDEDIR),$(PYTHON_SITE))

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/termpool $(DESTDIR)$(PREFIX)/share/man/man6/termpool.6 \
	  $(DESTDIR)$(LIBDIR)/libtermpool.a $(DESTDIR)$(LIBDIR)/libtermpool.so.$(VERSION) \
	  $(DESTDIR)$(LIBDIR)/$(SONAME) $(DESTDIR)$(LIBDIR)/libtermpool.so \
	  $(DESTDIR)$(LIBDIR)/pkgconfig/termpool.pc \
	  $(DESTDIR)$(PYTHON_SITE)/$(notdir $(PYTHON_MODULE))
	rm -rf $(DESTDIR)$(INCLUDEDIR)/termpool

clean:
	rm -rf build

format:
	clang-format -i $(FORMAT_FILES)

format-check:
	clang-format --dry-run --Werror $(FORMAT_FILES)

help:
	@echo "targets:"
	@echo "  all           build $(BIN) (default)"
	@echo "  run           build, then start build/termpool (ARGS=... its arguments)"
	@echo "  test          build everything, install it into $(BUILD)/stage, run the unit and"
	@echo "                end-to-end tests side by side (the installed copy and Python's too)"
	@echo "                (TEST_ARGS='[tag]' to filter; TERMPOOL_SKIP_E2E=1 skips [e2e])"
	@echo "  check         like test, in build/san with ASan+UBSan"
	@echo "  bench         build, then run 'build/termpool bench' (BENCH_ARGS=...)"
	@echo "  soak          the stress test's checks over SOAK_SHOTS shots (10^6), two threads,"
	@echo "                then 100,000 more random shots ([.soak] tests)"
	@echo "  layers        print the include graph: which folder includes which, how often"
	@echo "  deps          install $(DEB_PACKAGES) with apt-get if missing"
	@echo "  lib           build $(CORE_LIB) and $(SHARED_LIB) (soname $(SONAME))"
	@echo "  python        build the Python module $(PYTHON_MODULE) (pybind11)"
	@echo "  docs          the API reference from the headers: $(BUILD)/docs/html/index.html"
	@echo "  install       install the binary, man page, libraries, headers, termpool.pc and the"
	@echo "                Python module under \$$(DESTDIR)\$$(PREFIX) ($(PREFIX))"
	@echo "  uninstall     remove them again"
	@echo "  clean         remove build/"
	@echo "  format        clang-format -i all sources"
	@echo "  format-check  fail if any source is not clang-formatted"
	@echo "  fuzz          build the libFuzzer targets in build/fuzz (clang)"
	@echo "  fuzz-run      run each fuzz target FUZZ_SECONDS (600) on its corpus"
