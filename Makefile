# FabGuide: the two commands a user needs, wrapping CMake (see README.md).
#   make          install missing Debian packages, build everything into build/
#   make test     ... then run every test (C++, headless FreeCAD, FreeCAD GUI under Xvfb)
#   make demo     ... then install the workbench into FreeCAD and run it on a bundled example
#   make install  ... then install the workbench (MOD_DIR=... to choose the folder)
#   make bench    ... then regenerate docs/benchmarks.md
BUILD ?= build
JOBS ?= $(shell nproc)
MOD_DIR ?=

.PHONY: all deps test demo install bench format clean

all: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	cmake --build $(BUILD) -j$(JOBS)

deps:
	@tools/install-deps

test: all
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS)

install: all
	cmake --install $(BUILD) $(if $(MOD_DIR),--prefix $(MOD_DIR)) >/dev/null
	@echo "FabGuide installed into $$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' $(BUILD)/CMakeCache.txt)$(if $(MOD_DIR), (here: $(MOD_DIR)))"

demo: install
		freecadcmd -c "import runpy; runpy.run_path('tools/demo.py', run_name='__main__')"
	QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a -s "-screen 0 1280x1024x24" freecad tools/demo_view.py 2>&1 | grep "^wrote"

bench: all
	python3 tests/bench/benchmarks.py

format:
	clang-format -i $$(find App python/bindings tests -name '*.cpp' -o -name '*.h')

clean:
	rm -rf $(BUILD)
