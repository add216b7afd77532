# bounce: the two commands are `make demo` and `make test`.
#   make        configure + build (CLI at build/bin/bounce, Python at build/python)
#   make test   install missing Debian packages, build, run every C++ and Python test, then
#               the C++ tests and short fuzz runs again under ASan+UBSan (make test-sanitize)
#   make demo   install missing Debian packages, build, run the main job into out/
#   make bench  build and run the benchmarks (not part of `make test`)
#   make check-long  opt-in long sweeps (results recorded in docs/)
#   make lint        functions over 60 lines, files over 400 (clang-tidy), layering; both checks
#                    also run in `make test` (tests lint_sizes, layers_include_downward)
#   make test-sanitize  the C++ tests and 15 s of each fuzz target, built with clang,
#                    AddressSanitizer and UndefinedBehaviorSanitizer in build-asan
#   make fuzz        each fuzz target for FUZZ_SECONDS (default 600) in build-asan
#                    (docs/hardening.md)
#   make lammps      LAMMPS 20220106 from Debian's source package (GRANULAR + PLUGIN + MPI),
#                    cached in ~/.cache/bounce, and build/lammps/bounceplugin.so against it;
#                    build/lammps/lmp runs it, and `make test` then runs the LAMMPS tests
#                    (docs/lammps.md)
#   make package     Debian packages (CPack DEB) into dist/: libbounce0, libbounce-dev, bounce (man
#                    page, bash completion), python3-bounce, bounce-lammps-plugin (docs/install.md)
#   make check-package  opt-in: make package, then the packages unpacked into an empty folder and
#                    checked (--version, a collision, import bounce, the consumer, plugin load)
#   make check-pip   opt-in: pip install --no-build-isolation . into a fresh venv, import, pip wheel
#   make check-debian13  opt-in, root: make test, make demo and make check-pip in a fresh Debian 13
#                    (trixie) root made by debootstrap (docs/install.md records the times)
#   make explorer    the browser explorer: bounce's library compiled to WebAssembly by Debian's
#                    emscripten, with the page, into out/explorer/ (docs/explorer.md; opens from
#                    file:// or any static host); `make test` runs its browser test when chromium
#                    is installed (.ci/run installs it)
#   make explore     make explorer, then serve out/explorer on http://127.0.0.1:$(PORT)/
#   make lammps-demo opt-in, on 2 MPI ranks: the homogeneous cooling state of two granular gases
#                    (~7 min; out/figures/hcs-cooling, out/hcs/results.json) and the aggregation of
#                    sticky ice grains with K13's law against elastic JKR (~2 min;
#                    out/figures/aggregation, out/aggregation/results.json)
#   make aggregate-collisions  opt-in, on 2 MPI ranks: two BPCA aggregates of 1000 ice monomers
#                    collide head-on at 11 speeds, set against DT97's and W07's energies (~15 min;
#                    out/figures/aggregate_collisions.png, out/aggregate_collisions/results.json)

BUILD_DIR ?= build
JOBS      ?= $(shell nproc 2>/dev/null || echo 2)
WERROR    ?= ON
PYTHON    := /usr/bin/python3
CMAKE_FLAGS ?=
ASAN_DIR  ?= build-asan
FUZZ_SECONDS ?= 600
FUZZ_TARGETS ?= materials table rules ranges cli fit_data
# The browser explorer's build tree (emscripten), its page, the browser its test drives, and the
# port `make explore` serves on.
EXPLORER_DIR ?= build-explorer
EXPLORER_OUT ?= out/explorer
CHROMIUM  ?= /usr/bin/chromium
PORT      ?= 8000
# The sanitizer build's own packages (clang with its sanitizer and libFuzzer runtimes; LLVM's
# OpenMP, which SUNDIALS 7's CMake package looks for and clang finds only with it), and
# clang-tidy for the size check (`make lint`, test lint_sizes).
SANITIZE_DEPS := clang libclang-rt-dev libomp-dev ccache clang-tidy
# Every report ends the process with an error, leaks included (docs/hardening.md).
SANITIZE_ENV := ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1:strict_init_order=1 \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

.PHONY: all build deps deps-sanitize configure test demo bench check-long check-posterior lint clean \
        build-sanitize test-sanitize fuzz lammps lammps-demo package check-package check-pip check-debian13 aggregate-collisions \
        deps-explorer deps-browser explorer explore

all: build

deps:
	@./scripts/install-deps.sh

deps-sanitize:
	@./scripts/install-deps.sh $(SANITIZE_DEPS)

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release \
	  -DBOUNCE_WERROR=$(WERROR) -DPython3_EXECUTABLE=$(PYTHON) $(CMAKE_FLAGS)

configure: $(BUILD_DIR)/CMakeCache.txt

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: deps-sanitize
	@$(MAKE) --no-print-directory build
	@if [ -x $(CHROMIUM) ]; then $(MAKE) --no-print-directory explorer; fi
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS) -LE long
	@$(MAKE) --no-print-directory test-sanitize

# The sanitizer build: clang (libFuzzer), no Python extension, no benchmarks.
$(ASAN_DIR)/CMakeCache.txt:
	cmake -S . -B $(ASAN_DIR) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_COMPILER=/usr/bin/clang++ -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
	  -DBOUNCE_SANITIZE=ON -DBOUNCE_FUZZ=ON -DBOUNCE_BUILD_PYTHON=OFF -DBOUNCE_BUILD_BENCH=OFF \
	  -DBOUNCE_WERROR=$(WERROR) -DPython3_EXECUTABLE=$(PYTHON)

