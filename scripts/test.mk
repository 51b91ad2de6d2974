# The test command's phases (scripts/test.sh runs this with make -j): each
# phase a target, its prerequisites the order and overlap, scripts/phase.sh
# its runner (its output in $(B)/phases/NAME.log, printed whole when it ends,
# its wall and CPU time, and the whole run ended at the first failure).
#
#   build ──┬── test ────────────┬── test-asan ──┬── systemd
#           └── package ── package-check ────────┘
#   build-asan ──────────────────┴── fuzz
#   tidy
#   format
#
# What runs beside another is niced (the first argument of $(run)) so that
# what the next phase waits for gets the cores first: the plain build and
# its tests, then the sanitizer build (the sanitizer tests wait for it), then
# the package, then clang-tidy and the fuzzers, which nothing waits for until
# the end. The sanitizer build and clang-tidy start at once, beside the plain
# build: niced, they take the cores its links and configure leave idle. The
# sanitizer tests wait for the plain tests too: both at once would fight over
# the cores that the tests' timing leans on. The service's container is not
# niced: its bridge is real-time, and a niced one would judge the host's load.
# The measured times are in docs/testing.md, "The test command's time".

B := $(BUILD)
P := $(B)/phases
run = scripts/phase.sh $(P) $@
JOBS ?= $(shell nproc)

.PHONY: all quick format build test build-asan test-asan package package-check systemd tidy fuzz
all: format test test-asan package-check systemd tidy fuzz
	@scripts/phase.sh --summary $(P)
quick: test
	@scripts/phase.sh --summary $(P)

format:
	@$(run) 0 scripts/lint.sh --format
# The full run's plain tree leaves out the fuzz targets' corpus replays: the
# sanitizer tree runs the same corpora under ASan and UBSan.
build:
	@$(run) 0 scripts/build.sh -DANDROS_FUZZ_REPLAY=$(if $(filter all,$(MAKECMDGOALS)),OFF,ON)
# ctest runs three jobs a core: a command-line test mostly waits on the frame
# clock, and the longest of them are the phase's floor (tests/CMakeLists.txt
# starts them first).
test: build
	@$(run) 0 ctest --test-dir $(B) --output-on-failure --parallel $$((3 * $(JOBS))) --timeout 300

# One sanitizer tree for the suite and the fuzz targets: clang, ASan + UBSan,
# libFuzzer's coverage in every file, -O1 -g1 (OSS-Fuzz's flags). A tree an
# older test command configured with gcc is made again.
build-asan:
	@grep -qs '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang' $(B)-asan/CMakeCache.txt || rm -rf $(B)-asan
	@CXX=clang++ BUILD_DIR=$(B)-asan BUILD_FLAGS=cmake $(run) 5 scripts/build.sh -DANDROS_SANITIZE=ON \
	  -DANDROS_FUZZ=ON -DANDROS_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
# Four jobs a core: nothing builds beside these (the fuzzers, niced, take what
# they leave idle).
test-asan: build-asan test
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  $(run) 0 ctest --test-dir $(B)-asan --output-on-failure --parallel $$((4 * $(JOBS))) --timeout 600
# Each fuzz target for ANDROS_FUZZ_SECONDS (10) of its own: bounded by its
# time, not its work (its executions, printed at the end, say how much).
fuzz: build-asan
	@FUZZ_BUILD_DIR=$(B)-asan $(run) 19 scripts/fuzz.sh $${ANDROS_FUZZ_SECONDS:-10}

# The Debian package, its objects from ccache (the plain build compiled them
# with its flags), then checked.
package: build
	@$(run) 10 --tail 1 scripts/package.sh
package-check: package
	@$(run) 10 tests/package/test_package.sh dist/andros-bridge_*.deb
systemd: package-check test-asan
	@$(run) 0 tests/service/test_systemd.sh dist/andros-bridge_*.deb
# clang-tidy's cache (scripts/lint_tidy.py) makes a run over unchanged files
# take seconds.
tidy:
	@$(run) 19 scripts/lint.sh --tidy
