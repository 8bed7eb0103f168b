# FabGuide: the two commands a user needs, wrapping CMake (see README.md).
#   make          install missing Debian packages, build everything into build/
#   make test     ... then run every test (C++, headless FreeCAD, FreeCAD GUI under Xvfb)
#   make check    ... then the fast tier: the C++ tests, the style check and the Python suites of a few seconds
#   make demo     ... then install the workbench into FreeCAD and run it on a bundled example
#   make install  ... then install the workbench (MOD_DIR=... to choose the folder)
#   make bench    ... then regenerate docs/benchmarks.md
#   make deb      ... then build the Debian package of this release into build/ (tools/make-deb)
# and what CI runs besides `make test` (.ci/run):
#   make test-debian13   `make test` inside a Debian 13 chroot (FreeCAD 1.0, OCCT 7.8), made by tools/in-debian13;
#                        CTEST_ARGS="-LE host" (as CI runs it) leaves out the suites no Debian release changes,
#                        CMAKE_ARGS=-DFABGUIDE_CPP_TESTS=OFF (as CI) the C++ tests, run by Debian 12 and the sanitizers
#   make test-deb        `make deb`, then apt install the package and test the installed workbench (tools/test-deb)
#   make test-deb-debian13   the same in the Debian 13 chroot
#   make demo-debian13   `make demo` there
#   make test-debian14   `make test` in Debian 14 "forky" (testing: FreeCAD 1.1, Qt6), not in CI (docs/decisions.md)
#   make test-clang      the C++ tests built with clang, warnings as errors, into build-clang/
#   make test-sanitize   the C++ tests under AddressSanitizer + UndefinedBehaviorSanitizer (clang, warnings as errors,
#                        the programs too), build-sanitize/
#   make fuzz            the fuzz harnesses of tests/fuzz for FUZZ_SECONDS each (default 60), build-sanitize/
#   make fuzz-products   PRODUCTS generated products (tests/gen) solved and checked, PRINTS of them printed too
#   make translations    the .ts files of Resources/translations updated from the code and .ui files, and compiled
#   make same-outputs BASE=<commit>   whether this build writes what BASE's does, byte for byte, on the bundled
#                        inputs and SEEDS generated products (tests/bench/same_outputs.py; BASE built in build-base/)
SHELL := /bin/bash
BUILD ?= build
JOBS ?= $(shell nproc)
MOD_DIR ?=
FUZZ_SECONDS ?= 60
PRODUCTS ?= 300
PRINTS ?= 0
FIRST ?= 0
BASE ?= HEAD
SEEDS ?= 200
CTEST_ARGS ?=
CMAKE_ARGS ?=
# The clang builds check the code, not its speed: -O1 compiles in half the time of -O3 and keeps the sanitizers fast.
CLANG_FLAGS = -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DFABGUIDE_WERROR=ON
SANITIZE_CONFIGURE = cmake -S . -B build-sanitize -DCMAKE_CXX_COMPILER=clang++ $(CLANG_FLAGS) -DFABGUIDE_SANITIZE=ON >/dev/null
CPP_CHECK = cmake --build $(1) -j$(JOBS) --target fabguide_tests $(2) && ctest --test-dir $(1) -L cpp --output-on-failure -j$(JOBS) $(3)
# Under the sanitizers three searches over a hundred pieces run twenty times slower (214 s of one core here) and
# go through no code the shorter ones miss; the optimised builds run them (docs/decisions.md).
SANITIZE_SKIP := MinWastageTest.TheSameSeedGivesTheSameSuggestionsOnOneThreadOrTwo
SANITIZE_SKIP := $(SANITIZE_SKIP)|Skyline.SearchingTheTopOfTheLowestStripAgain
SANITIZE_SKIP := $(SANITIZE_SKIP)|LeastDesignTest.ShortestSidesAreNoLongerThanAnyDesign

.PHONY: all deps test check demo install bench format clean test-debian13 demo-debian13 test-clang test-sanitize fuzz \
	clang-deps fuzz-products deb test-deb test-deb-debian13 test-debian14 translations same-outputs

all: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) >/dev/null
	cmake --build $(BUILD) -j$(JOBS)

deps:
	@tools/install-deps

test: all
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS) $(CTEST_ARGS)

check: all
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS) -L "cpp|style|fast"

install: all
	cmake --install $(BUILD) $(if $(MOD_DIR),--prefix $(MOD_DIR)) >/dev/null
	@echo "FabGuide installed into $$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' $(BUILD)/CMakeCache.txt)$(if $(MOD_DIR), (here: $(MOD_DIR)))"

demo: install
		freecadcmd -c "import runpy; runpy.run_path('tools/demo.py', run_name='__main__')"
	QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a -s "-screen 0 1280x1024x24" freecad tools/demo_view.py 2>&1 | \
	  { grep -E "^(wrote|demo: )" || true; }; test $${PIPESTATUS[0]} -eq 0

test-debian13:
	tools/in-debian13 make test CTEST_ARGS="$(CTEST_ARGS)" CMAKE_ARGS="$(CMAKE_ARGS)"

deb: all
	tools/make-deb $(BUILD)

test-deb: deb
	tools/test-deb $(BUILD)

test-deb-debian13:
	tools/in-debian13 make test-deb

test-debian14:
	FABGUIDE_SUITE=forky tools/in-debian13 make test

demo-debian13:
	tools/in-debian13 make demo

clang-deps:
	@tools/install-deps clang

test-clang: clang-deps
	cmake -S . -B build-clang -DCMAKE_CXX_COMPILER=clang++ $(CLANG_FLAGS) >/dev/null
	$(call CPP_CHECK,build-clang,fabguide fabguide-print)

test-sanitize: clang-deps
	$(SANITIZE_CONFIGURE)
	$(call CPP_CHECK,build-sanitize,fabguide fabguide-print fuzz_pack fuzz_workslike fuzz_flatpack fuzz_printable,-E "$(SANITIZE_SKIP)")

fuzz: clang-deps
	$(SANITIZE_CONFIGURE)
	cmake --build build-sanitize -j$(JOBS) --target fuzz_pack fuzz_workslike fuzz_flatpack fuzz_printable
	tests/fuzz/run $(FUZZ_SECONDS) build-sanitize

fuzz-products: all
	/usr/bin/python3 tests/gen/fuzz_products.py --products $(PRODUCTS) --prints $(PRINTS) --first $(FIRST) \
	  --cli $(BUILD)/fabguide --keep $(BUILD)/fuzz-products

same-outputs: all
	tools/build-at $(BASE) build-base
	/usr/bin/python3 tests/bench/same_outputs.py build-base/build $(BUILD) --seeds $(SEEDS) --prints

bench: all
	python3 tests/bench/benchmarks.py

format:
	clang-format -i $$(find App python/bindings tests -name '*.cpp' -o -name '*.h')

clean:
	rm -rf $(BUILD) build-clang build-sanitize build-base

translations:
	pylupdate5 -noobsolete $$(git ls-files 'freecad/*.py') Resources/ui/*.ui \
	  -ts Resources/translations/FabGuide.ts $(wildcard Resources/translations/FabGuide_*.ts)
	for ts in Resources/translations/FabGuide_*.ts; do lrelease -silent $$ts; done