build-sanitize: $(ASAN_DIR)/CMakeCache.txt
	cmake --build $(ASAN_DIR) -j $(JOBS)

# Not here: pytest (no extension in this build), the find_package consumer (built by the
# system compiler, without the sanitizers' runtime) and the size check (the same sources).
test-sanitize: deps-sanitize
	@$(MAKE) --no-print-directory build-sanitize
	cd $(ASAN_DIR) && $(SANITIZE_ENV) ctest --output-on-failure -j $(JOBS) -LE 'long|python|packaging|lint|browser'

fuzz: deps-sanitize
	@$(MAKE) --no-print-directory build-sanitize
	$(SANITIZE_ENV) ./fuzz/run.sh --keep-going --seconds $(FUZZ_SECONDS) $(ASAN_DIR) $(FUZZ_TARGETS)

# The LAMMPS build (scripts/build-lammps.sh prints its src/ folder) and the plugin against it.
lammps: deps
	@./scripts/install-deps.sh xz-utils
	@$(MAKE) --no-print-directory configure
	@src=$$(./scripts/build-lammps.sh) && cmake -S . -B $(BUILD_DIR) -DLAMMPS_SOURCE_DIR="$$src" >/dev/null
	cmake --build $(BUILD_DIR) -j $(JOBS)
	@echo "bounce: $(BUILD_DIR)/lammps/lmp and $(BUILD_DIR)/lammps/bounceplugin.so (docs/lammps.md)"

# The packages are built in their own tree (/usr prefix, no tests), with the LAMMPS plugin
# against `make lammps`'s LAMMPS (scripts/build-lammps.sh prints its src/ folder).
package: deps
	@./scripts/install-deps.sh help2man dpkg-dev file xz-utils
	@src=$$(./scripts/build-lammps.sh) && JOBS=$(JOBS) WERROR=$(WERROR) ./scripts/package.sh build-package dist "$$src"

check-package: package
	@src=$$(./scripts/build-lammps.sh) && ./scripts/check-package.sh --lmp "$$src/../../build/lmp" dist

check-pip: deps
	@./scripts/install-deps.sh python3-venv python3-pip python3-setuptools python3-wheel
	CMAKE_BUILD_PARALLEL_LEVEL=$(JOBS) ./scripts/check-pip.sh

check-debian13:
	./scripts/check-debian13.sh

# Debian's emscripten, and npm where node has none (Debian's nodejs does not bring it; NodeSource's does).
deps-explorer:
	@./scripts/install-deps.sh emscripten
	@command -v npm >/dev/null 2>&1 || ./scripts/install-deps.sh npm

# The browser the explorer's test drives (about 100 MB): `.ci/run` installs it, `make test` uses
# it when present.
deps-browser:
	@./scripts/install-deps.sh chromium

# The library's generated sources come from the native build tree (its master-curve generator);
# uPlot and the test's driver from npm, pinned by explorer/package-lock.json. Debian's emscripten
# finds its node modules (acorn) through NODE_PATH when node is not Debian's own.
explorer: deps deps-explorer
	@$(MAKE) --no-print-directory configure
	cmake --build $(BUILD_DIR) --target generated/master_curve_data.cpp
	cd explorer && npm ci --no-audit --no-fund --loglevel=error
	emcmake cmake -S explorer -B $(EXPLORER_DIR) -G Ninja -DBOUNCE_GENERATED=$(abspath $(BUILD_DIR))/generated \
	  -DBOUNCE_OUT=$(abspath $(EXPLORER_OUT)) >/dev/null
	NODE_PATH=/usr/share/nodejs cmake --build $(EXPLORER_DIR) -j $(JOBS)
	@echo "bounce: the explorer is in $(EXPLORER_OUT)/ (open index.html, or make explore; docs/explorer.md)"

explore: explorer
	$(PYTHON) tools/explore.py --dir $(EXPLORER_OUT) --port $(PORT)

lammps-demo: lammps
	$(PYTHON) tools/hcs.py --build $(BUILD_DIR) --out out
	$(PYTHON) tools/aggregation.py --build $(BUILD_DIR) --out out

aggregate-collisions: lammps
	$(PYTHON) tools/aggregate_collision.py --build $(BUILD_DIR) --out out

demo: deps
	@$(MAKE) --no-print-directory build
	./scripts/demo.sh $(BUILD_DIR)

bench: deps
	@$(MAKE) --no-print-directory build
	./scripts/bench.sh $(BUILD_DIR)

check-long: deps
	@$(MAKE) --no-print-directory build
	cd $(BUILD_DIR) && ctest --output-on-failure -L long

# bounce.posterior's calibration over 100 synthetic data sets (docs/fitting.md, Posteriors; ~15 min).
check-posterior: deps
	@$(MAKE) --no-print-directory build
	PYTHONPATH=$(BUILD_DIR)/python $(PYTHON) tools/posterior_calibration.py 100 1

lint: build
	@./scripts/install-deps.sh clang-tidy
	$(PYTHON) tools/check_layers.py
	./tools/check_sizes.sh $(BUILD_DIR)

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) $(EXPLORER_DIR) out build-package build-pip dist
